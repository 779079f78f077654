// What the station is and which front ends it serves (docs/configuration.md
// "kind", docs/hostlink.md, docs/jw51cm.md). Read from the same configuration
// file as config::ServerConfig, by its own parser, so that config.hpp — which
// half the tree includes — does not depend on the front ends. One
// FrontEndsConfig per station: a future "stations" list gives each its own.
#pragma once

#include <filesystem>
#include <memory>
#include <optional>
#include <string>
#include <string_view>

#include "config/config.hpp"
#include "config/json_path.hpp"
#include "frontends/hostlink/host_link.hpp"
#include "frontends/jw51cm/computer_link.hpp"

namespace slmp::config {

// A MELSEC CPU serving SLMP (and, with a "hostlink" or "jw51cm" section, that
// protocol too on the same memory), a Ladder Motion controller serving only
// Host Link, or a Sharp JW CPU serving only the JW-51CM computer link.
enum class StationKind : std::uint8_t { Melsec, LadderMotion, SharpJw };
std::string_view kind_name(StationKind kind);   // "melsec", "ladder-motion", "sharp-jw"

// The Ladder Motion host-link port.
struct HostLinkConfig {
    bool enabled = false;
    PortConfig port{Transport::Tcp, 9600, DataCode::Ascii, 8};   // TCP only; 8 clients (inferred)
    std::shared_ptr<hostlink::Options> options;   // memory map, codes, image sizes; set when enabled
    std::string serial_path;   // --serial: also serve it on a pseudo-terminal linked here (empty: none)
};
// Turns the host link on with default options unless it has some (--hostlink-port).
void enable_hostlink(HostLinkConfig& hostlink);

// The Sharp JW-51CM computer-link ports.
struct Jw51cmConfig {
    bool enabled = false;
    std::optional<PortConfig> tcp = PortConfig{Transport::Tcp, 3000, DataCode::Binary, 8};   // TCP_Passive
    std::optional<PortConfig> udp = PortConfig{Transport::Udp, 3001, DataCode::Binary};
    std::shared_ptr<jw51cm::Options> options;   // file sizes, T/C attributes; set when enabled
};

struct FrontEndsConfig {
    StationKind kind = StationKind::Melsec;
    HostLinkConfig hostlink;
    Jw51cmConfig jw51cm;
};

// The "kind", "hostlink" and "jw51cm" keys of a configuration file (the rest
// is parse_server_config's). Throws ConfigError naming the key and the fix.
FrontEndsConfig parse_frontends_config(const std::string& json_text, const std::string& source);
FrontEndsConfig parse_frontends_config(const JsonAt& root);
FrontEndsConfig load_frontends_config(const std::filesystem::path& file);

}  // namespace slmp::config
