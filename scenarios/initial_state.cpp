#include "scenarios/initial_state.hpp"

namespace slmp::scenarios {

void apply_initial_state(const Scenario& scenario, config::ServerConfig& config) {
    const auto& initial = scenario.initial;
    config.devices.insert(config.devices.end(), initial.devices.begin(), initial.devices.end());
    auto& runtime = config.cpu.runtime;
    if (initial.run_switch) runtime.run_switch = *initial.run_switch;
    if (initial.password) runtime.password = *initial.password;
    if (initial.error) runtime.error = *initial.error;
}

}  // namespace slmp::scenarios
