// slmp-sim --check-config FILE: everything a start checks, without a port, a
// state directory, a recording or a thread (docs/ci.md). Pipelines run it on
// their configurations and scenarios before they start anything.
#pragma once

#include "config/config_error.hpp"
#include "config/plant_config.hpp"

namespace slmp::server {

// Builds the station as a start would (profile, device sizes and initial
// values, modules, CPU No.2-4, "cpu" parameters, scenarios checked against
// the CPU, --snapshot read) and throws config::ConfigError with the same
// one-line message a start would give (in a plant: "station 'NAME': ...").
void check_configuration(const config::StationConfig& station);

}  // namespace slmp::server
