#include "station/scan_loop.hpp"

#include <ctime>

#include <spdlog/spdlog.h>

#include "station/cpu_program.hpp"
#include "station/log_exception.hpp"

namespace slmp::station {

namespace asio = boost::asio;

devicemodel::CalendarTime local_calendar(std::chrono::system_clock::time_point now) {
    auto t = std::chrono::system_clock::to_time_t(now);
    std::tm tm{};
    localtime_r(&t, &tm);
    return {tm.tm_year + 1900, tm.tm_mon + 1, tm.tm_mday, tm.tm_hour, tm.tm_min, tm.tm_sec, tm.tm_wday};
}

ScanLoop::ScanLoop(const station::Home& home, std::vector<devicemodel::Cpu*> cpus, std::chrono::milliseconds period,
                   double speed, bool frozen)
    : timer_(home), cpus_(std::move(cpus)), period_(period), clock_(speed, frozen), last_end_(clock_.now()) {}

void ScanLoop::start() {
    asio::co_spawn(timer_.get_executor(), run(), log_exception("scan cycle stopped"));
}

void ScanLoop::stop() {
    stopped_ = true;
    timer_.cancel();
    wake_waiters();
}

void ScanLoop::run_clock(double speed) {
    clock_.run(speed);
    timer_.cancel();   // wakes a loop that sleeps while frozen
    wake_waiters();    // their real-time deadlines follow the new speed
}

void ScanLoop::freeze_clock() {
    clock_.freeze();
    wake_waiters();
}

void ScanLoop::set_time(VirtualClock::TimePoint cpu_time) {
    clock_.set(cpu_time);
    last_end_ = cpu_time;
    wake_waiters();
}

void ScanLoop::wake_waiters() {
    for (auto* timer : *waiters_) timer->cancel();
}

namespace {

// Registers a waiting coroutine's timer for as long as it waits.
class WaiterGuard {
public:
    WaiterGuard(const std::shared_ptr<std::vector<StrandTimer*>>& list, StrandTimer& timer)
        : list_(list), timer_(&timer) {
        list->push_back(timer_);
    }
    ~WaiterGuard() {
        if (auto list = list_.lock()) std::erase(*list, timer_);
    }
    WaiterGuard(const WaiterGuard&) = delete;
    WaiterGuard& operator=(const WaiterGuard&) = delete;

private:
    std::weak_ptr<std::vector<StrandTimer*>> list_;
    StrandTimer* timer_;
};

}  // namespace

StrandTask<> ScanLoop::until_end_or(std::optional<std::uint64_t> seen, std::optional<VirtualClock::TimePoint> at) {
    StrandTimer timer(timer_.get_executor());
    WaiterGuard guard(waiters_, timer);
    const auto now = clock_.now();
    if (stopped_ || (seen && scans_ > *seen) || (at && now >= *at)) co_return;
    if (clock_.frozen() || !at)
        timer.expires_at(std::chrono::steady_clock::time_point::max());   // an END, a step, a nudge cancels it
    else
        timer.expires_after(std::chrono::duration_cast<std::chrono::steady_clock::duration>((*at - now) / clock_.speed()));
    boost::system::error_code ec;
    co_await timer.async_wait(asio::redirect_error(use_strand, ec));
}

VirtualClock::TimePoint ScanLoop::end_time(std::uint64_t number) const {
    if (number == 0 || number > scans_ || scans_ - number >= kEndsKept) return last_end_;
    return ends_[number % kEndsKept];
}

void ScanLoop::scan_once() {
    const auto now = clock_.now();
    auto calendar = local_calendar(clock_.calendar());
    if (program_) program_->execute();
    for (auto* cpu : cpus_) cpu->runtime().scan(cpu->memory(), now, calendar);
    if (program_) program_->end_of_scan(std::chrono::duration_cast<std::chrono::microseconds>(now - last_end_));
    ++scans_;
    last_end_ = now;
    ends_[scans_ % kEndsKept] = now;
    for (const auto& callback : after_scan_) callback(now);
    if (!waiters_->empty()) wake_waiters();
}

void ScanLoop::step_scans(std::uint64_t scans) {
    if (!clock_.frozen()) return;
    for (std::uint64_t i = 0; i < scans; ++i) {
        clock_.advance(period_);
        scan_once();
    }
}

void ScanLoop::step_time(std::chrono::microseconds by) {
    if (!clock_.frozen()) return;
    const std::chrono::microseconds period = period_;
    for (auto left = by; left.count() > 0; left -= period) {
        clock_.advance(std::min(left, period));
        scan_once();
    }
}

StrandTask<> ScanLoop::run() {
    auto next = std::chrono::steady_clock::now();
    while (!stopped_) {
        boost::system::error_code ec;
        if (clock_.frozen()) {
            // Nothing scans on its own; run_clock() or stop() cancels this wait.
            timer_.expires_at(std::chrono::steady_clock::time_point::max());
            co_await timer_.async_wait(asio::redirect_error(use_strand, ec));
            next = std::chrono::steady_clock::now();
            continue;
        }
        const auto real = std::chrono::steady_clock::now();
        scan_once();
        // A fixed cadence; after a stall (a long request, a suspended process)
        // the next scan starts at once instead of catching up scan by scan.
        next += period_;
        if (next < real) next = real;
        timer_.expires_at(next);
        co_await timer_.async_wait(asio::redirect_error(use_strand, ec));
    }
}

}  // namespace slmp::station
