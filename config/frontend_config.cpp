// "kind" and the front ends' sections of the server configuration
// (docs/configuration.md, docs/hostlink.md).
#include "config/frontend_config.hpp"

#include <fstream>
#include <sstream>

#include "config/json_path.hpp"

namespace slmp::config {

namespace {

std::string response_code(const JsonAt& at) {
    auto code = at.string();
    bool hex = code.size() == 2;
    for (char ch : code) hex = hex && ((ch >= '0' && ch <= '9') || (ch >= 'A' && ch <= 'F'));
    if (!hex) at.fail("'" + code + "' is not a response code", "write two uppercase hex digits, e.g. \"01\" or \"15\"");
    return code;
}

void parse_areas(const JsonAt& areas, hostlink::MemoryMap& map) {
    areas.expect_object();
    for (const auto& [key, _] : areas.json().items()) {
        auto at = areas[key];
        auto area = hostlink::area_by_key(key);
        if (!area) at.fail("unknown host-link area '" + key + "'", "use CIO, HR, LR, AR, DM, VR, TC, TC_SET or TC_UP");
        at.only_keys({"device", "size"});
        auto binding = map.binding(*area);
        if (at.has("device")) {
            std::string error;
            auto address = devicemodel::parse_address(at["device"].string(), &error);
            if (!address) at["device"].fail(error, "write the first device of the area, e.g. D0, M4096, TN0");
            binding.base = *address;
        }
        if (at.has("size")) {
            binding.size = static_cast<std::uint32_t>(at["size"].unsigned_int(10000));
            if (binding.size == 0) at["size"].fail("must be at least 1", "give the number of channels, words or T/C numbers");
        }
        map.bind(*area, binding);
    }
}

void parse_hostlink(const JsonAt& at, HostLinkConfig& h) {
    at.only_keys({"tcp_port", "max_connections", "idle_timeout_ms", "partial_frame_timeout_ms", "refused_code",
                  "fcs_error_code", "environment_bytes", "object_bytes", "version", "areas"});
    enable_hostlink(h);
    if (at.has("tcp_port")) h.port.port = static_cast<std::uint16_t>(at["tcp_port"].unsigned_int(65535));
    if (at.has("max_connections")) {
        h.port.max_connections = static_cast<unsigned>(at["max_connections"].unsigned_int(4096));
        if (*h.port.max_connections == 0) at["max_connections"].fail("must be at least 1", "use e.g. 8");
    }
    if (at.has("idle_timeout_ms")) h.port.idle_timeout_ms = static_cast<unsigned>(at["idle_timeout_ms"].unsigned_int(86400000));
    if (at.has("partial_frame_timeout_ms"))
        h.port.partial_frame_timeout_ms = static_cast<unsigned>(at["partial_frame_timeout_ms"].unsigned_int(86400000));
    if (at.has("refused_code")) h.options->refused_code = response_code(at["refused_code"]);
    if (at.has("fcs_error_code")) h.options->fcs_error_code = response_code(at["fcs_error_code"]);
    if (at.has("environment_bytes")) h.options->environment_bytes = at["environment_bytes"].unsigned_int(65536);
    if (at.has("object_bytes")) h.options->object_bytes = at["object_bytes"].unsigned_int(65536);
    if (at.has("version")) h.options->version = at["version"].hex_code();
    if (at.has("areas")) parse_areas(at["areas"], h.options->map);
}

// An optional port: a number, or null for none.
std::optional<PortConfig> optional_port(const JsonAt& at, PortConfig port) {
    if (at.json().is_null()) return std::nullopt;
    port.port = static_cast<std::uint16_t>(at.unsigned_int(65535));
    return port;
}

void parse_jw51cm(const JsonAt& at, Jw51cmConfig& j) {
    at.only_keys({"tcp_port", "udp_port", "max_connections", "idle_timeout_ms", "partial_frame_timeout_ms",
                  "file_bytes", "timers", "timer_attributes"});
    j.enabled = true;
    if (!j.options) j.options = std::make_shared<jw51cm::Options>();
    if (at.has("tcp_port")) j.tcp = optional_port(at["tcp_port"], j.tcp.value_or(PortConfig{Transport::Tcp, 3000, DataCode::Binary, 8}));
    if (at.has("udp_port")) j.udp = optional_port(at["udp_port"], j.udp.value_or(PortConfig{Transport::Udp, 3001, DataCode::Binary}));
    if (!j.tcp && !j.udp) at.fail("no port left", "give \"tcp_port\" or \"udp_port\" a number (the unit needs a TCP_Passive or UDP connection)");
    if (j.tcp) {
        if (at.has("max_connections")) {
            j.tcp->max_connections = static_cast<unsigned>(at["max_connections"].unsigned_int(8));
            if (*j.tcp->max_connections == 0) at["max_connections"].fail("must be 1-8", "the unit has 8 connections; use 1-8");
        }
        if (at.has("idle_timeout_ms")) j.tcp->idle_timeout_ms = static_cast<unsigned>(at["idle_timeout_ms"].unsigned_int(86400000));
        if (at.has("partial_frame_timeout_ms"))
            j.tcp->partial_frame_timeout_ms = static_cast<unsigned>(at["partial_frame_timeout_ms"].unsigned_int(86400000));
    }
    if (at.has("file_bytes")) {
        j.options->file_bytes = static_cast<std::uint32_t>(at["file_bytes"].unsigned_int(65536));
        if (j.options->file_bytes % 2 != 0) at["file_bytes"].fail("must be even", "use e.g. 16384 or 65536");
    }
    if (at.has("timers")) j.options->timers = static_cast<std::uint32_t>(at["timers"].unsigned_int(1024));
    if (at.has("timer_attributes")) {
        auto attributes = at["timer_attributes"];
        attributes.expect_object();
        for (const auto& [number, _] : attributes.json().items()) {
            std::size_t used = 0;
            unsigned long value = 0;
            try {
                value = std::stoul(number, &used, 8);
            } catch (const std::exception&) {
                used = 0;
            }
            if (used != number.size() || value >= j.options->timers)
                attributes[number].fail("'" + number + "' is not a T/C number", "write it in octal, 0000-1777 (TMR0002 is \"0002\")");
            auto code = attributes[number].hex_code();
            if (code > 0x0F) attributes[number].fail("not a T/C attribute", "use 0000-000F (04 TMR, 02 CNT, 08 DTMR BCD, ...)");
            j.options->timer_attributes[static_cast<std::uint32_t>(value)] = static_cast<std::uint8_t>(code);
        }
    }
}

}  // namespace

void enable_hostlink(HostLinkConfig& hostlink) {
    hostlink.enabled = true;
    if (!hostlink.options) hostlink.options = std::make_shared<hostlink::Options>();
}

std::string_view kind_name(StationKind kind) {
    switch (kind) {
        case StationKind::Melsec: return "melsec";
        case StationKind::LadderMotion: return "ladder-motion";
        case StationKind::SharpJw: return "sharp-jw";
    }
    return "?";
}

FrontEndsConfig parse_frontends_config(const std::string& json_text, const std::string& source) {
    auto json = parse_json(json_text, source);
    return parse_frontends_config(JsonAt(json, source));
}

FrontEndsConfig parse_frontends_config(const JsonAt& root) {
    FrontEndsConfig c;
    if (root.has("kind")) {
        auto kind = root["kind"].string();
        if (kind == "melsec") c.kind = StationKind::Melsec;
        else if (kind == "ladder-motion") c.kind = StationKind::LadderMotion;
        else if (kind == "sharp-jw") c.kind = StationKind::SharpJw;
        else root["kind"].fail("unknown station kind '" + kind + "'", "use \"melsec\" (default), \"ladder-motion\" or \"sharp-jw\"");
    }
    if (root.has("hostlink")) parse_hostlink(root["hostlink"], c.hostlink);
    if (root.has("jw51cm")) parse_jw51cm(root["jw51cm"], c.jw51cm);
    if (c.kind == StationKind::SharpJw) {
        if (root.has("ports"))
            root["ports"].fail("a sharp-jw station serves no SLMP ports",
                               "remove \"ports\" (the unit's ports are \"jw51cm\": {\"tcp_port\": ..., \"udp_port\": ...}), "
                               "or use \"kind\": \"melsec\" with a \"jw51cm\" section to serve both on one memory");
        if (root.has("hostlink")) root["hostlink"].fail("a sharp-jw station has no host-link port", "remove \"hostlink\"");
        c.jw51cm.enabled = true;
        if (!c.jw51cm.options) c.jw51cm.options = std::make_shared<jw51cm::Options>();
    }
    if (c.kind == StationKind::LadderMotion) {
        // A Ladder Motion controller has no SLMP port: its link is Host Link.
        if (root.has("jw51cm")) root["jw51cm"].fail("a ladder-motion station has no JW-51CM unit", "remove \"jw51cm\"");
        if (root.has("ports"))
            root["ports"].fail("a ladder-motion station serves no SLMP ports",
                               "remove \"ports\" (the host-link port is \"hostlink\": {\"tcp_port\": ...}), or use "
                               "\"kind\": \"melsec\" with a \"hostlink\" section to serve both on one memory");
        enable_hostlink(c.hostlink);
    }
    return c;
}

FrontEndsConfig load_frontends_config(const std::filesystem::path& file) {
    return parse_frontends_config(read_config_file(file), file.string());
}

}  // namespace slmp::config
