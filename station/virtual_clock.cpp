#include "station/virtual_clock.hpp"

namespace slmp::station {

using std::chrono::steady_clock;

VirtualClock::VirtualClock(double speed, bool frozen)
    : origin_(steady_clock::now()),
      calendar_origin_(std::chrono::system_clock::now()),
      base_cpu_(origin_),
      base_real_(origin_),
      speed_(speed),
      frozen_(frozen) {}

VirtualClock::TimePoint VirtualClock::now() const {
    if (frozen_) return base_cpu_;
    return base_cpu_ + std::chrono::duration_cast<Duration>((steady_clock::now() - base_real_) * speed_);
}

std::chrono::system_clock::time_point VirtualClock::calendar() const {
    return calendar_origin_ + std::chrono::duration_cast<std::chrono::system_clock::duration>(elapsed());
}

void VirtualClock::rebase() {
    base_cpu_ = now();
    base_real_ = steady_clock::now();
}

void VirtualClock::run(double speed) {
    rebase();
    speed_ = speed;
    frozen_ = false;
}

void VirtualClock::freeze() {
    rebase();
    frozen_ = true;
}

void VirtualClock::advance(Duration by) {
    if (frozen_) base_cpu_ += by;
}

void VirtualClock::set(TimePoint cpu_time) {
    base_cpu_ = cpu_time;
    base_real_ = steady_clock::now();
}

}  // namespace slmp::station
