// What the station is and which protocol faces it serves (docs/configuration.md
// "kind"; the faces: frontends/face.hpp). Read from the same configuration
// file as config::ServerConfig, by its own parser, so that config.hpp — which
// half the tree includes — does not depend on the faces. One
// FrontEndsConfig per station: a future "stations" list gives each its own.
#pragma once

#include <filesystem>
#include <string>
#include <string_view>
#include <vector>

#include "config/config.hpp"
#include "config/json_path.hpp"
#include "frontends/face.hpp"

namespace slmp::config {

// A MELSEC CPU serving SLMP ("melsec", with a face's section that protocol
// too on the same memory), or a controller serving only one face: the kind a
// face names (frontends::Face::station_kind, e.g. "ladder-motion").
struct StationKind {
    std::string_view name = "melsec";
    static const StationKind Melsec;
    friend bool operator==(const StationKind&, const StationKind&) = default;
};
inline const StationKind StationKind::Melsec{"melsec"};
inline std::string_view kind_name(StationKind kind) { return kind.name; }

struct FrontEndsConfig {
    StationKind kind = StationKind::Melsec;
    std::vector<frontends::Settings> faces;   // the faces served, in registration order
    // The face's settings when the station serves it, else null.
    const frontends::Settings* find(std::string_view face) const;
    frontends::Settings* find(std::string_view face);
    // The face (that kind's) serving this station alone, or null for "melsec".
    const frontends::Face* kind_face() const;
    // Turns `face` on with its defaults unless it is on; returns its settings.
    frontends::Settings& enable(const frontends::Face& face);
};

// The "kind" key and the faces' sections of a configuration file (the rest
// is parse_server_config's). Throws ConfigError naming the key and the fix.
FrontEndsConfig parse_frontends_config(const std::string& json_text, const std::string& source);
FrontEndsConfig parse_frontends_config(const JsonAt& root);
FrontEndsConfig load_frontends_config(const std::filesystem::path& file);

}  // namespace slmp::config
