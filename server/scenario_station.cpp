#include "server/scenario_station.hpp"

#include <spdlog/spdlog.h>

namespace slmp::server {

void ScenarioStation::power_off() {
    off_ = true;
    update_ports();
    std::vector<std::uint64_t> ids;
    for (const auto& [id, _] : core_.activity.connections()) ids.push_back(id);
    for (auto id : ids) core_.activity.close(id, "power cut (scenario)");
    spdlog::info("scenario: power off: {} connection(s) dropped, TCP ports closed", ids.size());
}

void ScenarioStation::power_on() {
    off_ = false;
    // The CPU came back: UDP sessions start afresh (locked again under a remote password).
    for (auto& l : udp_) l->restart_session();
    update_ports();
}

void ScenarioStation::refuse_connections(bool refuse) {
    refusing_ = refuse;
    update_ports();
}

void ScenarioStation::update_ports() {
    for (auto& l : tcp_) l->set_refusing(off_ || refusing_);
}

}  // namespace slmp::server
