// The command line: Boost.Program_options on top of the JSON configuration
// file. Precedence: built-in defaults < --config file < command-line options.
#pragma once

#include <optional>
#include <string>

#include "config/config.hpp"
#include "config/frontend_config.hpp"
#include "config/plant_config.hpp"

namespace slmp::server {

struct CommandLine {
    // One station, or a plant of them ("stations", docs/plants.md). The
    // process-wide settings (HTTP, log level, ready file) are the same in
    // every station's ServerConfig; stations.front()'s are read.
    config::PlantConfig plant;
    bool exit_now = false;      // --help, --version, --list-profiles: printed already
    bool check_only = false;    // --check-config: check the configuration, start nothing
};

// Parses argv. Throws config::ConfigError with a one-line message that names
// the option and the fix.
CommandLine parse_command_line(int argc, char** argv);

}  // namespace slmp::server
