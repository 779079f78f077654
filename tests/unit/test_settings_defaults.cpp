// The settings table's defaults against what the loaders give: a row whose
// default is a value (`8192`, `"auto"`, `false`, `{"mode": "instant"}`) must be
// what a configuration that leaves the key out loads to — from the file, from
// the command line with no flags, and for a profile's keys from a profile that
// leaves them out. The docs show the row's default, users get the loader's;
// this test is where the two meet (issue 29: "defaults are only text").
#include <catch2/catch.hpp>

#include <filesystem>
#include <fstream>
#include <functional>
#include <map>
#include <optional>
#include <sstream>
#include <stdexcept>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "config/config.hpp"
#include "config/plant_config.hpp"
#include "config/settings.hpp"
#include "devicemodel/drive_spec.hpp"
#include "server/options.hpp"

using namespace slmp;
using config::Section;
using config::Setting;
using nlohmann::json;

namespace {

const std::filesystem::path kSource = SLMP_SOURCE_DIR;

// The row's default as a JSON value, when its text is one: `false`, 8192,
// "\"auto\"", `{"mode": "instant"}`. Prose ("the profile's", "none") is not.
std::optional<json> default_value(const Setting& row) {
    std::string text(row.default_text);
    if (text.size() >= 2 && text.front() == '`' && text.back() == '`') text = text.substr(1, text.size() - 2);
    if (text.empty()) return std::nullopt;
    auto value = json::parse(text, nullptr, false);
    if (value.is_discarded() || value.is_array()) return std::nullopt;
    return value;
}

// What a station loads to: its configuration and the plant it is in.
struct Loaded {
    const config::PlantConfig& plant;
    const config::ServerConfig& server;
};

// A document that holds the row's object (with the object's required keys) and
// nothing else: the row's own key is left out, so the loader's default applies.
json minimal_document(Section section) {
    switch (section) {
        case Section::Plant: return {{"stations", json::array({{{"name", "a"}}})}};
        case Section::Template: return {{"stations", json::array({{{"template", {{"name", "s{i}"}}}, {"count", 1}}})}};
        case Section::Station: return json::object();
        case Section::Port: return {{"ports", json::array({{{"transport", "tcp"}, {"port", 0}}})}};
        case Section::Http: return {{"http", json::object()}};
        case Section::Cpu: return {{"cpu", json::object()}};
        case Section::Lockout: return {{"cpu", {{"password_lockout", json::object()}}}};
        case Section::Timer: return {{"cpu", {{"timers", json::array({{{"device", "T0"}, {"preset", 1}}})}}}};
        case Section::CpuError: return {{"cpu", {{"error", {{"code", "1900"}}}}}};
        case Section::Program: return {{"cpu", {{"program", {{"file", "line1.csv"}}}}}};
        case Section::TimerLimit:
            return {{"cpu", {{"program", {{"file", "line1.csv"}, {"timer_limit", json::object()}}}}}};
        case Section::Timing: return {{"timing", json::object()}};
        case Section::Module: return {{"modules", json::array({{{"start_io", "0030"}, {"buffer_words", 16}}})}};
        case Section::Redundant: return {{"redundant", {{"pair", "press-b"}}}};
        case Section::NodeSearch: return {{"node_search", {{"port", 45237}}}};
        case Section::Label: return {{"labels", json::array({{{"name", "Speed"}, {"type", "Word [Signed]"}}})}};
        case Section::MultiCpu: return {{"cpus", json::array({{{"number", 2}, {"profile", "R08CPU"}}})}};
        default: FAIL("no minimal document for section " << config::section_name(section)); return nullptr;
    }
}

std::string run_switch(devicemodel::RunSwitch s) { return s == devicemodel::RunSwitch::Run ? "RUN" : "STOP"; }
std::string data_code(config::DataCode c) {
    return c == config::DataCode::Binary ? "binary" : c == config::DataCode::Ascii ? "ascii" : "auto";
}

using Read = std::function<json(const Loaded&)>;

// How to read each value-default row's key back from a loaded configuration.
// A row whose default is a value and which has no entry here fails the test:
// add the reader with the row.
const std::map<std::pair<Section, std::string>, Read>& readers() {
    static const std::map<std::pair<Section, std::string>, Read> map = {
        {{Section::Plant, "shards"}, [](const Loaded& l) -> json { return l.plant.layout.file_count; }},
        {{Section::Plant, "metrics_by"}, [](const Loaded& l) -> json { return l.plant.metrics_by; }},
        // The template's first station is i = first: "s{i}" names it.
        {{Section::Template, "first"}, [](const Loaded& l) -> json { return std::stol(l.server.name.substr(1)); }},
        {{Section::Station, "profile"}, [](const Loaded& l) -> json { return l.server.profile; }},
        {{Section::Station, "bind"}, [](const Loaded& l) -> json { return l.server.bind; }},
        {{Section::Station, "max_request_bytes"}, [](const Loaded& l) -> json { return l.server.max_request_bytes; }},
        {{Section::Station, "upstream_timeout_ms"}, [](const Loaded& l) -> json { return l.server.upstream_timeout_ms; }},
        {{Section::Station, "compare"}, [](const Loaded& l) -> json { return l.server.compare; }},
        {{Section::Station, "compare_slack_ms"}, [](const Loaded& l) -> json { return l.server.compare_slack_ms; }},
        {{Section::Station, "log_level"}, [](const Loaded& l) -> json { return l.server.log_level; }},
        {{Section::Station, "timing"},
         [](const Loaded& l) -> json { return {{"mode", std::string(config::to_string(l.server.timing.mode))}}; }},
        {{Section::Station, "clock_speed"}, [](const Loaded& l) -> json { return l.server.clock_speed; }},
        {{Section::Station, "snapshot_interval_s"},
         [](const Loaded& l) -> json { return l.server.persistence.snapshot_interval_s; }},
        {{Section::Station, "restore"},
         [](const Loaded& l) -> json { return l.server.persistence.restore_all ? "all" : "latched"; }},
        {{Section::Port, "data_code"}, [](const Loaded& l) -> json { return data_code(l.server.ports.at(0).data_code); }},
        {{Section::Port, "idle_timeout_ms"}, [](const Loaded& l) -> json { return l.server.ports.at(0).idle_timeout_ms; }},
        {{Section::Port, "partial_frame_timeout_ms"},
         [](const Loaded& l) -> json { return l.server.ports.at(0).partial_frame_timeout_ms; }},
        {{Section::Port, "max_connections_per_address"},
         [](const Loaded& l) -> json { return l.server.ports.at(0).max_connections_per_address; }},
        {{Section::Port, "remote_password"}, [](const Loaded& l) -> json { return l.server.ports.at(0).remote_password; }},
        {{Section::Redundant, "system"}, [](const Loaded& l) -> json { return std::string(1, l.server.redundant.value().system); }},
        {{Section::NodeSearch, "max_delay_ms"}, [](const Loaded& l) -> json { return l.server.node_search.max_delay_ms; }},
        {{Section::Module, "head_address"}, [](const Loaded& l) -> json { return l.server.modules.at(0).head_address; }},
        {{Section::Http, "enabled"}, [](const Loaded& l) -> json { return l.server.http.enabled; }},
        {{Section::Http, "port"}, [](const Loaded& l) -> json { return l.server.http.port; }},
        {{Section::Label, "external"}, [](const Loaded& l) -> json { return l.server.labels.labels.at(0).external; }},
        {{Section::Cpu, "switch"}, [](const Loaded& l) -> json { return run_switch(l.server.cpu.runtime.run_switch); }},
        {{Section::Cpu, "scan_time_ms"}, [](const Loaded& l) -> json { return l.server.cpu.runtime.scan_time.count(); }},
        {{Section::Cpu, "remote_reset"}, [](const Loaded& l) -> json { return l.server.cpu.runtime.remote_reset_enabled; }},
        {{Section::Cpu, "output_off_at_stop"},
         [](const Loaded& l) -> json { return l.server.cpu.runtime.output_off_at_stop; }},
        {{Section::Cpu, "system_protect"}, [](const Loaded& l) -> json { return l.server.cpu.runtime.system_protect; }},
        {{Section::Lockout, "attempts"}, [](const Loaded& l) -> json { return l.server.cpu.runtime.lockout_attempts; }},
        {{Section::Lockout, "seconds"}, [](const Loaded& l) -> json { return l.server.cpu.runtime.lockout_period.count(); }},
        {{Section::Timer, "points"}, [](const Loaded& l) -> json { return l.server.cpu.runtime.timers.at(0).count; }},
        {{Section::CpuError, "stop"}, [](const Loaded& l) -> json { return l.server.cpu.runtime.error.value().stop; }},
        {{Section::Program, "operation_error"},
         [](const Loaded& l) -> json {
             return l.server.cpu.program.options.operation_error == program::OnOperationError::Stop ? "stop" : "continue";
         }},
        {{Section::Program, "wdt_ms"}, [](const Loaded& l) -> json { return l.server.cpu.program.options.wdt_ms; }},
        {{Section::Program, "timer_limit"},
         [](const Loaded& l) -> json {
             const auto& o = l.server.cpu.program.options;
             return {{"low_ms", o.timer_low_ms}, {"high_ms", o.timer_high_ms}};
         }},
        {{Section::Program, "output_mode_at_run"},
         [](const Loaded& l) -> json {
             return l.server.cpu.program.options.output_mode_at_run == program::OutputModeAtRun::Previous ? "previous"
                                                                                                         : "recalculate";
         }},
        {{Section::Program, "max_steps_per_scan"},
         [](const Loaded& l) -> json { return l.server.cpu.program.options.max_steps_per_scan; }},
        {{Section::Program, "allow_double_timer_coils"},
         [](const Loaded& l) -> json { return l.server.cpu.program.options.allow_double_timer_coils; }},
        {{Section::TimerLimit, "low_ms"}, [](const Loaded& l) -> json { return l.server.cpu.program.options.timer_low_ms; }},
        {{Section::TimerLimit, "high_ms"},
         [](const Loaded& l) -> json { return l.server.cpu.program.options.timer_high_ms; }},
        {{Section::Timing, "mode"}, [](const Loaded& l) -> json { return std::string(config::to_string(l.server.timing.mode)); }},
        {{Section::Timing, "jitter"}, [](const Loaded& l) -> json { return l.server.timing.jitter; }},
        {{Section::Timing, "seed"}, [](const Loaded& l) -> json { return l.server.timing.seed; }},
    };
    return map;
}

// Value defaults the loaders leave unset on purpose, and where the value is applied instead.
const std::map<std::pair<Section, std::string>, std::string> kAppliedElsewhere = {
    // RedundantConfig::switchover_ms stays unset so either CPU of the pair may give it;
    // station/network_map.cpp takes 100 ms when neither does.
    {{Section::Redundant, "switchover_ms"}, "station/network_map.cpp"},
};

// Profile keys: how to read them back from a loaded profile, and where the key sits in the file.
struct ProfileRead {
    std::string object;   // the JSON pointer of the object the key is in: "" (top level), "/pipeline", "/file_drives/2"
    std::function<json(const config::Profile&)> read;
};
std::string hex4(std::uint16_t code) {
    char text[5];
    std::snprintf(text, sizeof text, "%04X", code);
    return text;
}
const devicemodel::DriveSpec& drive(const config::Profile& p, std::uint16_t number) {
    for (const auto& d : p.cpu.drives)
        if (d.number == number) return d;
    throw std::runtime_error("no drive " + std::to_string(number));
}
const std::map<std::pair<Section, std::string>, ProfileRead>& profile_readers() {
    static const std::map<std::pair<Section, std::string>, ProfileRead> map = {
        {{Section::Profile, "station_extended_frame"}, {"", [](const config::Profile& p) -> json { return p.port.station_extended_frame; }}},
        {{Section::Profile, "relays"}, {"", [](const config::Profile& p) -> json { return p.port.relays; }}},
        {{Section::Profile, "node_commands"}, {"", [](const config::Profile& p) -> json { return p.port.node_commands; }}},
        {{Section::Profile, "online_change"}, {"", [](const config::Profile& p) -> json { return p.port.online_change; }}},
        {{Section::Profile, "max_connections"}, {"", [](const config::Profile& p) -> json { return p.port.max_connections; }}},
        {{Section::Profile, "xy_radix"},
         {"", [](const config::Profile& p) -> json { return static_cast<int>(p.cpu.numbering.xy); }}},
        {{Section::Pipeline, "over_limit"},
         {"/pipeline", [](const config::Profile& p) -> json { return hex4(p.port.pipeline_over_limit.end_code); }}},
        {{Section::EndCodes, "online_change_refused"},
         {"/end_codes", [](const config::Profile& p) -> json { return hex4(p.port.online_change_code); }}},
        {{Section::EndCodes, "system_protect"},
         {"/end_codes", [](const config::Profile& p) -> json { return hex4(p.port.system_protect_code); }}},
        // R08CPU's drive 2 is an SD card, its drive 1 an alias of drive 3.
        {{Section::FileDrive, "present"}, {"/file_drives/2", [](const config::Profile& p) -> json { return drive(p, 2).present; }}},
        {{Section::FileDrive, "write_protect"},
         {"/file_drives/2", [](const config::Profile& p) -> json { return drive(p, 2).write_protect; }}},
        {{Section::DriveAlias, "kind"},
         {"/file_drives/1", [](const config::Profile& p) -> json { return std::string(devicemodel::drive_kind_key(drive(p, 1).kind)); }}},
    };
    return map;
}

bool in_profile(Section section) {
    return section == Section::Profile || section == Section::Pipeline || section == Section::EndCodes ||
           section == Section::Frame1E || section == Section::Limits || section == Section::PointLimit ||
           section == Section::FormLimit || section == Section::ProfileTiming || section == Section::Difference ||
           section == Section::SizeRegister || section == Section::FileDrive || section == Section::DriveAlias;
}

std::string read_text(const std::filesystem::path& file) {
    std::ifstream in(file);
    std::stringstream text;
    text << in.rdbuf();
    return text.str();
}

config::PlantConfig from_command_line(std::vector<std::string> words) {
    words.insert(words.begin(), "slmp-sim");
    std::vector<char*> argv;
    for (auto& w : words) argv.push_back(w.data());
    return server::parse_command_line(static_cast<int>(argv.size()), argv.data()).plant;
}

}  // namespace

TEST_CASE("a key left out loads to its row's default", "[settings]") {
    int checked = 0;
    for (const auto& row : config::all_settings()) {
        auto value = default_value(row);
        if (!value || row.key.empty() || in_profile(row.section)) continue;
        const std::pair<Section, std::string> id{row.section, std::string(row.key)};
        INFO(config::section_name(row.section) << " " << row.key << ": the table says " << row.default_text);
        if (kAppliedElsewhere.contains(id)) continue;
        auto reader = readers().find(id);
        if (reader == readers().end()) {
            FAIL_CHECK("no reader for this value default in tests/unit/test_settings_defaults.cpp");
            continue;
        }
        auto doc = minimal_document(row.section);
        INFO(doc.dump());
        auto plant = config::parse_plant_config(doc.dump(), "defaults.json", "/tmp", "");
        REQUIRE(!plant.stations.empty());
        CHECK(reader->second({plant, plant.stations.front().server}) == *value);
        ++checked;
    }
    CHECK(checked >= 40);
}

TEST_CASE("a station's defaults are the same from an empty file, the command line and the struct", "[settings]") {
    auto dir = std::filesystem::temp_directory_path() / "slmp-settings-defaults";
    std::filesystem::create_directories(dir);
    std::ofstream(dir / "empty.json") << "{}";
    auto from_file = config::parse_plant_config("{}", "defaults.json", "/tmp", "");
    auto from_flags = from_command_line({});
    auto from_empty_config = from_command_line({"--config", (dir / "empty.json").string()});
    config::PlantConfig built;
    built.stations.push_back({});
    for (const auto& row : config::all_settings()) {
        auto value = default_value(row);
        if (!value || (row.section != Section::Station && row.section != Section::Port)) continue;
        auto reader = readers().find({row.section, std::string(row.key)});
        if (reader == readers().end()) continue;   // the test above fails for it
        INFO(row.key << ": the table says " << row.default_text);
        for (const auto* plant : {&from_file, &from_flags, &from_empty_config, &built}) {
            REQUIRE(!plant->stations.empty());
            CHECK(reader->second({*plant, plant->stations.front().server}) == *value);
        }
    }
    // "ports": TCP 5000 and UDP 5000, as the table says in words.
    for (const auto* plant : {&from_file, &from_flags, &from_empty_config, &built}) {
        const auto& ports = plant->stations.front().server.ports;
        REQUIRE(ports.size() == 2);
        CHECK((ports[0].transport == config::Transport::Tcp && ports[0].port == 5000));
        CHECK((ports[1].transport == config::Transport::Udp && ports[1].port == 5000));
    }
}

TEST_CASE("a profile key left out loads to its row's default", "[settings]") {
    // R08CPU.json extends nothing, so leaving a key out of it leaves it to the loader.
    auto base = json::parse(read_text(kSource / "config/profiles/R08CPU.json"));
    int checked = 0;
    for (const auto& row : config::all_settings()) {
        auto value = default_value(row);
        if (!value || !in_profile(row.section)) continue;
        INFO(config::section_name(row.section) << " " << row.key << ": the table says " << row.default_text);
        auto reader = profile_readers().find({row.section, std::string(row.key)});
        if (reader == profile_readers().end()) {
            FAIL_CHECK("no reader for this value default in tests/unit/test_settings_defaults.cpp");
            continue;
        }
        auto doc = base;
        doc.at(json::json_pointer(reader->second.object)).erase(std::string(row.key));
        auto profile = config::parse_profile(doc.dump(), "defaults.json");
        CHECK(reader->second.read(profile) == *value);
        ++checked;
    }
    CHECK(checked >= 12);
}

// Defaults the table writes in words: what the loaders give matches them too.
TEST_CASE("the defaults written in words are what the loaders give", "[settings]") {
    auto load = [](const json& doc) { return config::parse_plant_config(doc.dump(), "defaults.json", "/tmp", "").stations.front().server; };
    auto text = [](Section section, const char* key) { return std::string(config::setting(section, key).default_text); };
    // networks[].device_sizes: "16384, 16384, 32768, 512, 131072, 512" (X, Y, B, SB, W, SW).
    auto net = load({{"networks", json::array({{{"number", 1}, {"station", 2}}})}}).networks.at(0);
    std::string sizes;
    for (auto area : {devicemodel::Area::X, devicemodel::Area::Y, devicemodel::Area::B, devicemodel::Area::SB,
                      devicemodel::Area::W, devicemodel::Area::SW})
        sizes += (sizes.empty() ? "" : ", ") + std::to_string(net.sizes[static_cast<std::size_t>(area)]);
    CHECK(sizes == text(Section::Network, "device_sizes"));
    // networks[].send: "256 LB and 256 LW from (station − 1) × 256".
    CHECK(text(Section::Network, "send") == "256 LB and 256 LW from (station − 1) × 256");
    REQUIRE(net.send.size() == 2);
    for (const auto& range : net.send) CHECK((range.first == 256 && range.count == 256));
    // http: "on, port 8080".
    CHECK(text(Section::Station, "http") == "on, port 8080");
    auto plain = load(json::object());
    CHECK((plain.http.enabled && plain.http.port == 8080));
    // cpu.password_lockout: "10, 60" (attempts, seconds).
    CHECK(text(Section::Cpu, "password_lockout") ==
          std::to_string(plain.cpu.runtime.lockout_attempts) + ", " + std::to_string(plain.cpu.runtime.lockout_period.count()));
    // cpu.timers[].base_ms: "100 (LT, LST: 0.001)".
    CHECK(text(Section::Timer, "base_ms") == "100 (LT, LST: 0.001)");
    auto timers = load({{"cpu", {{"timers", json::array({{{"device", "T0"}, {"preset", 1}}, {{"device", "LT0"}, {"preset", 1}}})}}}})
                      .cpu.runtime.timers;
    REQUIRE(timers.size() == 2);
    CHECK(timers[0].base == std::chrono::milliseconds(100));
    CHECK(timers[1].base == std::chrono::microseconds(1));
    // --clock: "realtime".
    CHECK(config::setting_by_flag("clock")->default_text == "realtime");
    CHECK_FALSE(from_command_line({}).stations.front().server.clock_frozen);
    // ports[].max_connections: "the profile's (16 on iQ-R, Q, L; 8 on FX5; 56 on RJ71EN71)".
    CHECK(text(Section::Port, "max_connections") == "the profile's (16 on iQ-R, Q, L; 8 on FX5; 56 on RJ71EN71)");
    for (const auto& [profile, connections] : std::vector<std::pair<std::string, unsigned>>{
             {"R08CPU", 16}, {"Q26UDEHCPU", 16}, {"L26CPU-BT", 16}, {"FX5U-32MR", 8}, {"RJ71EN71", 56}}) {
        INFO(profile);
        CHECK(config::load_profile(profile).port.max_connections == connections);
    }
}
