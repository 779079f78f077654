// CPU profiles: JSON (config/profiles/*.json, embedded at build time) into
// devicemodel::CpuProfile. The keys are documented in docs/configuration.md.
#include <algorithm>
#include <cctype>
#include <fstream>
#include <map>
#include <mutex>
#include <sstream>

#include "config/builtin_profiles.hpp"
#include "config/config.hpp"
#include "config/config_parts.hpp"
#include "config/json_path.hpp"
#include "config/settings.hpp"
#include "config/profile_drives.hpp"

namespace slmp::config {

using devicemodel::Area;
using devicemodel::CpuProfile;
using devicemodel::Family;
using protocol::Refusal;

namespace {

std::string upper(std::string text) {
    for (auto& c : text) c = static_cast<char>(std::toupper(static_cast<unsigned char>(c)));
    return text;
}

Area area(const JsonAt& at) {
    auto name = at.string();
    auto found = devicemodel::area_by_name(name);
    if (!found) at.fail("unknown device '" + name + "'", "use a device area such as X, M, D, T, ZR, LZ");
    return *found;
}

// "answer", "silence", "close", or a 4-digit end code such as "C059".
Refusal refusal(const JsonAt& at) {
    auto text = at.string();
    if (text == "answer") return {Refusal::Kind::Serve, 0};
    if (text == "silence") return {Refusal::Kind::Silence, 0};
    if (text == "close") return {Refusal::Kind::Close, 0};
    if (text.size() != 4) at.fail("'" + text + "' is not a port reaction", "use answer, silence, close or an end code like \"C059\"");
    return {Refusal::Kind::EndCode, at.hex_code()};
}

Family family(const JsonAt& at) {
    auto text = at.string();
    for (auto f : {Family::IQR, Family::QnU, Family::L, Family::QJ71E71, Family::IQF})
        if (text == family_name(f)) return f;
    at.fail("unknown family '" + text + "'", "use iQ-R, QnU, L, QJ71E71 or iQ-F");
}

std::uint32_t whole32(const JsonAt& at, Section section, std::string_view key) {
    return static_cast<std::uint32_t>(bounded_setting(at, section, key));
}

protocol::PointLimit limit(const JsonAt& at) {
    check_keys(at, Section::PointLimit);
    return {whole32(at, Section::PointLimit, "max"), at["end_code"].hex_code()};
}

protocol::FormLimit form_limit(const JsonAt& at) {
    check_keys(at, Section::FormLimit);
    return {whole32(at, Section::FormLimit, "q"), whole32(at, Section::FormLimit, "iqr"), at["end_code"].hex_code()};
}

// "frame_1e": {"pc_type": "41"}: the port serves 1E and answers 15 with this byte.
void frame_1e(const JsonAt& at, protocol::PortProfile& port) {
    check_keys(at, Section::Frame1E);
    auto code = at["pc_type"].hex_code();
    if (code > 0xFF) at["pc_type"].fail("is not one byte", "write it like \"0041\" (00-FF)");
    port.frame_1e = true;
    port.pc_type_1e = static_cast<std::uint8_t>(code);
}

// "pipeline": {"buffer": 32, "over_limit": "CEE0"}: 1 + buffer ÷ connections (SLMP Reference Manual §3.3).
void pipeline(const JsonAt& at, protocol::PortProfile& port) {
    check_keys(at, Section::Pipeline);
    port.pipeline_buffer = whole32(at, Section::Pipeline, "buffer");
    if (at.has("over_limit")) port.pipeline_over_limit = refusal(at["over_limit"]);
    if (port.pipeline_over_limit.kind == Refusal::Kind::Serve)
        at["over_limit"].fail("cannot be answer", "use an end code such as \"CEE0\", silence or close");
}

void end_codes(const JsonAt& codes, protocol::PortProfile& port) {
    check_keys(codes, Section::EndCodes);
    port.not_supported_code = codes["not_supported"].hex_code();
    port.out_of_range_code = codes["out_of_range"].hex_code();
    port.not_accessible_code = codes["not_accessible"].hex_code();
    port.unknown_device_code = codes["unknown_device"].hex_code();
    port.bad_unit_code = codes["bad_unit"].hex_code();
    if (codes.has("online_change_refused")) port.online_change_code = codes["online_change_refused"].hex_code();
    if (codes.has("system_protect")) port.system_protect_code = codes["system_protect"].hex_code();
}

void limits(const JsonAt& limits, protocol::PortProfile& port) {
    check_keys(limits, Section::Limits);
    port.batch_words = limit(limits["batch_words"]);
    port.batch_bits_binary = limit(limits["batch_bits_binary"]);
    port.batch_bits_ascii = limit(limits["batch_bits_ascii"]);
    port.loopback_max_bytes = whole32(limits, Section::Limits, "loopback_bytes");
    port.random_read_points = form_limit(limits["random_read_points"]);
    port.random_write_weight = form_limit(limits["random_write_weight"]);
    port.random_write_bits = form_limit(limits["random_write_bits"]);
    port.monitor_points = form_limit(limits["monitor_points"]);
    port.block_count = form_limit(limits["block_count"]);
    port.block_points = limit(limits["block_points"]);
    if (limits.has("extended_over_limit_code")) port.extended_over_limit_code = limits["extended_over_limit_code"].hex_code();
}

// Keyed by topic, so a profile that extends another changes one entry.
void manual_vs_hardware(const JsonAt& differences, Profile& profile) {
    differences.expect_object();
    for (const auto& [topic, _] : differences.json().items()) {
        auto d = differences[topic];
        check_keys(d, Section::Difference);
        auto follows = d["follows"].string();
        if (!is_choice(setting(Section::Difference, "follows"), follows))
            d["follows"].fail("must be \"manual\" or \"hardware\"", "say which of the two the profile does");
        profile.manual_vs_hardware.push_back({d["what"].string(), d["manual"].string(), d["hardware"].string(),
                                              follows == "hardware"});
    }
}

// [min, max] characters, e.g. [4, 4] for Q/L, [6, 32] for iQ-R.
void password_length(const JsonAt& rule, CpuProfile& p) {
    rule.expect_array();
    if (rule.json().size() != 2) rule.fail("must be [min, max]", "write e.g. [6, 32] (iQ-R) or [4, 4] (Q/L)");
    p.password_min_length = static_cast<std::uint8_t>(rule[0].unsigned_int(32));
    p.password_max_length = static_cast<std::uint8_t>(rule[1].unsigned_int(32));
    if (p.password_min_length == 0 || p.password_min_length > p.password_max_length)
        rule.fail("min must be 1..max", "write e.g. [6, 32] (iQ-R) or [4, 4] (Q/L)");
}

void size_registers(const JsonAt& regs, CpuProfile& p) {
    regs.expect_array();
    for (std::size_t i = 0; i < regs.json().size(); ++i) {
        auto reg = regs[i];
        check_keys(reg, Section::SizeRegister);
        auto bits = bounded_setting(reg, Section::SizeRegister, "bits");
        if (bits != 16 && bits != 32) reg["bits"].fail("must be 16 or 32", "write 16 or 32");
        auto sd = static_cast<std::uint16_t>(bounded_setting(reg, Section::SizeRegister, "sd"));
        if (sd + (bits == 32 ? 1u : 0u) >= p.size(Area::SD))
            reg["sd"].fail("SD" + std::to_string(sd) + " is outside the SD size", "raise device_sizes.SD or fix the number");
        p.size_registers.push_back({area(reg["device"]), sd, static_cast<std::uint8_t>(bits)});
    }
}

std::vector<Area> areas(const JsonAt& at) {
    at.expect_array();
    std::vector<Area> list;
    for (std::size_t i = 0; i < at.json().size(); ++i) list.push_back(area(at[i]));
    return list;
}

}  // namespace

std::string_view family_name(Family family) {
    switch (family) {
        case Family::IQR: return "iQ-R";
        case Family::QnU: return "QnU";
        case Family::L: return "L";
        case Family::QJ71E71: return "QJ71E71";
        case Family::IQF: return "iQ-F";
    }
    return "?";
}

Profile parse_profile(const std::string& json_text, const std::string& source, const std::filesystem::path& directory) {
    auto json = resolve_profile_json(json_text, {source, directory});
    JsonAt root(json, source);
    check_keys(root, Section::Profile);
    Profile profile;
    auto& p = profile.cpu;
    auto& port = profile.port;
    p.name = root["name"].string();
    if (root.has("description")) profile.description = root["description"].string();
    p.type_name = root["type_name"].string();
    if (p.type_name.size() > 16) root["type_name"].fail("longer than 16 characters", "shorten it (0101 sends 16)");
    p.model_code = root["model_code"].hex_code();
    p.family = family(root["family"]);
    port.frame_4e = refusal(root["frame_4e"]);
    port.iqr_subcommands = refusal(root["iqr_subcommands"]);
    if (root.has("frame_1e")) frame_1e(root["frame_1e"], port);
    if (root.has("station_extended_frame")) port.station_extended_frame = root["station_extended_frame"].boolean();
    if (root.has("relays")) port.relays = root["relays"].boolean();
    if (root.has("node_commands")) port.node_commands = root["node_commands"].boolean();
    if (root.has("timing")) profile.timing = parse_timing_model(root["timing"], profile.timing);
    if (root.has("pipeline")) pipeline(root["pipeline"], port);
    // Which commands a port family serves is the command table's (families);
    // a profile may refuse more.
    if (root.has("unsupported_commands")) {
        auto unsupported = root["unsupported_commands"];
        unsupported.expect_array();
        for (std::size_t i = 0; i < unsupported.json().size(); ++i)
            port.unsupported_commands.push_back(unsupported[i].hex_code());
    }

    end_codes(root["end_codes"], port);
    if (root.has("online_change")) port.online_change = root["online_change"].boolean();
    if (root.has("manual_vs_hardware")) manual_vs_hardware(root["manual_vs_hardware"], profile);
    if (root.has("max_connections"))
        port.max_connections = static_cast<unsigned>(whole_setting(root, Section::Profile, "max_connections"));

    limits(root["limits"], port);
    port.mixed_block_write = refusal(root["mixed_block_write"]);
    if (root.has("station_buffer_words"))
        p.station_buffer_words = whole32(root, Section::Profile, "station_buffer_words");

    for (auto [area, points] : parse_device_sizes(root["device_sizes"])) p.sizes[static_cast<std::size_t>(area)] = points;
    p.start_only_range_check = areas(root["start_only_range_check"]);
    port.read_only = areas(root["read_only_devices"]);
    size_registers(root["size_registers"], p);
    port.zr_ascii_hex = root["zr_ascii_hex"].boolean();
    if (root.has("xy_radix")) {
        auto radix = bounded_setting(root, Section::Profile, "xy_radix");
        if (radix != 8 && radix != 16) root["xy_radix"].fail("must be 8 or 16", "write 8 (iQ-F: X0-X7, X10) or 16 (iQ-R, Q, L)");
        p.numbering.xy = static_cast<devicemodel::Radix>(radix);
    }
    if (root.has("remote_password_length")) password_length(root["remote_password_length"], p);
    parse_file_drives(root, p, port);
    return profile;
}

std::vector<std::string> builtin_profile_names() {
    std::vector<std::string> names;
    for (const auto& p : builtin_profiles()) names.emplace_back(p.name);
    return names;
}

const BuiltinProfile* find_builtin_profile(const std::string& name) {
    for (const auto& p : builtin_profiles())
        if (upper(std::string(p.name)) == upper(name)) return &p;
    return nullptr;
}

std::string builtin_profile_list() {
    std::string list;
    for (const auto& n : builtin_profile_names()) list += (list.empty() ? "" : ", ") + n;
    return list;
}

Profile load_profile(const std::string& name_or_path) {
    bool is_path = name_or_path.find('/') != std::string::npos ||
                   (name_or_path.size() > 5 && name_or_path.ends_with(".json"));
    if (is_path) {
        std::ifstream file(name_or_path);
        if (!file) throw ConfigError(name_or_path + ": cannot open the profile file; check the path");
        std::stringstream text;
        text << file.rdbuf();
        return parse_profile(text.str(), name_or_path, std::filesystem::path(name_or_path).parent_path());
    }
    if (const auto* p = find_builtin_profile(name_or_path)) {
        // Built-in profiles never change, so each is parsed once per process:
        // a 10 000-station plant of one profile spent a fifth of its start
        // parsing the same JSON again for every station.
        static std::mutex mutex;
        static std::map<const BuiltinProfile*, Profile> parsed;
        std::lock_guard lock(mutex);
        auto it = parsed.find(p);
        if (it == parsed.end()) it = parsed.emplace(p, parse_profile(std::string(p->json), "profile " + std::string(p->name))).first;
        return it->second;
    }
    throw ConfigError("unknown profile '" + name_or_path + "'; use one of: " + builtin_profile_list() +
                      " (or a path to a profile .json file)");
}

}  // namespace slmp::config
