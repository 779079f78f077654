// The server's part in scenarios and recording (docs/scenarios.md): load the
// --scenario files before the CPU is built (their initial state is part of the
// configuration), then start them once the ports exist, driven by the scan cycle.
#include <spdlog/spdlog.h>

#include "scenarios/initial_state.hpp"
#include "scenarios/loader.hpp"
#include "server/server.hpp"

namespace slmp::server {

std::vector<scenarios::Scenario> Server::load_scenarios() {
    std::vector<scenarios::Scenario> list;
    for (const auto& file : config_.scenarios) {
        list.push_back(scenarios::load_scenario(file));
        scenarios::apply_initial_state(list.back(), config_);
    }
    scenarios::check_together(list);
    return list;
}

void Server::start_scenarios(std::vector<scenarios::Scenario> list) {
    if (!config_.record_file.empty()) core_.scenario.record(config_.record_file, core_.cpu.profile().name);
    if (!config_.record_pcap_file.empty()) core_.scenario.record_pcap(config_.record_pcap_file, config_.bind);
    // With the HTTP API on, scenarios and recordings may start later (POST
    // /api/scenarios, /api/recording), so the hook is wired up even when idle.
    const bool later = config_.http.enabled;
    if (!list.empty() || later) {
        station_ = std::make_unique<ScenarioStation>(core_, tcp_, udp_);
        core_.scenario.attach(core_.cpu, *station_);
        if (!list.empty()) core_.scenario.start(std::move(list), core_.cpu, *station_);
        scan_->after_scan([this](std::chrono::steady_clock::time_point now) { core_.scenario.scanned(now); });
    }
    if (core_.scenario.active() || later) core_.activity.add_observer(&core_.scenario);
}

}  // namespace slmp::server
