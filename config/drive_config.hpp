// The "drives" key and the --drive option (docs/files.md, docs/configuration.md).
#pragma once

#include <string>

#include "config/config.hpp"
#include "config/json_path.hpp"

namespace slmp::config {

// "drives": {"4": {"dir": "plc-data", "capacity": 4194304, "write_protect": false,
//            "present": true, "passwords": {"LINE.CSV": "secret1"}}}
void parse_drives(const JsonAt& root, ServerConfig& config);
// --drive N=DIR: drive N served from the folder DIR.
DriveConfig parse_drive_option(const std::string& text);

}  // namespace slmp::config
