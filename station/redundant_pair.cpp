// A redundant pair's roles and its system switch (redundant_pair.hpp;
// docs/plants.md, "Redundant pairs").
#include "station/redundant_pair.hpp"

#include <spdlog/spdlog.h>

#include "station/log_exception.hpp"
#include "station/station.hpp"

namespace slmp::station {

namespace asio = boost::asio;

RedundantPair::RedundantPair(Station& a, std::string a_name, Station& b, std::string b_name,
                             std::chrono::milliseconds switchover,
                             const std::optional<std::vector<Tracking::Range>>& tracking)
    : members_{&a, &b},
      names_{std::move(a_name), std::move(b_name)},
      switchover_(switchover),
      tracking_(tracking, a.cpu().memory(), b.cpu().memory()) {}

devicemodel::RedundantStatus RedundantPair::status(const Station& s, std::uint64_t e) const {
    const auto i = index(s);
    return {i == 1, control_in(s, e), own_cause_[i].load(), switch_cause_[i].load(), failure_[i].load()};
}

void RedundantPair::clear_registers(const Station& s) {
    const auto i = index(s);
    own_cause_[i].store(devicemodel::SwitchCause::None);
    switch_cause_[i].store(devicemodel::SwitchCause::None);
    failure_[i].store(devicemodel::SwitchFailure::None);
}

void RedundantPair::keep(Image image) {
    std::lock_guard lock(image_mutex_);
    latest_ = std::move(image);
}

RedundantPair::Image RedundantPair::latest() const {
    std::lock_guard lock(image_mutex_);
    return latest_;
}

Station& RedundantPair::pick(std::uint16_t module_io) const {
    switch (module_io) {
        case 0x03D0: return control();
        case 0x03D1: return standby();
        case 0x03D2: return *members_[0];
        default: return *members_[1];   // 03D3
    }
}

namespace {

// The end of a switch: `switchover` later on the new control system's clock
// (a frozen clock: when a step passes it).
StrandTask<> finish_switch(Station& control, std::chrono::milliseconds switchover, std::atomic<bool>& switching,
                           std::string name) {
    co_await control.wait_on_clock(switchover);
    switching.store(false);
    control.log().info("redundant pair: system switch complete; {} is the control system", name);
}

}  // namespace

std::string RedundantPair::switch_over(const std::string& why, devicemodel::SwitchCause cause, bool cleared) {
    using devicemodel::SwitchFailure;
    const auto refuse = [this](SwitchFailure failure, std::string reason) {
        failure_[control_.load()].store(failure);
        return reason;
    };
    bool idle = false;
    if (!switching_.compare_exchange_strong(idle, true)) return refuse(SwitchFailure::Switching, "a system switch is under way");
    const auto old_control = control_.load();
    const auto next = 1 - old_control;
    if (!available_[next].load()) {
        switching_.store(false);
        return refuse(SwitchFailure::StandbyUnavailable, "the standby system (" + names_[next] + ") is down");
    }
    if (stop_error_[next].load()) {
        switching_.store(false);
        return refuse(SwitchFailure::StandbyStopError, "the standby system (" + names_[next] + ") is in a stop error");
    }
    // The causes first, so a station that hears of the switch publishes them.
    switch_cause_[next].store(cause);
    failure_[next].store(SwitchFailure::None);
    if (!cleared) {
        own_cause_[old_control].store(cause);
        switch_cause_[old_control].store(cause);
        failure_[old_control].store(SwitchFailure::None);
    }
    control_.store(next);
    switches_.fetch_add(1);
    for (auto* member : members_) {
        if (member->has_home()) asio::post(member->home(), [member] { member->pair_switched(); });
        else member->pair_switched();   // a bare station (unit tests): no strand
    }
    auto& control = *members_[next];
    control.log().info("redundant pair: system switch ({}): {} (system {}) becomes the control system, {} the standby",
                       why, names_[next], next == 0 ? 'A' : 'B', names_[old_control]);
    if (switchover_.count() == 0) {
        switching_.store(false);
        return {};
    }
    asio::co_spawn(control.home(), finish_switch(control, switchover_, switching_, names_[next]),
                   log_exception("redundant pair: system switch"));
    return {};
}

}  // namespace slmp::station
