// The scan cycle on the io_context. Scans come at CPU instants one scan time
// (× the clock's speed) apart, counted from the last one; each runs one scan
// of each CPU at its instant. Requests are handled on the same strand, so a
// request is applied whole between two scans (the real CPU's END processing).
// While the clock is frozen no scan runs on its own; step() runs scans at
// once, each moving the clock by one scan time.
//
// Idle costs nothing (docs/timing.md, "What wakes a station"): only a station
// that needs every scan (a program in RUN, a running scenario, a request
// waiting for END or for its modelled time, a device watcher) wakes every
// scan time. Any other sleeps until the next scan that does more than repeat
// the last one (a timer reaching its preset: Runtime::scans_until_due) or,
// with none, until something touches it; whatever reads or changes the
// station first calls catch_up(), which runs the scans due by now — the first
// one whole, the rest at once (Runtime::scan_repeated) — so every value is
// the one a scan at every instant would show.
#pragma once

#include <array>
#include <chrono>
#include <functional>
#include <optional>
#include <memory>
#include <vector>

#include "station/asio.hpp"

#include "devicemodel/cpu.hpp"
#include "station/virtual_clock.hpp"

namespace slmp::station {

class CpuProgram;

// The host's local time as the CPU's calendar (SD210-SD216).
devicemodel::CalendarTime local_calendar(std::chrono::system_clock::time_point now);

class ScanLoop {
public:
    // `speed` > 1 runs the CPU's clock faster than the host's (scans still come
    // every `period` of real time, each covering period × speed of CPU time).
    // `real`: the host's steady clock, or a test's fake one (the loop's own
    // timer is then never started: the test calls catch_up()).
    ScanLoop(const station::Home& home, std::vector<devicemodel::Cpu*> cpus, std::chrono::milliseconds period,
             double speed = 1, bool frozen = false, VirtualClock::RealTime real = &std::chrono::steady_clock::now);

    void start();   // begin() on the strand, then the loop
    // The first scan now (unless frozen), without the loop's timer: start()
    // does this; a test on a fake clock calls it and then catch_up().
    void begin();
    void stop();
    // Whether something outside the CPUs needs every scan (running scenarios,
    // a device watcher); asked after every scan and touch.
    void needs_every_scan(std::function<bool()> ask) { every_scan_ = std::move(ask); }
    // Runs the scans due by the clock's time now: what the station shows is
    // then what it would show had it scanned at every instant. Call before
    // anything reads or changes the station (a request, an HTTP call, a
    // snapshot); cheap when nothing is due.
    void catch_up();
    // Something may have changed the station (a request, an API write): it
    // scans at the next instant and looks again at what it needs (a timer
    // started by the write, RUN with a program, a scenario loaded).
    void touched();
    // Times the loop's own timer woke it (not a touch or a change of the
    // clock): what an idle plant's test counts (GET /api/info, /api/stations).
    std::uint64_t wakeups() const { return wakeups_; }
    // Every scan, not only those that do more than repeat (tests compare both).
    void always_scan(bool on) { always_ = on; }
    // Called after every scan that does more than repeat with the scan's time
    // (the scenarios' clock, the link scan), in the order added.
    void after_scan(std::function<void(std::chrono::steady_clock::time_point)> callback) {
        after_scan_.push_back(std::move(callback));
    }
    // Called at every END, the repeated scans' last one too (after the
    // after_scan callbacks): a redundant pair's tracking and flags.
    void at_end(std::function<void()> callback) { at_end_.push_back(std::move(callback)); }
    // CPU No.1's program: executed in every scan before END processing, its
    // timers given the scan's time after it (null: none; docs/program.md).
    void run_program(CpuProgram* program) { program_ = program; }

    const VirtualClock& clock() const { return clock_; }
    std::chrono::milliseconds period() const { return period_; }
    void run_clock(double speed);
    void freeze_clock();
    // Frozen only: `scans` scans, each one scan time later than the last.
    void step_scans(std::uint64_t scans);
    // Frozen only: scans of one scan time until `by` has passed, the last one
    // shorter when `by` is not a whole number of scan times.
    void step_time(std::chrono::microseconds by);
    // A restored snapshot's CPU time (the mode stays).
    void set_time(VirtualClock::TimePoint cpu_time);
    void set_calendar(std::chrono::system_clock::time_point shows) { clock_.set_calendar(shows); }

    // Requests held for the clock (docs/timing.md): until_end_or() below; while
    // the clock is frozen it holds until the clock is stepped or runs again.
    // Any number may wait at once.
    // Each catches up first (catch_up()).
    std::uint64_t scans() { catch_up(); return scans_; }
    VirtualClock::TimePoint last_end() { catch_up(); return last_end_; }   // CPU time of the last END (start: the clock's origin)
    // One scan time of CPU time: the period × the running clock's speed
    // (frozen: the period, which step_scans() moves by).
    VirtualClock::Duration cpu_period() const;
    // Returns at whichever comes first: the END of the scan after the
    // `seen`-th (none: no END ends the wait), CPU time `at` (none: no time
    // limit), or a nudge().
    StrandTask<> until_end_or(std::optional<std::uint64_t> seen, std::optional<VirtualClock::TimePoint> at);
    // Wakes every waiter to re-check its condition (a transport read more
    // while it waited: its earliest deadline may have changed).
    void nudge() { wake_waiters(); }
    // The CPU time of the `number`-th END (the first is 1) when it is one of
    // the last kEndsKept; otherwise last_end().
    VirtualClock::TimePoint end_time(std::uint64_t number);
    std::size_t waiting() const { return waiters_->size(); }   // answers held now (GET /api/info)
    bool stopped() const { return stopped_; }   // at shutdown: waits return at once

private:
    StrandTask<> run();
    void scan_once(VirtualClock::TimePoint at);
    // `count` scans that repeat the last one, the last at `at`.
    void scan_repeated(VirtualClock::TimePoint at, std::uint64_t count);
    void ended(VirtualClock::TimePoint at, std::uint64_t count);   // scans_, last_end_, ends_, waiters
    bool needs_every_scan() const;
    // When the loop's timer should wake it next (CPU time); nullopt: only a
    // touch, a step or a change of the clock does.
    std::optional<VirtualClock::TimePoint> next_wake() const;
    void replan();   // the sleeping loop looks again at next_wake()
    void wake_waiters();   // each re-checks its condition against the clock

    using Waiters = std::vector<StrandTimer*>;

    StrandTimer timer_;   // the strand's own type: no allocation a scan (1000 stations scan 100 000 times a second)
    std::vector<devicemodel::Cpu*> cpus_;
    std::chrono::milliseconds period_;
    VirtualClock clock_;
    bool started_ = false;
    bool stopped_ = false;
    bool always_ = false;
    bool touched_ = false;   // scan at the next instant, then look again
    std::optional<VirtualClock::TimePoint> armed_;   // what the loop's timer waits for now (nullopt: nothing)
    std::uint64_t wakeups_ = 0;
    std::function<bool()> every_scan_;
    std::uint64_t scans_ = 0;
    VirtualClock::TimePoint last_end_;
    static constexpr std::size_t kEndsKept = 16;
    std::array<VirtualClock::TimePoint, kEndsKept> ends_{};   // END n at ends_[n % kEndsKept]
    // Shared with each waiting coroutine, which removes itself also when it is
    // destroyed after the loop (at shutdown).
    std::shared_ptr<Waiters> waiters_ = std::make_shared<Waiters>();
    std::vector<std::function<void(std::chrono::steady_clock::time_point)>> after_scan_;
    std::vector<std::function<void()>> at_end_;
    CpuProgram* program_ = nullptr;
};

}  // namespace slmp::station
