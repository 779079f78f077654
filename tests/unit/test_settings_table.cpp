// The settings table (config/settings.cpp) against everything built from it:
// every row's JSON key is accepted by its loader and its flag by the command
// line; unknown keys are refused naming the key and the fix; the docs' option
// tables and config/schema.json are what the table generates.
// SLMP_UPDATE_DOCS=1 rewrites the docs tables and the schema from the table.
#include <catch2/catch.hpp>

#include <algorithm>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <map>
#include <set>
#include <sstream>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "config/config.hpp"
#include "config/plant_config.hpp"
#include "config/settings.hpp"
#include "devicemodel/drive_spec.hpp"
#include "scenarios/loader.hpp"
#include "server/options.hpp"

using namespace slmp;
using config::Section;
using config::Setting;
using config::SettingType;
using nlohmann::json;

namespace {

const std::filesystem::path kSource = SLMP_SOURCE_DIR;

bool updating() {
    const char* env = std::getenv("SLMP_UPDATE_DOCS");
    return env && std::string(env) == "1";
}

std::string read_text(const std::filesystem::path& file) {
    std::ifstream in(file);
    std::stringstream text;
    text << in.rdbuf();
    return text.str();
}

void write_text(const std::filesystem::path& file, const std::string& text) { std::ofstream(file) << text; }

// The objects of a CPU profile file, which the profile test below loads.
bool in_profile(Section section) {
    switch (section) {
        case Section::Profile:
        case Section::Frame1E:
        case Section::Pipeline:
        case Section::EndCodes:
        case Section::Limits:
        case Section::PointLimit:
        case Section::FormLimit:
        case Section::ProfileTiming:
        case Section::Difference:
        case Section::SizeRegister:
        case Section::FileDrive:
        case Section::DriveAlias: return true;
        default: return false;
    }
}

// A value the key takes: the scalars from the row, the rest by hand.
json sample(const Setting& row) {
    // Keys whose sample depends on the object they are in.
    static const std::map<std::pair<Section, std::string>, json> in_object = {
        {{Section::Label, "name"}, "Speed"}, {{Section::Label, "type"}, "Word [Signed]"},
        {{Section::Label, "device"}, "D100"}, {{Section::Structure, "name"}, "Axis"},
        {{Section::Structure, "members"}, json::array({{{"name", "pos"}, {"type", "Word [Signed]"}}})},
        {{Section::Member, "name"}, "pos"}, {{Section::Member, "type"}, "Word [Signed]"},
        {{Section::Timer, "device"}, "T0"}, {{Section::Timer, "points"}, 1}, {{Section::Timer, "preset"}, 1},
        {{Section::MultiCpu, "profile"}, "R08CPU"}, {{Section::CpuError, "code"}, "1900"},
        {{Section::Network, "send"}, json::array({"W0-W0F"})}, {{Section::Redundant, "tracking"}, json::array({"D0-D99", "M"})}, {{Section::Network, "device_sizes"}, {{"W", 8192}}}, {{Section::Drive, "passwords"}, {{"LINE.CSV", "secret1"}}},
        {{Section::Drive, "dir"}, "/tmp"}, {{Section::Template, "count"}, 2}, {{Section::NodeSearch, "port"}, 45237},
        {{Section::Template, "template"}, {{"name", "s{i}"}, {"tcp_port", 0}}}};
    if (auto it = in_object.find({row.section, std::string(row.key)}); it != in_object.end()) return it->second;
    static const std::map<std::string, json> samples = {
        {"profile", "R04CPU"}, {"bind", "127.0.0.1"}, {"name", "press-1"}, {"ports", json::array()},
        {"device_sizes", {{"D", 2000}}}, {"devices", {{"D0", 1}}}, {"modules", json::array()},
        {"networks", json::array()}, {"routes", json::array()}, {"node_search", {{"port", 45237}}}, {"cpus", json::array()}, {"scenarios", json::array()},
        {"http", json::object()}, {"cpu", json::object()}, {"labels", json::array()}, {"structures", json::array()},
        {"state_dir", "/tmp/slmp-settings-test"}, {"drives", json::object()}, {"timing", json::object()},
        {"stations", json::array({{{"name", "a"}}})}, {"password", "abcdef"},
        {"password_lockout", {{"attempts", 3}}}, {"latch", {{"D", {0, 9}}}}, {"timers", json::array()},
        {"counters", json::array()}, {"program", {{"file", "line1.csv"}}}, {"error", {{"code", "1900"}}},
        {"file", "line1.csv"}, {"comments", "comments.csv"}, {"timer_limit", json::object()}, {"seed", 7},
        {"wdt_ms", 200}, {"shard_host", "plant-{shard}.plant"}, {"upstream", "192.168.3.39:5000"},
        {"compare", false},   // true needs "upstream" beside it (checked in its own test)
        {"redundant", {{"pair", "press-b"}}}, {"multidrop", {{"via", "line"}, {"start_io", "0040"}, {"number", 3}}},
        {"pair", "press-b"}, {"via", "line"},
        {"start_io", "0030"}, {"model", "Q62DA"}, {"head_address", "1008"}, {"dims", json::array({2})},
        {"comment", "a note"}, {"members", json::array()}};
    if (auto it = samples.find(std::string(row.key)); it != samples.end()) return it->second;
    switch (row.type) {
        case SettingType::Integer: return static_cast<std::uint64_t>(row.max);
        case SettingType::Number: return row.max;
        case SettingType::Boolean: return true;
        case SettingType::Choice: return std::string(row.choices.substr(0, row.choices.find('|')));
        default: FAIL("no sample value for key " << row.key); return nullptr;
    }
}

// A configuration document that holds `value` under the row's key.
json document(Section section, const std::string& key, const json& value) {
    switch (section) {
        case Section::Plant:   // a plant's own key needs a plant
            if (key != "stations" && key != "threads") return {{key, value}, {"stations", json::array({{{"name", "a"}}})}};
            return {{key, value}};
        case Section::Station: return {{key, value}};
        case Section::Template: {   // a template entry of a plant: stations s1, s2, ... on any free port
            json entry = {{"template", {{"name", "s{i}"}, {"tcp_port", 0}}}, {"count", 1}};
            entry[key] = value;
            return {{"stations", json::array({entry})}};
        }
        case Section::Port: {
            json port = {{"transport", "tcp"}, {"port", 0}};
            if (key == "network" || key == "station") port["network"] = port["station"] = 1;   // given together
            port[key] = value;
            return {{"ports", json::array({port})}};
        }
        case Section::Http: return {{"http", {{key, value}}}};
        case Section::Cpu: return {{"cpu", {{key, value}}}};
        case Section::Program: {
            json program = {{"file", "line1.csv"}};
            program[key] = value;
            return {{"cpu", {{"program", program}}}};
        }
        case Section::TimerLimit: return {{"cpu", {{"program", {{"file", "line1.csv"}, {"timer_limit", {{key, value}}}}}}}};
        case Section::Timing: return {{"timing", {{key, value}}}};
        case Section::Module: {
            json module = {{"start_io", "0030"}, {"buffer_words", 16}};
            module[key] = value;
            return {{"modules", json::array({module})}};
        }
        case Section::Network: {
            json network = {{"number", 1}, {"station", 1}};
            network[key] = value;
            return {{"networks", json::array({network})}};
        }
        case Section::MultiCpu: {
            json cpu = {{"number", 2}, {"profile", "R08CPU"}};
            cpu[key] = value;
            return {{"cpus", json::array({cpu})}};
        }
        case Section::Drive: return {{"drives", {{"2", {{key, value}}}}}};
        case Section::Label: {
            json label = {{"name", "Speed"}, {"type", "Word [Signed]"}};
            label[key] = value;
            return {{"labels", json::array({label})}};
        }
        case Section::Structure: {
            json structure = {{"name", "Axis"}, {"members", json::array()}};
            structure[key] = value;
            return {{"structures", json::array({structure})}};
        }
        case Section::Member: {
            json member = {{"name", "pos"}, {"type", "Word [Signed]"}};
            member[key] = value;
            return {{"structures", json::array({{{"name", "Axis"}, {"members", json::array({member})}}})}};
        }
        case Section::Redundant: {   // a lone station takes the keys and ignores them (docs/plants.md)
            json pair = {{"pair", "press-b"}};
            pair[key] = value;
            return {{"redundant", pair}};
        }
        case Section::Multidrop: {
            json multidrop = {{"via", "line"}, {"start_io", "0040"}, {"number", 3}};
            multidrop[key] = value;
            return {{"multidrop", multidrop}};
        }
        case Section::Route: {   // leaves through network 1 (via_network: through the network it names)
            json route = {{"network", 3}, {"via_network", 1}, {"via_station", 2}};
            route[key] = value;
            json networks = json::array({{{"number", 1}, {"station", 1}}});
            if (key == "via_network" && value.is_number_unsigned() && value.get<std::uint64_t>() >= 1 &&
                value.get<std::uint64_t>() <= 239 && value.get<std::uint64_t>() != 1)
                networks.push_back({{"number", value}, {"station", 1}});
            if (key == "network" && value == 1) route["network"] = 3;
            return {{"networks", networks}, {"routes", json::array({route})}};
        }
        case Section::NodeSearch: {
            json search = {{"port", 45237}};
            search[key] = value;
            return {{"node_search", search}};
        }
        case Section::Lockout: return {{"cpu", {{"password_lockout", {{key, value}}}}}};
        case Section::Timer:
        case Section::Counter: {
            bool timer = section == Section::Timer;
            json entry = {{"device", timer ? "T0" : "C0"}, {"preset", 1}};
            entry[key] = value;
            return {{"cpu", {{timer ? "timers" : "counters", json::array({entry})}}}};
        }
        case Section::CpuError: {
            json error = {{"code", "1900"}};
            error[key] = value;
            return {{"cpu", {{"error", error}}}};
        }
        default: break;   // the command line; a profile file (its own test below); a --labels file
    }
    return json::object();
}

config::PlantConfig parse(const json& doc) { return config::parse_plant_config(doc.dump(), "settings.json", "/tmp", ""); }

struct Args {
    std::vector<std::string> words{"slmp-sim"};
    server::CommandLine run() {
        std::vector<char*> argv;
        for (auto& w : words) argv.push_back(w.data());
        return server::parse_command_line(static_cast<int>(argv.size()), argv.data());
    }
};

// The docs blocks between "<!-- settings: NAME -->" and "<!-- /settings -->".
struct Block {
    std::string name;
    std::size_t begin, end;   // the text between the two markers
};
std::vector<Block> blocks(const std::string& text) {
    std::vector<Block> list;
    const std::string open = "<!-- settings: ", close = "<!-- /settings -->";
    for (auto pos = text.find(open); pos != std::string::npos; pos = text.find(open, pos + 1)) {
        auto name_end = text.find(" -->", pos);
        auto begin = text.find('\n', name_end) + 1;
        auto end = text.find(close, begin);
        REQUIRE(end != std::string::npos);
        list.push_back({text.substr(pos + open.size(), name_end - pos - open.size()), begin, end});
    }
    return list;
}

}  // namespace

TEST_CASE("each key and each flag is one row", "[settings]") {
    std::map<std::pair<int, std::string>, int> keys;
    std::map<std::string, int> flags;
    for (const auto& row : config::all_settings()) {
        if (!row.key.empty()) CHECK(++keys[{static_cast<int>(row.section), std::string(row.key)}] == 1);
        if (!row.flag.empty()) CHECK(++flags[std::string(row.long_flag())] == 1);
        INFO(row.key << " " << row.flag);
        CHECK((row.key.empty() == (row.section == Section::CommandLine)));
        CHECK(!(row.help.empty() && row.doc.empty() && row.key != "transport"));
        // A plain range says "use a smaller number" above it; below it (or off its step) the row's words.
        bool below_checked = row.min > 0 || row.step > 1;
        if (row.has_range() && !row.own_check && (!row.plain_range || below_checked)) CHECK(!row.fix.empty());
        if (row.plain_range && below_checked) CHECK(!row.below_min.empty());
        if (row.type == SettingType::Choice) CHECK(!row.choices.empty());
        if (!row.noun.empty()) CHECK((row.type == SettingType::Choice && !row.fix.empty()));
    }
    // The faces' flags and keys live with the faces, not here.
    CHECK(config::setting_by_flag("hostlink-port") == nullptr);
    CHECK(config::setting_by_flag("serial") == nullptr);
    for (auto key : config::section_keys(Section::Station)) CHECK((key != "hostlink" && key != "jw51cm" && key != "kind"));
    // The HTTP API's clock speed check uses the same range.
    CHECK(config::setting(Section::Station, "clock_speed").min == config::kMinClockSpeed);
    CHECK(config::setting(Section::Station, "clock_speed").max == config::kMaxClockSpeed);
    CHECK(config::setting(Section::Station, "clock_speed").fix == config::kClockSpeedFix);
}

TEST_CASE("every row's JSON key is accepted by its loader", "[settings]") {
    for (const auto& row : config::all_settings()) {
        if (row.key.empty() || in_profile(row.section)) continue;
        auto doc = document(row.section, std::string(row.key), sample(row));
        INFO(doc.dump());
        CHECK_NOTHROW(parse(doc));
    }
}

TEST_CASE("a key's value outside its row's range is refused with the row's fix", "[settings]") {
    for (const auto& row : config::all_settings()) {
        if (row.key.empty() || !row.has_range() || row.own_check || in_profile(row.section)) continue;
        if (row.plain_range) {   // JsonAt::unsigned_int's message above the range, the row's below it
            if (row.max < config::kAnyUnsigned) {
                auto max = static_cast<std::uint64_t>(row.max);
                auto doc = document(row.section, std::string(row.key), max + 1);
                INFO(doc.dump());
                CHECK_THROWS_WITH(parse(doc), Catch::Contains("/" + std::string(row.key) + ": value " + std::to_string(max + 1) +
                                                              " is larger than " + std::to_string(max) +
                                                              "; use a smaller number"));
            }
            if (row.min > 0 || row.step > 1) {
                auto low = row.min > 0 ? static_cast<std::uint64_t>(row.min) - 1 : std::uint64_t{row.step} + 1;
                auto doc = document(row.section, std::string(row.key), low);
                INFO(doc.dump());
                CHECK_THROWS_WITH(parse(doc), Catch::Contains("/" + std::string(row.key) + ": " + std::string(row.below_min) +
                                                              "; " + std::string(row.fix)));
            }
            continue;
        }
        auto too_big = row.type == SettingType::Integer ? json(static_cast<std::uint64_t>(row.max) + 1) : json(row.max * 2 + 1);
        auto doc = document(row.section, std::string(row.key), too_big);
        INFO(doc.dump());
        CHECK_THROWS_WITH(parse(doc), Catch::Contains("/" + std::string(row.key) + ": ") &&
                                          Catch::Contains(std::string(row.fix)));
        if (row.min > 0) {
            auto too_small = row.type == SettingType::Integer ? json(static_cast<std::uint64_t>(row.min) - 1) : json(0);
            auto small_doc = document(row.section, std::string(row.key), too_small);
            INFO(small_doc.dump());
            CHECK_THROWS_WITH(parse(small_doc), Catch::Contains(std::string(row.fix)));
        }
    }
}

TEST_CASE("an unknown key is refused naming the key and the keys it may be", "[settings]") {
    for (auto section : {Section::Station, Section::Port, Section::Http, Section::Cpu, Section::Program,
                         Section::TimerLimit, Section::Timing, Section::Module, Section::Network, Section::MultiCpu,
                         Section::Redundant, Section::Multidrop, Section::Route, Section::NodeSearch,
                         Section::Drive, Section::Label, Section::Structure, Section::Member, Section::Lockout,
                         Section::Timer, Section::Counter, Section::CpuError}) {
        auto doc = document(section, "no_such_key", 1);
        std::string list;
        for (auto key : config::section_keys(section)) list += (list.empty() ? "" : ", ") + std::string(key);
        if (section == Section::Station) list += ", kind, hostlink, jw51cm";
        INFO(doc.dump());
        CHECK_THROWS_WITH(parse(doc), Catch::Contains("/no_such_key: unknown key; use one of: " + list));
    }
    // In a plant too: a station entry's typo names the station.
    CHECK_THROWS_WITH(parse(json{{"stations", {{{"name", "a"}, {"prfile", "R08CPU"}}}}}),
                      Catch::Contains("station 'a': /prfile: unknown key; use one of: profile, bind"));
}

// Each nested object's keys, in the order its unknown-key error has always
// listed them (tests and users read these messages).
TEST_CASE("a nested object's keys are its rows, in the order its error lists them", "[settings]") {
    using List = std::vector<std::string_view>;
    const std::vector<std::pair<Section, List>> objects = {
        {Section::Module, {"start_io", "model", "buffer_words", "head_address"}},
        {Section::Network, {"number", "station", "master", "send", "device_sizes"}},
        {Section::MultiCpu, {"number", "profile", "device_sizes", "devices"}},
        {Section::Redundant, {"pair", "system", "switchover_ms", "tracking"}},
        {Section::Multidrop, {"via", "start_io", "number"}},
        {Section::Route, {"network", "via_network", "via_station"}},
        {Section::NodeSearch, {"port", "max_delay_ms"}},
        {Section::Drive, {"dir", "capacity", "write_protect", "present", "passwords"}},
        {Section::Label, {"name", "type", "device", "dims", "external", "comment"}},
        {Section::Structure, {"name", "members", "comment"}},
        {Section::Member, {"name", "type", "dims", "comment"}},
        {Section::LabelsFile, {"labels", "structures"}},
        {Section::Lockout, {"attempts", "seconds"}},
        {Section::Timer, {"device", "points", "preset", "base_ms"}},
        {Section::Counter, {"device", "points", "preset"}},
        {Section::CpuError, {"code", "stop"}},
        {Section::Frame1E, {"pc_type"}},
        {Section::Pipeline, {"buffer", "over_limit"}},
        {Section::EndCodes, {"not_supported", "out_of_range", "not_accessible", "unknown_device", "bad_unit",
                             "online_change_refused", "system_protect"}},
        {Section::Limits, {"batch_words", "batch_bits_binary", "batch_bits_ascii", "loopback_bytes", "random_read_points",
                           "random_write_weight", "random_write_bits", "monitor_points", "block_count", "block_points",
                           "extended_over_limit_code"}},
        {Section::PointLimit, {"max", "end_code"}},
        {Section::FormLimit, {"q", "iqr", "end_code"}},
        {Section::ProfileTiming, {"ke_ms", "ke_ascii_ms", "kdt_ms", "kdt_ascii_ms", "scan_wait"}},
        {Section::Difference, {"what", "manual", "hardware", "follows"}},
        {Section::SizeRegister, {"device", "sd", "bits"}},
    };
    for (const auto& [section, keys] : objects) {
        INFO(config::section_name(section));
        CHECK(config::section_keys(section) == keys);
    }
    // Every object a row holds has rows, and every nested object is held by a row.
    std::set<Section> held;
    for (const auto& row : config::all_settings())
        if (row.holds != Section::None) {
            held.insert(row.holds);
            INFO(row.key);
            CHECK((row.type == SettingType::Object || row.type == SettingType::Array));
            CHECK((!config::section_keys(row.holds).empty()));
        }
    for (const auto& [section, _] : objects)
        if (section != Section::LabelsFile) CHECK(held.count(section) == 1);
    // Every section has its path (config/settings.cpp's kSections).
    for (int i = 0; i <= static_cast<int>(Section::SizeRegister); ++i)
        CHECK_NOTHROW(config::section_name(static_cast<Section>(i)));
}

TEST_CASE("a profile's nested objects refuse an unknown key naming their rows", "[settings]") {
    const std::vector<std::pair<std::string, std::string>> cases = {
        {R"("pipeline": {"buffer": 1, "zzz": 1})", "/pipeline/zzz: unknown key; use one of: buffer, over_limit"},
        {R"("frame_1e": {"pc_type": "0041", "zzz": 1})", "/frame_1e/zzz: unknown key; use one of: pc_type"},
        {R"("end_codes": {"zzz": "C059"})", "/end_codes/zzz: unknown key; use one of: not_supported, out_of_range"},
        {R"("limits": {"batch_words": {"max": 960, "end_code": "C051", "zzz": 1}})",
         "/limits/batch_words/zzz: unknown key; use one of: max, end_code"},
        {R"("limits": {"block_count": {"q": 1, "iqr": 1, "end_code": "C054", "zzz": 1}})",
         "/limits/block_count/zzz: unknown key; use one of: q, iqr, end_code"},
        {R"("limits": {"loopback_bytes": 70000})", "/limits/loopback_bytes: value 70000 is larger than 65535; use a smaller number"},
        {R"("timing": {"ke_ms": 1, "jitter": 0.1})", "/timing/jitter: unknown key; use one of: ke_ms, ke_ascii_ms, kdt_ms, kdt_ascii_ms, scan_wait"},
        {R"("timing": {"ke_ms": 70000})", "/timing/ke_ms: out of range; use 0 to 60000 ms"},
        {R"("manual_vs_hardware": {"x": {"what": "a", "manual": "b", "hardware": "c", "follows": "both"}})",
         "/manual_vs_hardware/x/follows: must be \"manual\" or \"hardware\"; say which of the two the profile does"},
        {R"("size_registers": [{"device": "D", "sd": 280, "bits": 32, "zzz": 1}])",
         "/size_registers/0/zzz: unknown key; use one of: device, sd, bits"},
        {R"("xy_radix": 17)", "/xy_radix: value 17 is larger than 16; use a smaller number"},
    };
    for (const auto& [member, message] : cases) {
        auto text = R"({"extends": "R08CPU", "name": "X", "description": "x", )" + member + "}";
        INFO(text);
        CHECK_THROWS_WITH(config::parse_profile(text, "p.json"), Catch::Contains("p.json: " + message));
    }
}

TEST_CASE("a profile takes the profile rows' keys, and only those", "[settings]") {
    // Every key the built-in profiles use is a row (they load, so the loader took them).
    std::set<std::string> used;
    for (const auto& file : std::filesystem::directory_iterator(kSource / "config/profiles")) {
        auto profile = json::parse(read_text(file.path()));
        for (const auto& [key, _] : profile.items()) used.insert(key);
    }
    auto keys = config::section_keys(Section::Profile);
    for (const auto& key : used) {
        INFO(key);
        CHECK(std::find(keys.begin(), keys.end(), key) != keys.end());
    }
    std::string list;
    for (auto key : keys) list += (list.empty() ? "" : ", ") + std::string(key);
    CHECK_THROWS_WITH(config::parse_profile(R"({"extends": "R08CPU", "name": "X", "description": "x", "zzz": 1})", "p.json"),
                      Catch::Contains("p.json: /zzz: unknown key; use one of: " + list));
    CHECK_THROWS_WITH(config::parse_profile(R"({"extends": "R08CPU", "name": "X", "description": "x", "max_connections": 0})", "p.json"),
                      Catch::Contains("/max_connections: must be at least 1; write the CPU's connection count"));
    for (const auto& file : std::filesystem::directory_iterator(kSource / "config/profiles")) {
        INFO(file.path());
        CHECK_NOTHROW(config::load_profile(file.path().string()));
    }
}

TEST_CASE("every row's flag is accepted by the command line", "[settings]") {
    auto dir = std::filesystem::temp_directory_path() / "slmp-settings-flags";
    std::filesystem::create_directories(dir);
    write_text(dir / "c.json", "{}");
    write_text(dir / "labels.json", R"({"labels": []})");
    write_text(dir / "plant.json", R"({"stations": [{"name": "a", "tcp_port": 0}]})");
    const std::map<std::string, std::vector<std::string>> values = {
        {"config", {(dir / "c.json").string()}}, {"check-config", {(dir / "c.json").string()}},
        {"labels", {(dir / "labels.json").string()}}, {"drive", {"4=" + dir.string()}},
        {"network-no", {"1", "--station-no", "1"}}, {"station-no", {"1", "--network-no", "1"}},
        {"profile", {"R04CPU"}}, {"switch", {"STOP"}}, {"clock", {"frozen"}},
        {"shard", {"0/1", "--config", (dir / "plant.json").string()}}, {"upstream", {"192.168.3.39:5000"}},
        {"compare", {"--upstream", "192.168.3.39:5000"}}};
    for (const auto& row : config::all_settings()) {
        if (row.flag.empty()) continue;
        const std::string flag(row.long_flag());
        Args args;
        args.words.push_back("--" + flag);
        if (auto it = values.find(flag); it != values.end()) {
            args.words.insert(args.words.end(), it->second.begin(), it->second.end());
        } else if (row.flag_arg != config::FlagArg::None) {
            if (row.type == SettingType::Choice) args.words.emplace_back(row.choices.substr(0, row.choices.find('|')));
            else if (row.has_range()) args.words.push_back(std::to_string(static_cast<std::uint64_t>(row.max / row.flag_scale)));
            else args.words.push_back((dir / "file").string());
        }
        if (flag != "tcp-port" && flag != "udp-port" && flag != "shard") args.words.insert(args.words.end(), {"--tcp-port", "0"});
        INFO(flag);
        std::ostringstream swallow;   // --help, --version, --list-profiles print
        auto* old = std::cout.rdbuf(swallow.rdbuf());
        CHECK_NOTHROW(args.run());
        std::cout.rdbuf(old);
    }
}

TEST_CASE("a flag outside its row's range is refused naming the flag", "[settings]") {
    for (const auto& row : config::all_settings()) {
        if (row.flag.empty() || !row.has_range() || row.own_check) continue;
        const std::string flag(row.long_flag());
        Args args;
        args.words = {"slmp-sim", "--" + flag, std::to_string(static_cast<std::uint64_t>(row.max / row.flag_scale) + 1)};
        if (flag != "tcp-port" && flag != "udp-port" && flag != "shard") args.words.insert(args.words.end(), {"--tcp-port", "0"});
        INFO(flag);
        auto fix = row.flag_fix.empty() ? row.fix : row.flag_fix;
        CHECK_THROWS_WITH(args.run(), Catch::StartsWith("--" + flag + " ") && Catch::Contains(std::string(fix)));
    }
}

TEST_CASE("--help lists every flag of the table with its help", "[settings]") {
    Args args;
    args.words.push_back("--help");
    std::ostringstream out;
    auto* old = std::cout.rdbuf(out.rdbuf());
    args.run();
    std::cout.rdbuf(old);
    for (const auto& row : config::all_settings())
        if (!row.flag.empty()) CHECK(out.str().find("--" + std::string(row.long_flag())) != std::string::npos);
    CHECK(out.str().find("--hostlink-port") != std::string::npos);
}

TEST_CASE("the docs' option tables are the table's", "[settings]") {
    std::map<std::string, int> seen;
    for (auto doc : {"docs/configuration.md", "docs/program.md", "docs/labels.md"}) {
        auto file = kSource / doc;
        auto text = read_text(file);
        auto list = blocks(text);
        // From the end, so a rewrite keeps the earlier offsets.
        for (auto it = list.rbegin(); it != list.rend(); ++it) {
            ++seen[it->name];
            auto want = config::settings_markdown(it->name);
            INFO(doc << ": table '" << it->name << "' differs from config/settings.cpp; run the unit tests with "
                        "SLMP_UPDATE_DOCS=1 to rewrite it");
            if (updating()) text.replace(it->begin, it->end - it->begin, want);
            else CHECK(text.substr(it->begin, it->end - it->begin) == want);
        }
        if (updating()) write_text(file, text);
    }
    for (auto name : config::settings_markdown_tables()) {
        INFO("table " << name);
        CHECK(seen[std::string(name)] == 1);
    }
}

TEST_CASE("config/schema.json is the table's", "[settings]") {
    auto file = kSource / "config/schema.json";
    auto want = config::settings_json_schema().dump(2) + "\n";
    if (updating()) write_text(file, want);
    INFO("config/schema.json differs from config/settings.cpp; run the unit tests with SLMP_UPDATE_DOCS=1");
    CHECK(read_text(file) == want);
    // Every key the loaders take is in the schema, and nothing else is.
    auto schema = json::parse(want);
    for (auto key : config::section_keys(Section::Station)) CHECK(schema["properties"].contains(std::string(key)));
    for (auto key : config::section_keys(Section::Port))
        CHECK(schema["properties"]["ports"]["items"]["properties"].contains(std::string(key)));
    CHECK(schema["properties"].contains("threads"));
    CHECK(schema["additionalProperties"] == false);
    // The nested objects too: each is its rows' keys and nothing else.
    for (const auto& [pointer, section] : std::vector<std::pair<std::string, Section>>{
             {"/networks/items", Section::Network}, {"/modules/items", Section::Module},
             {"/cpus/items", Section::MultiCpu}, {"/drives/additionalProperties", Section::Drive},
             {"/labels/items", Section::Label}, {"/structures/items", Section::Structure},
             {"/structures/items/properties/members/items", Section::Member},
             {"/cpu/properties/timers/items", Section::Timer}, {"/cpu/properties/counters/items", Section::Counter},
             {"/cpu/properties/error", Section::CpuError}, {"/cpu/properties/password_lockout", Section::Lockout}}) {
        INFO(pointer);
        const auto& object = schema["properties"].at(json::json_pointer(pointer));
        CHECK(object.at("additionalProperties") == false);
        std::vector<std::string> keys, rows;
        for (const auto& item : object.at("properties").items()) keys.push_back(item.key());
        for (auto key : config::section_keys(section)) rows.emplace_back(key);
        std::sort(rows.begin(), rows.end());
        CHECK(keys == rows);
    }
    CHECK(schema["properties"].at(json::json_pointer("/cpu/properties/program/properties/wdt_ms/multipleOf")) == 10);
}

// The scenario loader names the keys it takes when it refuses one; the schema's
// objects (scenarios/schema.json) must list the same keys.
TEST_CASE("scenarios/schema.json lists the keys the scenario loader takes", "[settings][scenarios]") {
    auto schema = json::parse(read_text(kSource / "scenarios/schema.json"));
    const auto& defs = schema["definitions"];
    const std::vector<std::pair<std::string, json>> cases = {
        {R"({"zzz": 1})", schema},
        {R"({"initial": {"zzz": 1}})", defs["initial"]},
        {R"({"initial": {"error": {"code": "1900", "zzz": 1}}})", defs["cpu_error"]},
        {R"({"timeline": {"steps": [], "zzz": 1}})", defs["timeline"]},
        {R"({"replay": {"file": "r.jsonl", "zzz": 1}})", defs["replay"]},
        {R"({"triggers": [{"when": "M0", "do": [{"set": {"D0": 1}}], "zzz": 1}]})", defs["trigger"]},
    };
    for (const auto& [doc, object] : cases) {
        INFO(doc);
        std::string message;
        try {
            scenarios::parse_scenario(doc, "test.json");
        } catch (const config::ConfigError& e) {
            message = e.what();
        }
        const std::string marker = "unknown key; use one of: ";
        auto at = message.find(marker);
        REQUIRE(at != std::string::npos);
        std::set<std::string> loader;
        std::stringstream list(message.substr(at + marker.size()));
        for (std::string key; std::getline(list, key, ',');) loader.insert(key.substr(key.find_first_not_of(' ')));
        std::set<std::string> in_schema;
        for (const auto& [key, _] : object["properties"].items()) in_schema.insert(key);
        CHECK(loader == in_schema);
        CHECK(object["additionalProperties"] == false);
    }
}

// A profile's "file_drives" entries are rows too (FileDrive, and DriveAlias for
// another drive's second name): their unknown-key lists, kinds and ranges.
TEST_CASE("a profile's file drives take their rows' keys", "[settings]") {
    const std::vector<std::pair<std::string, std::string>> cases = {
        {R"({"2": {"kind": "sd_card", "capacity": 1, "size": 1}})",
         "/file_drives/2/size: unknown key; use one of: kind, capacity, present, write_protect"},
        {R"({"1": {"alias_of": 2, "capacity": 1}, "2": {"kind": "sd_card", "capacity": 1}})",
         "/file_drives/1/capacity: unknown key; use one of: alias_of, kind"},
        {R"({"2": {"kind": "floppy", "capacity": 1}})",
         "/file_drives/2/kind: unknown drive kind 'floppy'; use program_memory, sram_card, sd_card, standard_ram, "
         "standard_rom, device_label_memory or data_memory"},
        {R"({"2": {"kind": "sd_card", "capacity": 1099511627777}})",
         "/file_drives/2/capacity: value 1099511627777 is larger than 1099511627776; use a smaller number"},
        {R"({"1": {"alias_of": 256}})", "/file_drives/1/alias_of: value 256 is larger than 255; use a smaller number"},
    };
    for (const auto& [drives, message] : cases) {
        auto text = R"({"extends": "R08CPU", "name": "X", "description": "x", "file_drives": )" + drives + "}";
        INFO(text);
        CHECK_THROWS_WITH(config::parse_profile(text, "p.json"), Catch::Contains("p.json: " + message));
    }
    // The kinds are the device model's names, in its order.
    std::string kinds;
    for (auto k : {devicemodel::DriveKind::ProgramMemory, devicemodel::DriveKind::SramCard, devicemodel::DriveKind::SdCard,
                   devicemodel::DriveKind::StandardRam, devicemodel::DriveKind::StandardRom,
                   devicemodel::DriveKind::DeviceLabelMemory, devicemodel::DriveKind::DataMemory})
        kinds += (kinds.empty() ? "" : "|") + std::string(devicemodel::drive_kind_key(k));
    CHECK(config::setting(Section::FileDrive, "kind").choices == kinds);
    CHECK(config::setting(Section::DriveAlias, "kind").choices == kinds);
    CHECK(config::section_keys(Section::FileDrive) == std::vector<std::string_view>{"kind", "capacity", "present", "write_protect"});
    CHECK(config::section_keys(Section::DriveAlias) == std::vector<std::string_view>{"alias_of", "kind"});
}

// A plant's template entries ("template", "count", "first") are rows: their
// ranges and messages, and the schema's station entries list them.
TEST_CASE("a plant's template keys are rows", "[settings]") {
    CHECK(config::section_keys(Section::Template) == std::vector<std::string_view>{"template", "count", "first"});
    CHECK_THROWS_WITH(parse(json{{"stations", {{{"template", {{"name", "s{i}"}}}, {"count", 0}}}}}),
                      Catch::Contains("/stations/0/count: must be at least 1; give the number of stations the template makes"));
    CHECK_THROWS_WITH(parse(json{{"stations", {{{"template", {{"name", "s{i}"}}}, {"count", 10001}}}}}),
                      Catch::Contains("/stations/0/count: value 10001 is larger than 10000; use a smaller number"));
    auto plant = parse(json{{"stations", {{{"template", {{"name", "s{i}"}, {"tcp_port", "20000+i"}}}, {"count", 2}, {"first", 7}}}}});
    REQUIRE(plant.stations.size() == 2);
    CHECK(plant.stations[1].server.name == "s8");
    auto entry = config::settings_json_schema()["properties"]["stations"]["items"]["properties"];
    CHECK(entry["count"]["minimum"] == 1);
    CHECK(entry["count"]["maximum"] == 10000);
    CHECK(entry["first"]["maximum"] == 1000000);
    CHECK(entry["template"]["type"] == "object");
}
