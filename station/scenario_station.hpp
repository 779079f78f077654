// What scenarios do to the station around the CPU (scenarios::Station): a
// power cut drops every TCP connection and closes the TCP ports (UDP requests
// go unanswered meanwhile, decided in the scenario runner); a refusal period
// closes the TCP ports only. A port opens again when neither holds.
//
// Fidelity note: a powered-off PLC does not answer a TCP SYN at all (the
// client's connect times out); a closed port answers it with RST (connection
// refused at once). The simulator can only do the latter without raw sockets.
#pragma once

#include <functional>
#include <string>

#include "scenarios/runner.hpp"
#include "station/activity.hpp"
#include "station/station_log.hpp"
#include "station/transports.hpp"

namespace slmp::station {

class ScenarioStation final : public scenarios::Station {
public:
    using Ondemand = std::function<void(const scenarios::OndemandAction&, const std::string&)>;
    // A redundant pair's CPU (Station::powered, Station::system_switch).
    struct Redundancy {
        std::function<void(bool on)> powered;
        std::function<void(const std::string& why)> system_switch;
    };
    ScenarioStation(Activity& activity, Transports& transports, Ondemand ondemand, Redundancy redundancy,
                    spdlog::logger& log)
        : activity_(activity), transports_(transports), ondemand_(std::move(ondemand)),
          redundancy_(std::move(redundancy)), log_(log) {}

    void power_off() override;
    void power_on() override;
    void refuse_connections(bool refuse) override;
    void ondemand(const scenarios::OndemandAction& action, const std::string& why) override { ondemand_(action, why); }
    void system_switch(const std::string& why) override { redundancy_.system_switch(why); }

private:
    void update_ports();

    Activity& activity_;
    Transports& transports_;
    Ondemand ondemand_;
    Redundancy redundancy_;
    spdlog::logger& log_;
    bool off_ = false;
    bool refusing_ = false;
};

}  // namespace slmp::station
