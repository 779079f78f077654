// Global label declarations: the "labels" and "structures" sections of the
// configuration and of a --labels file, and declare_labels(), which turns
// them into the CPU's LabelTable. Keys and forms: docs/labels.md.
#include <fstream>
#include <sstream>

#include "config/config.hpp"
#include "config/config_parts.hpp"
#include "config/json_path.hpp"
#include "config/settings.hpp"
#include "devicemodel/labels.hpp"

namespace slmp::config {
namespace {

std::string where(const JsonAt& at, const std::string& source) {
    return source + ": " + (at.pointer().empty() ? "/" : at.pointer());
}

std::vector<std::uint32_t> dims(const JsonAt& at) {
    at.expect_array();
    if (at.json().empty() || at.json().size() > 3)
        at.fail("an array has 1 to 3 dimensions", "write e.g. [20] or [2, 20]");
    std::vector<std::uint32_t> out;
    for (std::size_t i = 0; i < at.json().size(); ++i) {
        auto n = static_cast<std::uint32_t>(at[i].unsigned_int(65536));
        if (n == 0) at[i].fail("an array dimension needs at least 1 element", "write the number of elements, e.g. 20");
        out.push_back(n);
    }
    return out;
}

LabelEntry label(const JsonAt& at, const std::string& source) {
    check_keys(at, Section::Label);
    LabelEntry e;
    e.where = where(at, source);
    e.name = at["name"].string();
    e.type = at["type"].string();
    if (at.has("device")) e.device = at["device"].string();
    if (at.has("dims")) e.dims = dims(at["dims"]);
    if (at.has("external")) e.external = at["external"].boolean();
    return e;
}

StructureEntry structure(const JsonAt& at, const std::string& source) {
    check_keys(at, Section::Structure);
    StructureEntry s;
    s.where = where(at, source);
    s.name = at["name"].string();
    auto members = at["members"];
    members.expect_array();
    for (std::size_t i = 0; i < members.json().size(); ++i) {
        auto m = members[i];
        check_keys(m, Section::Member);
        LabelMemberEntry e;
        e.where = where(m, source);
        e.name = m["name"].string();
        e.type = m["type"].string();
        if (m.has("dims")) e.dims = dims(m["dims"]);
        s.members.push_back(std::move(e));
    }
    return s;
}

[[noreturn]] void fail(const std::string& where, const std::string& problem, const std::string& fix) {
    throw ConfigError(where + ": " + problem + "; " + fix);
}

// The type text with its array part, and "dims" if given: one array, not two.
devicemodel::ParsedType type_of(const devicemodel::LabelTable& table, const std::string& text,
                                const std::vector<std::uint32_t>& dims, const std::string& at) {
    std::string error;
    auto parsed = devicemodel::parse_label_type(
        text, [&](std::string_view name) { return table.structure(name); }, &error);
    if (!parsed && error.rfind("unknown data type", 0) != 0)
        fail(at, error, "write an array as (0..n), (0..n,0..m) or (0..n,0..m,0..k) and a string as String(n), n 1 to 255");
    if (!parsed)
        fail(at, error,
             "use a GX Works3 type (Bit, Word [Signed], Word [Unsigned]/Bit String [16-bit], Double Word [Signed], "
             "Double Word [Unsigned]/Bit String [32-bit], FLOAT [Single Precision], FLOAT [Double Precision], Time, "
             "String(32), String [Unicode](32), Timer, Counter, Retentive Timer, Long Timer, Long Counter, Long "
             "Retentive Timer), an IEC name (BOOL, INT, UINT, WORD, DINT, UDINT, DWORD, REAL, LREAL, TIME, "
             "STRING[32], WSTRING[32]) or a structure declared before it");
    if (!dims.empty()) {
        if (!parsed->dims.empty()) fail(at, "the type '" + text + "' is an array and \"dims\" is given too",
                                        "give the array once: in the type or in \"dims\"");
        parsed->dims = dims;
    }
    return *parsed;
}

// "D9000", "M100", "ZR0"; a timer-family label may name its device as T5 for TN5.
devicemodel::DeviceAddress device_of(const std::string& text, const devicemodel::LabelType& type, const std::string& at) {
    std::string error;
    auto address = devicemodel::parse_address(text, &error);
    if (!address && type.kind == devicemodel::LabelType::Kind::Timer) {
        auto digit = text.find_first_of("0123456789");
        if (digit != std::string::npos) address = devicemodel::parse_address(text.substr(0, digit) + "N" + text.substr(digit));
    }
    if (!address) fail(at, error, "write a device such as D1000, M100, ZR0 (T5 for a Timer label)");
    return *address;
}

}  // namespace

void parse_labels(const JsonAt& root, const std::filesystem::path& directory, LabelsConfig& labels) {
    if (root.has("structures")) {
        auto list = root["structures"];
        list.expect_array();
        for (std::size_t i = 0; i < list.json().size(); ++i)
            labels.structures.push_back(structure(list[i], list[i].source()));
    }
    if (!root.has("labels")) return;
    auto list = root["labels"];
    if (list.json().is_string()) {
        // "labels": "global_labels.csv" — a GX Works3 export, relative to this file.
        auto file = std::filesystem::path(list.string());
        if (file.is_relative()) file = directory / file;
        auto csv = load_labels_file(file);
        labels.structures.insert(labels.structures.end(), csv.structures.begin(), csv.structures.end());
        labels.labels.insert(labels.labels.end(), csv.labels.begin(), csv.labels.end());
        return;
    }
    list.expect_array();
    for (std::size_t i = 0; i < list.json().size(); ++i) labels.labels.push_back(label(list[i], list[i].source()));
}

LabelsConfig load_labels_file(const std::filesystem::path& file) {
    std::ifstream in(file, std::ios::binary);
    if (!in) throw ConfigError(file.string() + ": cannot open the labels file; check the path given to --labels");
    std::stringstream text;
    text << in.rdbuf();
    if (file.extension() == ".csv" || file.extension() == ".CSV") return parse_labels_csv(text.str(), file.string());
    auto json = parse_json(text.str(), file.string());
    JsonAt root(json, file.string());
    check_keys(root, Section::LabelsFile);
    LabelsConfig labels;
    parse_labels(root, file.parent_path(), labels);
    return labels;
}

void declare_labels(devicemodel::Cpu& cpu, const LabelsConfig& labels) {
    auto& table = cpu.labels();
    for (const auto& s : labels.structures) {
        devicemodel::StructType type{s.name, {}, 0};
        for (const auto& m : s.members) {
            auto parsed = type_of(table, m.type, m.dims, m.where + "/type");
            type.members.push_back({m.name, parsed.type, parsed.dims, 0});
        }
        if (auto problem = table.add_structure(std::move(type))) fail(s.where, problem->problem, problem->fix);
    }
    for (const auto& l : labels.labels) {
        auto parsed = type_of(table, l.type, l.dims, l.where + l.type_key);
        devicemodel::LabelDecl decl{l.name, parsed.type, parsed.dims, l.external, std::nullopt};
        if (!l.device.empty()) decl.device = device_of(l.device, parsed.type, l.where + l.device_key);
        if (auto problem = table.add_label(std::move(decl), cpu.memory()))
            fail(l.where + (l.device.empty() ? "" : l.device_key), problem->problem, problem->fix);
    }
    if (auto problem = table.allocate(cpu.memory())) fail("labels", problem->problem, problem->fix);
}

}  // namespace slmp::config
