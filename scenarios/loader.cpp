// The scenario file's top level and the helpers its parts share. Layout and
// meaning of every key: docs/scenarios.md; machine-readable: schema.json.
#include "scenarios/loader.hpp"

#include <cctype>
#include <cmath>
#include <fstream>
#include <map>
#include <sstream>

#include "config/station_pattern.hpp"
#include "config/config_parts.hpp"
#include "scenarios/load_parts.hpp"

namespace slmp::scenarios {

namespace load {

double number(const JsonAt& at, double min, double max, std::string_view fix) {
    if (!at.json().is_number()) at.fail("expected a number, found " + std::string(at.json().type_name()), fix);
    auto v = at.json().get<double>();
    if (!(v >= min && v <= max)) at.fail("value " + at.json().dump() + " is out of range", fix);
    return v;
}

double millis(const JsonAt& at) { return number(at, 0, 86400000, "write milliseconds from 0 to 86400000 (one day)"); }

double probability(const JsonAt& at) { return number(at, 0, 1, "write a probability from 0 to 1, e.g. 0.25"); }

devicemodel::DeviceAddress address(const JsonAt& at) {
    std::string error;
    auto a = devicemodel::parse_address(at.string(), &error);
    if (!a) at.fail(error, "write a device such as D100, M0, X1F, ZR1000, TN0");
    return *a;
}

ValueFormat value_format(const JsonAt& owner, const devicemodel::DeviceAddress& device) {
    if (!owner.has("as")) return ValueFormat::Int16;
    auto as = owner["as"];
    auto text = as.string();
    if (device.spec->unit != devicemodel::Unit::Word) as.fail("\"as\" applies to word devices only", "remove it for bit devices");
    if (text == "int16") return ValueFormat::Int16;
    if (text == "int32") return ValueFormat::Int32;
    if (text == "float") return ValueFormat::Float32;
    as.fail("unknown value format '" + text + "'", "use \"int16\", \"int32\" or \"float\"");
}

bool may_be_label(std::string_view text) {
    return !text.empty() && (std::isalpha(static_cast<unsigned char>(text[0])) || text[0] == '_');
}

DeviceRef device(const JsonAt& at, const JsonAt& owner) {
    auto text = at.string();
    std::string error;
    if (auto a = devicemodel::parse_address(text, &error)) return {*a, value_format(owner, *a)};
    if (!may_be_label(text)) at.fail(error, "write a device such as D100, M0, X1F, ZR1000, TN0, or a label name");
    // Not a device: a label, checked against the CPU's labels by bind_labels().
    if (owner.has("as")) owner["as"].fail("\"as\" applies to devices; '" + text + "' is a label, whose type gives the format",
                                          "remove \"as\"");
    return {{}, ValueFormat::Int16, text};
}

SetValues set_values(const JsonAt& at) {
    at.expect_object();
    SetValues set;
    for (const auto& [key, value] : at.json().items()) {
        if (devicemodel::parse_address(key)) {
            set.devices.push_back(config::parse_initial_value(key, at[key]));
            continue;
        }
        auto item = at[key];
        if (!may_be_label(key)) config::parse_initial_value(key, item);   // fails with the device parser's message
        if (!value.is_number() && !value.is_boolean())
            item.fail("'" + key + "' is a label (no device is named so); a label takes one number",
                      "write e.g. {\"" + key + "\": 50}, or name a device such as D100");
        set.labels.push_back({{{}, ValueFormat::Int16, key}, value.is_boolean() ? double(value.get<bool>()) : value.get<double>()});
    }
    return set;
}

std::vector<DeviceRange> ranges(const JsonAt& at) {
    std::vector<DeviceRange> list;
    auto one = [&](const JsonAt& item) {
        auto text = item.string();
        auto dash = text.find('-');
        auto parse = [&](const std::string& part) {
            std::string error;
            auto a = devicemodel::parse_address(part, &error);
            if (!a) item.fail(error, "write a device range such as \"D100-D199\", \"X0-X1F\" or one device \"M0\"");
            return *a;
        };
        auto first = parse(text.substr(0, dash));
        auto last = dash == std::string::npos ? first : parse(text.substr(dash + 1));
        if (first.spec->area != last.spec->area)
            item.fail("the range mixes " + std::string(first.spec->symbol) + " and " + std::string(last.spec->symbol),
                      "name one device kind, e.g. \"D100-D199\"");
        if (last.number < first.number) item.fail("the range ends before it starts", "write the lower device first");
        list.push_back({first.spec->area, first.number, last.number});
    };
    if (at.json().is_array()) {
        if (at.json().empty()) at.fail("an empty list", "name at least one range or leave the key out");
        for (std::size_t i = 0; i < at.json().size(); ++i) one(at[i]);
    } else {
        one(at);
    }
    return list;
}

OndemandAction ondemand(const JsonAt& at) {
    at.only_keys({"data", "to"});
    std::string to = "all";
    if (at.has("to")) {
        const auto t = at["to"];
        if (t.json().is_number_unsigned()) to = std::to_string(t.json().get<std::uint64_t>());
        else to = t.string();
    }
    std::string error;
    auto action = parse_ondemand(at["data"].string(), to, &error);
    if (!action) at["data"].fail(error, "write a device range such as \"D100-D109\" (at most 960 words)");
    if (to != "all" && to != "tcp" && to != "udp" && to.find_first_not_of("0123456789") != std::string::npos)
        at["to"].fail("unknown target '" + to + "'", "use \"all\", \"tcp\", \"udp\" or a TCP connection id");
    return *action;
}

std::vector<std::uint16_t> codes(const JsonAt& at) {
    std::vector<std::uint16_t> list;
    if (!at.json().is_array()) return {at.hex_code()};
    if (at.json().empty()) at.fail("an empty list", "name at least one code or leave the key out");
    for (std::size_t i = 0; i < at.json().size(); ++i) list.push_back(at[i].hex_code());
    return list;
}

devicemodel::RunSwitch run_switch(const JsonAt& at) {
    auto text = at.string();
    if (text == "RUN" || text == "run") return devicemodel::RunSwitch::Run;
    if (text == "STOP" || text == "stop") return devicemodel::RunSwitch::Stop;
    at.fail("unknown switch position '" + text + "'", "use \"RUN\" or \"STOP\"");
}

devicemodel::CpuError cpu_error(const JsonAt& at) {
    at.only_keys({"code", "stop"});
    devicemodel::CpuError e{at["code"].hex_code(), false};
    if (at.has("stop")) e.stop = at["stop"].boolean();
    if (e.code == 0) at["code"].fail("error code 0000 means no error", "use the code to publish in SD0, e.g. \"3100\"");
    return e;
}

Access access(const JsonAt& at) {
    auto text = at.string();
    if (text == "read") return Access::Read;
    if (text == "write") return Access::Write;
    if (text == "any") return Access::Any;
    at.fail("unknown access '" + text + "'", "use \"read\", \"write\" or \"any\"");
}

}  // namespace load

std::optional<OndemandAction> parse_ondemand(std::string_view data, std::string to, std::string* error) {
    auto dash = data.find('-');
    auto first = devicemodel::parse_address(data.substr(0, dash), error);
    if (!first) return std::nullopt;
    auto last = dash == std::string_view::npos ? first : devicemodel::parse_address(data.substr(dash + 1), error);
    if (!last) return std::nullopt;
    if (first->spec->area != last->spec->area) {
        *error = "the range mixes " + std::string(first->spec->symbol) + " and " + std::string(last->spec->symbol);
        return std::nullopt;
    }
    if (last->number < first->number) {
        *error = "the range ends before it starts";
        return std::nullopt;
    }
    const std::uint32_t points = last->number - first->number + 1;
    const std::uint64_t words = first->spec->unit == devicemodel::Unit::Bit ? (points + 15) / 16 : points;
    if (words > 960) {
        *error = "more than 960 words (the Ondemand limit of 1920 bytes)";
        return std::nullopt;
    }
    return OndemandAction{*first, points, std::move(to)};
}

namespace {

using config::JsonAt;

InitialState initial_state(const JsonAt& at) {
    at.only_keys({"devices", "switch", "password", "error"});
    InitialState s;
    if (at.has("devices")) s.devices = config::parse_initial_values(at["devices"]);
    if (at.has("switch")) s.run_switch = load::run_switch(at["switch"]);
    if (at.has("password")) {
        s.password = at["password"].string();
        if (s.password->empty()) at["password"].fail("an empty password", "leave the key out for a PLC without one");
    }
    if (at.has("error")) s.error = load::cpu_error(at["error"]);
    return s;
}

LogicProgram logic(const JsonAt& at, const std::string& source) {
    at.expect_array();
    LogicProgram program;
    for (std::size_t i = 0; i < at.json().size(); ++i) parse_rung(program, at[i].string(), source, at[i].pointer());
    return program;
}

ReplaySpec replay(const JsonAt& at, const std::string& source) {
    at.only_keys({"file", "on_miss", "end_code"});
    ReplaySpec r;
    std::filesystem::path file = at["file"].string();
    // Relative to the scenario file, so a scenario and its recording travel together.
    if (file.is_relative()) file = std::filesystem::path(source).parent_path() / file;
    r.file = file.string();
    if (at.has("on_miss")) {
        auto text = at["on_miss"].string();
        if (text == "simulate") r.on_miss = ReplaySpec::Miss::Simulate;
        else if (text == "end_code") r.on_miss = ReplaySpec::Miss::EndCode;
        else if (text == "no_response") r.on_miss = ReplaySpec::Miss::NoResponse;
        else at["on_miss"].fail("unknown choice '" + text + "'", "use \"simulate\", \"end_code\" or \"no_response\"");
    }
    if (at.has("end_code")) {
        if (r.on_miss != ReplaySpec::Miss::EndCode) at["end_code"].fail("\"end_code\" needs \"on_miss\": \"end_code\"", "add it or remove \"end_code\"");
        r.miss_code = protocol::end_code(at["end_code"].hex_code());
    }
    return r;
}

}  // namespace

Scenario parse_scenario(const std::string& json_text, const std::string& source) {
    auto json = config::parse_json(json_text, source);
    JsonAt root(json, source);
    root.only_keys({"$schema", "name", "description", "stations", "seed", "initial", "timeline", "triggers", "logic",
                    "faults", "replay"});
    Scenario s;
    s.source = source;
    s.name = root.has("name") ? root["name"].string() : std::filesystem::path(source).stem().string();
    if (root.has("description")) s.description = root["description"].string();
    if (root.has("stations")) s.stations = config::parse_station_patterns(root["stations"]);
    if (root.has("seed")) s.seed = root["seed"].unsigned_int(0xFFFFFFFFFFFFFFFFull);
    if (root.has("initial")) s.initial = initial_state(root["initial"]);
    if (root.has("timeline")) s.timeline = load::timeline(root["timeline"]);
    if (root.has("triggers")) s.triggers = load::triggers(root["triggers"]);
    if (root.has("logic")) s.logic = logic(root["logic"], source);
    if (root.has("faults")) s.faults = load::faults(root["faults"]);
    if (root.has("replay")) s.replay = replay(root["replay"], source);

    // Within one file: ids are unique and every fault a trigger switches exists.
    check_together({s});
    return s;
}

Scenario load_scenario(const std::filesystem::path& file) {
    std::ifstream in(file);
    if (!in) throw config::ConfigError(file.string() + ": cannot open the scenario file; check the path given to --scenario");
    std::stringstream text;
    text << in.rdbuf();
    return parse_scenario(text.str(), file.string());
}

void check_together(const std::vector<Scenario>& scenarios) {
    std::map<std::string, std::string> faults, triggers;   // id -> "file: pointer"
    auto where = [](const Scenario& s, const std::string& pointer) { return s.source + ": " + pointer; };
    for (const auto& s : scenarios) {
        for (const auto& f : s.faults) {
            if (f.id.empty()) continue;
            auto [it, fresh] = faults.emplace(f.id, where(s, f.pointer));
            if (!fresh)
                throw config::ConfigError(where(s, f.pointer + "/id") + ": fault id '" + f.id + "' is also used at " +
                                          it->second + "; give each fault its own id");
        }
        for (const auto& t : s.triggers) {
            if (t.id.empty()) continue;
            auto [it, fresh] = triggers.emplace(t.id, where(s, t.pointer));
            if (!fresh)
                throw config::ConfigError(where(s, t.pointer + "/id") + ": trigger id '" + t.id + "' is also used at " +
                                          it->second + "; give each trigger its own id");
        }
    }
    for (const auto& s : scenarios)
        for (const auto& t : s.triggers)
            for (std::size_t i = 0; i < t.actions.size(); ++i)
                if (const auto* a = std::get_if<FaultSwitchAction>(&t.actions[i]); a && !faults.count(a->fault))
                    throw config::ConfigError(where(s, t.pointer + "/do/" + std::to_string(i)) + ": no fault has the id '" +
                                              a->fault + "'; use the \"id\" of one of the \"faults\"");
}

}  // namespace slmp::scenarios
