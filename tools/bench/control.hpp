// The run's clock and budget, shared by every connection (all on one thread,
// so no locks): when measuring starts, when sending stops, and how many
// measured requests are still allowed.
#pragma once

#include <cstdint>
#include <functional>
#include <string>
#include <vector>

#include "tools/bench/stats.hpp"
#include "tools/bench/workload.hpp"

namespace slmp::bench {

class RunControl {
public:
    // `measure_for`: zero = no time limit. `budget`: zero = no count limit.
    RunControl(Clock::time_point start, Clock::duration warmup, Clock::duration measure_for,
               std::uint64_t budget, Clock::duration timeout);

    // Asks to send one request at `now`. False once the run is over (time up or
    // budget spent). `measured` says whether its outcome counts (false in warm-up).
    bool claim(Clock::time_point now, bool& measured);
    // Stops all sending now (a fatal error).
    void stop(Clock::time_point now) { send_until_ = now; }
    bool over(Clock::time_point now) const { return now >= send_until_ || (budget_ && measured_sent_ >= budget_); }

    // Called for every measured outcome, so the rate divides by the time really used.
    void outcome(Clock::time_point now);

    Clock::time_point measure_start() const { return measure_start_; }
    Clock::time_point send_until() const { return send_until_; }
    Clock::duration timeout() const { return timeout_; }
    std::uint64_t measured_sent() const { return measured_sent_; }
    // Seconds from the end of warm-up to the last measured outcome.
    double measured_seconds() const;

private:
    Clock::time_point measure_start_;
    Clock::time_point send_until_;
    std::uint64_t budget_;
    std::uint64_t measured_sent_ = 0;
    Clock::time_point last_outcome_{};
    Clock::duration timeout_;
};

// Everything the connections share: what to send, the clock, where results go.
struct RunState {
    const Workload& workload;
    unsigned depth;
    RunControl control;
    std::vector<Recorder> recorders;   // one per operation, in --mix order
    std::string fatal;                 // set when the run cannot go on (first connect failed)
    unsigned live = 0;                 // connections still running
    std::function<void()> all_done;    // called when the last one finishes
};

}  // namespace slmp::bench
