#include "station/scan_loop.hpp"

#include <algorithm>
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
                   double speed, bool frozen, VirtualClock::RealTime real)
    : timer_(home), cpus_(std::move(cpus)), period_(period), clock_(speed, frozen, real), last_end_(clock_.now()) {}

void ScanLoop::start() {
    asio::co_spawn(timer_.get_executor(), run(), log_exception("scan cycle stopped"));
}

void ScanLoop::begin() {
    started_ = true;
    if (!clock_.frozen()) scan_once(clock_.now());
}

void ScanLoop::stop() {
    stopped_ = true;
    timer_.cancel();
    wake_waiters();
}

void ScanLoop::run_clock(double speed) {
    catch_up();
    clock_.run(speed);
    // As the clock starts (or changes speed) the CPU scans at once; later
    // scans count from this one.
    if (started_ && !stopped_) scan_once(clock_.now());
    timer_.cancel();   // the loop looks again at when to wake
    wake_waiters();    // their real-time deadlines follow the new speed
}

void ScanLoop::freeze_clock() {
    catch_up();
    clock_.freeze();
    timer_.cancel();
    wake_waiters();
}

void ScanLoop::set_time(VirtualClock::TimePoint cpu_time) {
    clock_.set(cpu_time);
    last_end_ = cpu_time;
    timer_.cancel();
    wake_waiters();
}

void ScanLoop::wake_waiters() {
    for (auto* timer : *waiters_) timer->cancel();
}

VirtualClock::Duration ScanLoop::cpu_period() const {
    if (clock_.frozen()) return period_;
    return std::chrono::duration_cast<VirtualClock::Duration>(std::chrono::duration<double, std::nano>(period_) * clock_.speed());
}

bool ScanLoop::needs_every_scan() const {
    if (always_ || !waiters_->empty()) return true;
    if (program_ && program_->running()) return true;
    if (every_scan_ && every_scan_()) return true;
    // A device watcher (event stream, wait) hears every write a scan makes.
    return std::any_of(cpus_.begin(), cpus_.end(), [](const devicemodel::Cpu* cpu) { return cpu->memory().observed(); });
}

std::optional<VirtualClock::TimePoint> ScanLoop::next_wake() const {
    if (!started_ || stopped_ || clock_.frozen()) return std::nullopt;
    const auto per = cpu_period();
    if (touched_ || needs_every_scan()) return last_end_ + per;
    const auto per_us = std::chrono::duration_cast<std::chrono::microseconds>(per);
    std::optional<std::uint64_t> due;
    for (const auto* cpu : cpus_)
        if (auto d = cpu->runtime().scans_until_due(cpu->memory(), per_us)) due = due ? std::min(*due, *d) : *d;
    if (!due) return std::nullopt;
    return last_end_ + per * static_cast<std::int64_t>(*due);
}

void ScanLoop::touched() {
    if (touched_) return;
    touched_ = true;
    replan();
}

void ScanLoop::replan() {
    // Only a wake that must come sooner needs the timer moved.
    if (started_ && !stopped_ && !clock_.frozen() && (!armed_ || *armed_ > last_end_ + cpu_period())) timer_.cancel();
}

void ScanLoop::catch_up() {
    if (!started_ || stopped_ || clock_.frozen()) return;
    const auto per = cpu_period();
    const auto now = clock_.now();
    if (per <= VirtualClock::Duration::zero() || now < last_end_ + per) return;
    const auto due = static_cast<std::uint64_t>((now - last_end_) / per);
    const auto last = last_end_ + per * static_cast<std::int64_t>(due);
    if (!needs_every_scan()) {
        // The first due scan sees what changed since the last one; the rest repeat it.
        scan_once(last_end_ + per);
        if (due > 1) scan_repeated(last, due - 1);
    } else {
        // Due scans are one when the host keeps up. Behind it (a stall, an
        // overloaded host), the CPU makes one scan at the last due instant
        // covering the gap, as a late scan always did: a program runs once.
        scan_once(last);
    }
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
    catch_up();
    const auto now = clock_.now();
    if (stopped_ || (seen && scans_ > *seen) || (at && now >= *at)) co_return;
    touched();   // a waiter needs every scan: a sleeping loop wakes at the next one
    if (clock_.frozen() || !at)
        timer.expires_at(std::chrono::steady_clock::time_point::max());   // an END, a step, a nudge cancels it
    else
        timer.expires_after(std::chrono::duration_cast<std::chrono::steady_clock::duration>((*at - now) / clock_.speed()));
    boost::system::error_code ec;
    co_await timer.async_wait(asio::redirect_error(use_strand, ec));
}

VirtualClock::TimePoint ScanLoop::end_time(std::uint64_t number) {
    catch_up();
    if (number == 0 || number > scans_ || scans_ - number >= kEndsKept) return last_end_;
    return ends_[number % kEndsKept];
}

void ScanLoop::scan_once(VirtualClock::TimePoint at) {
    auto calendar = local_calendar(clock_.calendar_at(at));
    if (program_) program_->execute();
    for (auto* cpu : cpus_) cpu->runtime().scan(cpu->memory(), at, calendar);
    if (program_) program_->end_of_scan(std::chrono::duration_cast<std::chrono::microseconds>(at - last_end_));
    ended(at, 1);
    for (const auto& callback : after_scan_) callback(at);
    for (const auto& callback : at_end_) callback();
    if (!waiters_->empty()) wake_waiters();
}

void ScanLoop::scan_repeated(VirtualClock::TimePoint at, std::uint64_t count) {
    const auto per_us = std::chrono::duration_cast<std::chrono::microseconds>(cpu_period());
    auto calendar = local_calendar(clock_.calendar_at(at));
    for (auto* cpu : cpus_) cpu->runtime().scan_repeated(cpu->memory(), at, calendar, per_us, count);
    ended(at, count);
    for (const auto& callback : at_end_) callback();
    if (!waiters_->empty()) wake_waiters();
}

void ScanLoop::ended(VirtualClock::TimePoint at, std::uint64_t count) {
    const auto per = cpu_period();
    for (std::uint64_t back = std::min<std::uint64_t>(count, kEndsKept); back-- > 0;)
        ends_[(scans_ + count - back) % kEndsKept] = at - per * static_cast<std::int64_t>(back);
    scans_ += count;
    last_end_ = at;
    touched_ = false;
}

void ScanLoop::step_scans(std::uint64_t scans) {
    if (!clock_.frozen()) return;
    for (std::uint64_t i = 0; i < scans; ++i) {
        clock_.advance(period_);
        scan_once(clock_.now());
    }
}

void ScanLoop::step_time(std::chrono::microseconds by) {
    if (!clock_.frozen()) return;
    const std::chrono::microseconds period = period_;
    for (auto left = by; left.count() > 0; left -= period) {
        clock_.advance(std::min(left, period));
        scan_once(clock_.now());
    }
}

StrandTask<> ScanLoop::run() {
    begin();
    while (!stopped_) {
        // Asleep until the next scan that does more than repeat the last one
        // (every scan when one is needed), a touch, or a change of the clock.
        armed_ = next_wake();
        timer_.expires_at(armed_ ? clock_.real_time_of(*armed_) : std::chrono::steady_clock::time_point::max());
        boost::system::error_code ec;
        co_await timer_.async_wait(asio::redirect_error(use_strand, ec));
        armed_.reset();
        if (stopped_) break;
        if (!ec) ++wakeups_;
        catch_up();
    }
}

}  // namespace slmp::station
