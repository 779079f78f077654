// A redundant pair's CPU at work (docs/plants.md, "Redundant pairs",
// "Tracking"; docs/cpu-runtime.md, "Redundant pairs"): the system switches a
// station asks for or causes, tracking at END, and the pair's SM/SD. Runs on
// the station's strand; the pair's shared state is its atomics
// (station/redundant_pair.hpp).
#include <spdlog/spdlog.h>

#include "devicemodel/hex.hpp"
#include "station/network_map.hpp"
#include "station/station.hpp"

namespace slmp::station {

namespace asio = boost::asio;
using devicemodel::SwitchCause;

std::string Station::system_switch(const std::string& why) {
    if (!pair_) return "this station is no CPU of a redundant pair";
    return pair_->switch_over(why, SwitchCause::Request);
}

void Station::powered(bool on) {
    if (!pair_) return;
    pair_->set_available(*this, on);
    if (on) {   // the CPU starts afresh: its switch registers read 0
        pair_restarted(false);
        return;
    }
    // The control system's power cut switches the systems (automatic system switching).
    if (pair_->is_control(*this)) {
        auto why = pair_->switch_over("power cut at the control system", SwitchCause::PowerOffOrReset, true);
        if (!why.empty()) log_->warn("redundant pair: no system switch: {}", why);
    }
}

void Station::pair_restarted(bool reset) {
    if (!pair_) return;
    pair_->clear_registers(*this);
    stop_error_switched_ = false;
    pair_->set_stop_error(*this, false);   // a RESET or power cycle clears the stop error
    // A RESET of the control system switches the systems, as its power cut does
    // (a powered-off CPU is no longer the control system when its power returns).
    if (reset && pair_->is_control(*this)) {
        auto why = pair_->switch_over("RESET of the control system", SwitchCause::PowerOffOrReset, true);
        if (!why.empty()) log_->warn("redundant pair: no system switch: {}", why);
    }
    publish_pair_flags();   // the restart cleared every SM
}

void Station::pair_switched() {
    if (!pair_) return;   // a station the map paired but that never joined (unit tests)
    pair_epoch_ = pair_->epoch();
    publish_pair_flags();
    touched();   // the program and the scan see the new role at the next scan
}

void Station::publish_pair_flags() {
    devicemodel::publish_redundant(cpu_.memory(), cpu_.profile().family, pair_->status(*this, pair_epoch_));
}

void Station::track_from(const RedundantPair::Image& image) {
    // Only an image of the epoch this CPU is the standby in (RedundantPair, "Epochs").
    if (!image.image || image.epoch != pair_epoch_ || pair_->control_in(*this, pair_epoch_) || !pair_->available(*this)) return;
    pair_->tracking().apply(*image.image, cpu_.memory());
}

void Station::pair_end_of_scan() {
    if (!pair_->available(*this)) return;   // powered off: no tracking, no flags (the power-on writes them)
    const auto& error = cpu_.runtime().operating_state().error();
    const bool stop_error = error && error->stop;
    pair_->set_stop_error(*this, stop_error);
    if (!stop_error) stop_error_switched_ = false;
    if (!pair_->control_in(*this, pair_epoch_)) {
        // The standby: what a client wrote to its tracked devices gives way to
        // the control system's last END again.
        track_from(pair_->latest());
        publish_pair_flags();
        return;
    }
    // Tracking: this END's devices, to the standby's strand (and kept for its
    // own END). Before a switch this END asks for, so the new control system
    // starts from this END's values.
    RedundantPair::Image image{pair_->tracking().capture(cpu_.memory()), pair_epoch_};
    pair_->keep(image);
    auto& standby = pair_->partner(*this);
    if (standby.has_home()) asio::post(standby.home(), [&standby, image] { standby.track_from(image); });
    // A stop error of the control system switches the systems; while the
    // standby cannot take over, every END asks again (logged once), so the
    // switch comes once the standby is back. A STOP does not switch: a real
    // pair keeps its roles (docs/plants.md).
    if (stop_error && pair_->is_control(*this)) {
        auto why = pair_->switch_over("stop error " + devicemodel::hex4(error->code) + " at the control system",
                                      SwitchCause::StopError);
        if (!why.empty() && !stop_error_switched_) log_->warn("redundant pair: no system switch: {}", why);
        stop_error_switched_ = true;
    }
    publish_pair_flags();
}

}  // namespace slmp::station
