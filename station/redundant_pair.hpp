// A redundant pair of a plant (docs/plants.md, "Redundant pairs"): two
// stations, system A and system B, one the control system and the other the
// standby, which a system switch exchanges. Module I/O 03D0-03D3 in a route
// pick a CPU of the pair by its role or its system; the plant's router asks
// this object which.
//
// Threads: the two stations live on their own strands, and a route reaches the
// pair from any station's strand. The roles are atomics, written by a switch
// (on the strand of the station that switches) and read by every router; the
// switch's end runs on the new control system's strand, on its clock. The
// one lock is the latest tracking image's pointer swap (a control system's
// END stores it, the standby's END takes it); no other lock is taken across
// stations.
//
// Epochs: the number of switches so far. In epoch e the control system is
// system A when e is even, system B when odd (each switch exchanges the
// roles). Each station learns of a switch on its own strand (a posted
// Station::pair_switched) and acts in the epoch it has learnt: a tracking
// image carries the epoch it was taken in, and the standby writes only an
// image of its own epoch — so after a switch no late image of the old
// control system overwrites the new one (docs/plants.md, "Tracking").
#pragma once

#include <array>
#include <atomic>
#include <chrono>
#include <cstdint>
#include <memory>
#include <mutex>
#include <string>
#include <vector>

#include "devicemodel/redundant_registers.hpp"
#include "station/redundant_tracking.hpp"

namespace slmp::station {

class Station;

class RedundantPair {
public:
    RedundantPair(Station& a, std::string a_name, Station& b, std::string b_name, std::chrono::milliseconds switchover,
                  const std::optional<std::vector<Tracking::Range>>& tracking = std::nullopt);

    bool has(const Station& s) const { return &s == members_[0] || &s == members_[1]; }
    Station& partner(const Station& s) const { return &s == members_[0] ? *members_[1] : *members_[0]; }
    char system_of(const Station& s) const { return &s == members_[0] ? 'A' : 'B'; }
    const std::string& name_of(const Station& s) const { return &s == members_[0] ? names_[0] : names_[1]; }
    Station& control() const { return *members_[control_.load()]; }
    Station& standby() const { return *members_[1 - control_.load()]; }
    bool is_control(const Station& s) const { return &s == &control(); }
    // The CPU a module I/O No. of 03D0-03D3 names (§3.1.4): the control system,
    // the standby system, system A, system B.
    Station& pick(std::uint16_t module_io) const;
    // Between a switch and its end (`switchover` on the new control system's
    // clock): routes by role (03D0/03D1) and file commands answer 4248.
    bool switching() const { return switching_.load(); }
    std::chrono::milliseconds switchover() const { return switchover_; }
    unsigned switches() const { return switches_.load(); }

    // Whether a CPU is up (false from a power cut until the power returns):
    // a switch needs its standby up; a route by role to a CPU that is down is
    // answered 4245 by its partner.
    bool available(const Station& s) const { return available_[index(s)].load(); }
    void set_available(const Station& s, bool up) { available_[index(s)].store(up); }

    // A stop error on a CPU (set at its END): a switch to it is refused.
    bool stop_error(const Station& s) const { return stop_error_[index(s)].load(); }
    void set_stop_error(const Station& s, bool error) { stop_error_[index(s)].store(error); }

    // The standby becomes the control system, the control system the standby
    // (`why` for the logs, `cause` for SD1588/SD1601, SD1643/SD1649). From the
    // strand of either station. Empty when it switched; else why not (a
    // switch under way, the standby down or in a stop error: SD1644).
    // Each station hears of it on its strand (Station::pair_switched).
    // `cleared`: the old control system's power is cut or it is resetting,
    // so it stores no cause (its registers start afresh).
    std::string switch_over(const std::string& why, devicemodel::SwitchCause cause, bool cleared = false);

    // Epochs (above): the switches so far, and whether `s` is the control system in epoch `e`.
    std::uint64_t epoch() const { return switches_.load(); }
    bool control_in(const Station& s, std::uint64_t e) const { return index(s) == e % 2; }
    // The pair's SM/SD as `s` shows them in epoch `e` (devicemodel/redundant_registers.hpp).
    devicemodel::RedundantStatus status(const Station& s, std::uint64_t e) const;
    // A CPU powered on or reset: its switch causes and failure read 0 again.
    void clear_registers(const Station& s);

    // Tracking (station/redundant_tracking.hpp): the control system's image of
    // its last END, kept here for the standby's own END (which writes it
    // again over what a client wrote to the standby meanwhile).
    struct Image {
        std::shared_ptr<const TrackingImage> image;
        std::uint64_t epoch = 0;
    };
    const Tracking& tracking() const { return tracking_; }
    void keep(Image image);
    Image latest() const;

private:
    std::size_t index(const Station& s) const { return &s == members_[0] ? 0 : 1; }

    std::array<Station*, 2> members_;   // system A, system B
    std::array<std::string, 2> names_;
    std::chrono::milliseconds switchover_;
    std::atomic<std::size_t> control_{0};   // system A is the control system at start
    std::atomic<bool> switching_{false};
    std::atomic<unsigned> switches_{0};
    std::array<std::atomic<bool>, 2> available_{true, true};
    std::array<std::atomic<bool>, 2> stop_error_{false, false};
    // Per CPU: the cause that occurred in it, the last switch's cause, the last failure.
    std::array<std::atomic<devicemodel::SwitchCause>, 2> own_cause_{devicemodel::SwitchCause::None,
                                                                    devicemodel::SwitchCause::None};
    std::array<std::atomic<devicemodel::SwitchCause>, 2> switch_cause_{devicemodel::SwitchCause::None,
                                                                       devicemodel::SwitchCause::None};
    std::array<std::atomic<devicemodel::SwitchFailure>, 2> failure_{devicemodel::SwitchFailure::None,
                                                                    devicemodel::SwitchFailure::None};
    Tracking tracking_;
    mutable std::mutex image_mutex_;
    Image latest_;
};

}  // namespace slmp::station
