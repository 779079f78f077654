// "file_drives" and "file_end_codes" of a profile (config/profile_drives.cpp).
#pragma once

#include "config/json_path.hpp"
#include "devicemodel/cpu_profile.hpp"
#include "protocol/port_profile.hpp"

namespace slmp::config {

void parse_file_drives(const JsonAt& root, devicemodel::CpuProfile& cpu, protocol::PortProfile& port);

}  // namespace slmp::config
