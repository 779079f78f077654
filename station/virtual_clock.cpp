#include "station/virtual_clock.hpp"

#include <cmath>
#include <cstdint>

namespace slmp::station {

using std::chrono::steady_clock;

VirtualClock::VirtualClock(double speed, bool frozen, RealTime real)
    : real_(real),
      origin_(real_()),
      calendar_origin_(std::chrono::system_clock::now()),
      base_cpu_(origin_),
      base_real_(origin_),
      speed_(speed),
      frozen_(frozen) {}

VirtualClock::TimePoint VirtualClock::now() const {
    if (frozen_) return base_cpu_;
    return base_cpu_ + std::chrono::duration_cast<Duration>((real_() - base_real_) * speed_);
}

VirtualClock::TimePoint VirtualClock::real_time_of(TimePoint cpu_time) const {
    if (frozen_) return TimePoint::max();
    const std::chrono::duration<double, std::nano> real_ahead = (cpu_time - base_cpu_) / speed_;
    return base_real_ + std::chrono::nanoseconds(static_cast<std::int64_t>(std::ceil(real_ahead.count())) + 1);
}

std::chrono::system_clock::time_point VirtualClock::calendar_at(TimePoint cpu_time) const {
    return calendar_origin_ + std::chrono::duration_cast<std::chrono::system_clock::duration>(cpu_time - origin_);
}

void VirtualClock::rebase() {
    base_cpu_ = now();
    base_real_ = real_();
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

void VirtualClock::set_calendar(std::chrono::system_clock::time_point shows) {
    calendar_origin_ = shows - std::chrono::duration_cast<std::chrono::system_clock::duration>(elapsed());
}

void VirtualClock::advance(Duration by) {
    if (frozen_) base_cpu_ += by;
}

void VirtualClock::set(TimePoint cpu_time) {
    base_cpu_ = cpu_time;
    base_real_ = real_();
}

}  // namespace slmp::station
