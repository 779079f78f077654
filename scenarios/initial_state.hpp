// A scenario's "initial" block folded into the server configuration before
// the CPU is built: its devices join the configuration's "devices" (so a
// device clear, Remote RESET or power cycle restores them, as the CPU's
// device initial values do), and its switch, password and error replace the
// configuration's "cpu" ones. Later scenarios override earlier ones.
#pragma once

#include "config/config.hpp"
#include "scenarios/scenario.hpp"

namespace slmp::scenarios {

void apply_initial_state(const Scenario& scenario, config::ServerConfig& config);

}  // namespace slmp::scenarios
