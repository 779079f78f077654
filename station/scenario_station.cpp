#include "station/scenario_station.hpp"

#include <vector>

#include <spdlog/spdlog.h>

namespace slmp::station {

void ScenarioStation::power_off() {
    off_ = true;
    update_ports();
    std::vector<std::uint64_t> ids;
    for (const auto& [id, _] : activity_.connections()) ids.push_back(id);
    for (auto id : ids) activity_.close(id, "power cut (scenario)");
    log_.info("scenario: power off: {} connection(s) dropped, TCP ports closed", ids.size());
    redundancy_.powered(false);
}

void ScenarioStation::power_on() {
    off_ = false;
    // The CPU came back: UDP sessions start afresh (locked again under a remote password).
    transports_.restart_sessions();
    update_ports();
    redundancy_.powered(true);
}

void ScenarioStation::refuse_connections(bool refuse) {
    refusing_ = refuse;
    update_ports();
}

void ScenarioStation::update_ports() {
    transports_.refuse_connections(off_ || refusing_);
}

}  // namespace slmp::station
