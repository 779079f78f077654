// Triggers at run time. A trigger fires when its condition becomes true:
//  - a device comparison ("D100 >= 50"): when it turns true (also at the
//    first scan if it is true then); with for_ms, once it has stayed true that
//    long; it fires again only after it has been false;
//  - rising/falling: when the bit changes between two scans;
//  - a time (at_ms): once, at the first scan at or after it;
//  - traffic: for every request the CPU handled that matches (with "request":
//    N, only the N-th match); reads/writes count only when they succeeded.
// `times` limits how often a trigger fires in all.
#pragma once

#include <vector>

#include "devicemodel/device_memory.hpp"
#include "protocol/end_code.hpp"
#include "scenarios/incoming.hpp"
#include "scenarios/scenario.hpp"

namespace slmp::scenarios {

class TriggerSet {
public:
    void add(const Trigger& trigger) { states_.push_back(State{&trigger}); }

    // Device and time conditions, once per scan. Appends what fired.
    void scan(const devicemodel::DeviceMemory& memory, double now_ms, std::vector<const Trigger*>& fired);
    // Traffic conditions, for a request the CPU answered with `end_code`.
    void request(const Incoming& incoming, protocol::EndCode end_code, std::vector<const Trigger*>& fired);

private:
    struct State {
        const Trigger* trigger;
        bool seen = false;          // a first value has been taken
        bool last = false;          // condition (compare) or bit (edges) at the previous scan
        double true_since = 0;      // when the compare turned true
        bool fired_this_time = false;
        std::uint64_t matches = 0;  // traffic: matching requests so far
        std::uint64_t fired = 0;
    };
    static bool exhausted(const State& s) { return s.trigger->times && s.fired >= s.trigger->times; }

    std::vector<State> states_;
};

// The value of a condition's operand now.
double operand_value(const devicemodel::DeviceMemory& memory, const Operand& operand);

}  // namespace slmp::scenarios
