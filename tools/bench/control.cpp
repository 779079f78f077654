#include "tools/bench/control.hpp"

#include <algorithm>

namespace slmp::bench {

RunControl::RunControl(Clock::time_point start, Clock::duration warmup, Clock::duration measure_for,
                       std::uint64_t budget, Clock::duration timeout)
    : measure_start_(start + warmup),
      send_until_(measure_for.count() > 0 ? start + warmup + measure_for : Clock::time_point::max()),
      budget_(budget),
      timeout_(timeout) {}

bool RunControl::claim(Clock::time_point now, bool& measured) {
    if (over(now)) return false;
    measured = now >= measure_start_;
    if (measured) ++measured_sent_;
    return true;
}

void RunControl::outcome(Clock::time_point now) { last_outcome_ = std::max(last_outcome_, now); }

double RunControl::measured_seconds() const {
    if (last_outcome_ <= measure_start_) return 0.0;
    return std::chrono::duration<double>(last_outcome_ - measure_start_).count();
}

}  // namespace slmp::bench
