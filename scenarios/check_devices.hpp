// Checks a scenario's devices against the CPU it runs on (sizes come from the
// profile and the configuration, so the loader cannot). Throws
// config::ConfigError naming the file, the JSON pointer and the fix.
#pragma once

#include "devicemodel/device_memory.hpp"
#include "scenarios/scenario.hpp"

namespace slmp::scenarios {

void check_devices(const Scenario& scenario, const devicemodel::DeviceMemory& memory, const std::string& profile);

}  // namespace slmp::scenarios
