// The CPU's time (docs/ci.md, "Virtual time"). Scan, timers, SM/SD clocks,
// the calendar, the password lock-out and scenario timelines all read it, so
// freezing it stops them all while requests are still answered, and stepping
// it moves them by exactly the time stepped — the same steps give the same
// values on every run, however busy the host is.
//
// Running, CPU time = the time at the last change + real time since × speed;
// frozen, it moves only by advance(). It never depends on when a scan ran.
#pragma once

#include <chrono>

namespace slmp::station {

class VirtualClock {
public:
    using TimePoint = std::chrono::steady_clock::time_point;
    using Duration = std::chrono::steady_clock::duration;

    explicit VirtualClock(double speed = 1, bool frozen = false);

    TimePoint now() const;
    // CPU time since the clock was made (what GET /api/clock reports).
    Duration elapsed() const { return now() - origin_; }
    // The calendar the CPU shows (SD210-SD216): the host's time when the clock
    // was made, moved on by CPU time, so a frozen clock stops the calendar too.
    std::chrono::system_clock::time_point calendar() const;

    bool frozen() const { return frozen_; }
    double speed() const { return speed_; }
    void run(double speed);        // real time × speed from now on
    void freeze();
    void advance(Duration by);     // frozen: CPU time moves by exactly `by`
    void set(TimePoint cpu_time);  // a restored snapshot's time; the mode stays

private:
    void rebase();

    TimePoint origin_;
    std::chrono::system_clock::time_point calendar_origin_;
    TimePoint base_cpu_;    // CPU time at the last change of mode or speed
    TimePoint base_real_;   // the real time of that change
    double speed_;
    bool frozen_;
};

}  // namespace slmp::station
