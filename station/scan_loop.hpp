// The scan cycle on the io_context: a steady_timer fires every scan time and
// runs one scan of each CPU at the virtual clock's time. Requests are handled
// on the same thread, so a request is applied whole between two scans (the
// real CPU's END processing). While the clock is frozen no scan runs on its
// own; step() runs scans at once, each moving the clock by one scan time.
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
    ScanLoop(const station::Home& home, std::vector<devicemodel::Cpu*> cpus, std::chrono::milliseconds period,
             double speed = 1, bool frozen = false);

    void start();
    void stop();
    // Called after every scan with the scan's time (the scenarios' clock, the link scan), in the order added.
    void after_scan(std::function<void(std::chrono::steady_clock::time_point)> callback) {
        after_scan_.push_back(std::move(callback));
    }
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

    // Requests held for the clock (docs/timing.md): until_end_or() below; while
    // the clock is frozen it holds until the clock is stepped or runs again.
    // Any number may wait at once.
    std::uint64_t scans() const { return scans_; }
    VirtualClock::TimePoint last_end() const { return last_end_; }   // CPU time of the last END (start: the clock's origin)
    // Returns at whichever comes first: the END of the scan after the
    // `seen`-th (none: no END ends the wait), CPU time `at` (none: no time
    // limit), or a nudge().
    StrandTask<> until_end_or(std::optional<std::uint64_t> seen, std::optional<VirtualClock::TimePoint> at);
    // Wakes every waiter to re-check its condition (a transport read more
    // while it waited: its earliest deadline may have changed).
    void nudge() { wake_waiters(); }
    // The CPU time of the `number`-th END (the first is 1) when it is one of
    // the last kEndsKept; otherwise last_end().
    VirtualClock::TimePoint end_time(std::uint64_t number) const;
    std::size_t waiting() const { return waiters_->size(); }   // answers held now (GET /api/info)
    bool stopped() const { return stopped_; }   // at shutdown: waits return at once

private:
    StrandTask<> run();
    void scan_once();
    void wake_waiters();   // each re-checks its condition against the clock

    using Waiters = std::vector<StrandTimer*>;

    StrandTimer timer_;   // the strand's own type: no allocation a scan (1000 stations scan 100 000 times a second)
    std::vector<devicemodel::Cpu*> cpus_;
    std::chrono::milliseconds period_;
    VirtualClock clock_;
    bool stopped_ = false;
    std::uint64_t scans_ = 0;
    VirtualClock::TimePoint last_end_;
    static constexpr std::size_t kEndsKept = 16;
    std::array<VirtualClock::TimePoint, kEndsKept> ends_{};   // END n at ends_[n % kEndsKept]
    // Shared with each waiting coroutine, which removes itself also when it is
    // destroyed after the loop (at shutdown).
    std::shared_ptr<Waiters> waiters_ = std::make_shared<Waiters>();
    std::vector<std::function<void(std::chrono::steady_clock::time_point)>> after_scan_;
    CpuProgram* program_ = nullptr;
};

}  // namespace slmp::station
