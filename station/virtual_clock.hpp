// The CPU's time (docs/ci.md, "Virtual time"). Scan, timers, SM/SD clocks,
// the calendar, the password lock-out and scenario timelines all read it, so
// freezing it stops them all while requests are still answered, and stepping
// it moves them by exactly the time stepped — the same steps give the same
// values on every run, however busy the host is.
//
// Running, CPU time = the time at the last change + real time since × speed;
// frozen, it moves only by advance(). It never depends on when a scan ran.
// The real time comes from the host's steady clock, or from a test's fake one.
#pragma once

#include <chrono>

namespace slmp::station {

class VirtualClock {
public:
    using TimePoint = std::chrono::steady_clock::time_point;
    using Duration = std::chrono::steady_clock::duration;

    using RealTime = TimePoint (*)();   // the host's steady clock, or a test's

    explicit VirtualClock(double speed = 1, bool frozen = false, RealTime real = &std::chrono::steady_clock::now);

    TimePoint now() const;
    // The host's steady time at which a running clock shows `cpu_time` (never
    // earlier: rounded up), for a timer that wakes then. Frozen: max().
    TimePoint real_time_of(TimePoint cpu_time) const;
    // CPU time since the clock was made (what GET /api/clock reports).
    Duration elapsed() const { return now() - origin_; }
    // The calendar the CPU shows (SD210-SD216): the host's time when the clock
    // was made, moved on by CPU time, so a frozen clock stops the calendar too.
    std::chrono::system_clock::time_point calendar() const { return calendar_at(now()); }
    // The calendar at CPU time `cpu_time` (a scan's instant).
    std::chrono::system_clock::time_point calendar_at(TimePoint cpu_time) const;

    bool frozen() const { return frozen_; }
    double speed() const { return speed_; }
    void run(double speed);        // real time × speed from now on
    void freeze();
    void advance(Duration by);     // frozen: CPU time moves by exactly `by`
    void set(TimePoint cpu_time);  // a restored snapshot's time; the mode stays
    // The calendar shows `shows` now and moves on from there with CPU time
    // (tests pin it, so two clocks show the same calendar).
    void set_calendar(std::chrono::system_clock::time_point shows);

private:
    void rebase();

    RealTime real_;
    TimePoint origin_;
    std::chrono::system_clock::time_point calendar_origin_;
    TimePoint base_cpu_;    // CPU time at the last change of mode or speed
    TimePoint base_real_;   // the real time of that change
    double speed_;
    bool frozen_;
};

}  // namespace slmp::station
