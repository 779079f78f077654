// The station's part in scenarios and recording (docs/scenarios.md): load the
// --scenario files before the CPU is built (their initial state is part of the
// configuration), then start them once the ports exist, driven by the scan cycle.
#include <spdlog/spdlog.h>

#include "config/station_pattern.hpp"
#include "scenarios/initial_state.hpp"
#include "scenarios/loader.hpp"
#include "station/scan_loop.hpp"
#include "station/scenario_station.hpp"
#include "station/station.hpp"

namespace slmp::station {

std::vector<scenarios::Scenario> Station::load_scenarios() {
    std::vector<scenarios::Scenario> list;
    for (const auto& file : config_.scenarios) {
        auto s = scenarios::load_scenario(file);
        if (!runs(s)) {   // a plant-wide list: the file names other stations
            log_->debug("scenario '{}' ({}) is for {}, not this station", s.name, s.source, fmt::join(s.stations, ", "));
            continue;
        }
        scenarios::apply_initial_state(s, config_);
        list.push_back(std::move(s));
    }
    scenarios::check_together(list);
    return list;
}

bool Station::runs(const scenarios::Scenario& s) const {
    return s.stations.empty() || config_.name.empty() || config::station_patterns_match(s.stations, config_.name);
}

void Station::start_scenarios(std::vector<scenarios::Scenario> list) {
    if (!config_.record_file.empty()) scenario_.record(config_.record_file, cpu_.profile().name);
    if (!config_.record_pcap_file.empty()) scenario_.record_pcap(config_.record_pcap_file, config_.bind);
    // With the HTTP API on, scenarios and recordings may start later (POST
    // /api/scenarios, /api/recording), so the hook is wired up even when idle.
    const bool later = config_.http.enabled;
    if (!list.empty() || later) {
        auto ondemand = [this](const scenarios::OndemandAction& action, const std::string& why) {
            try {
                this->ondemand(action, why);
            } catch (const config::ConfigError& e) {
                log_->warn("scenario: {}: Ondemand not sent: {}", why, e.what());
            }
        };
        scenario_station_ = std::make_unique<ScenarioStation>(activity_, *transports_, ondemand, *log_);
        scenario_.attach(cpu_, *scenario_station_);
        if (!list.empty()) scenario_.start(std::move(list), cpu_, *scenario_station_);
        scan_->after_scan([this](std::chrono::steady_clock::time_point now) { scenario_.scanned(now); });
    }
    if (scenario_.active() || later) activity_.add_observer(&scenario_);
}

}  // namespace slmp::station
