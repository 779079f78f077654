// A redundant pair of a plant (docs/plants.md, "Redundant pairs"): two
// stations, system A and system B, one the control system and the other the
// standby, which a system switch exchanges. Module I/O 03D0-03D3 in a route
// pick a CPU of the pair by its role or its system; the plant's router asks
// this object which.
//
// Threads: the two stations live on their own strands, and a route reaches the
// pair from any station's strand. The roles are atomics, written by a switch
// (on the strand of the station that switches) and read by every router; the
// switch's end runs on the new control system's strand, on its clock. No lock
// is taken across stations.
#pragma once

#include <array>
#include <atomic>
#include <chrono>
#include <cstdint>
#include <string>

namespace slmp::station {

class Station;

class RedundantPair {
public:
    RedundantPair(Station& a, std::string a_name, Station& b, std::string b_name, std::chrono::milliseconds switchover);

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

    // The standby becomes the control system, the control system the standby
    // (`why` for the logs). From the strand of either station. Empty when it
    // switched; else why not (a switch under way, the standby down).
    std::string switch_over(const std::string& why);

private:
    std::size_t index(const Station& s) const { return &s == members_[0] ? 0 : 1; }

    std::array<Station*, 2> members_;   // system A, system B
    std::array<std::string, 2> names_;
    std::chrono::milliseconds switchover_;
    std::atomic<std::size_t> control_{0};   // system A is the control system at start
    std::atomic<bool> switching_{false};
    std::atomic<unsigned> switches_{0};
    std::array<std::atomic<bool>, 2> available_{true, true};
};

}  // namespace slmp::station
