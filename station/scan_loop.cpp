#include "station/scan_loop.hpp"

#include <ctime>

#include <spdlog/spdlog.h>

#include "station/log_exception.hpp"

namespace slmp::station {

namespace asio = boost::asio;

devicemodel::CalendarTime local_calendar(std::chrono::system_clock::time_point now) {
    auto t = std::chrono::system_clock::to_time_t(now);
    std::tm tm{};
    localtime_r(&t, &tm);
    return {tm.tm_year + 1900, tm.tm_mon + 1, tm.tm_mday, tm.tm_hour, tm.tm_min, tm.tm_sec, tm.tm_wday};
}

ScanLoop::ScanLoop(asio::io_context& io, std::vector<devicemodel::Cpu*> cpus, std::chrono::milliseconds period,
                   double speed, bool frozen)
    : timer_(io), cpus_(std::move(cpus)), period_(period), clock_(speed, frozen) {}

void ScanLoop::start() {
    asio::co_spawn(timer_.get_executor(), run(), log_exception("scan cycle stopped"));
}

void ScanLoop::stop() {
    stopped_ = true;
    timer_.cancel();
}

void ScanLoop::run_clock(double speed) {
    clock_.run(speed);
    timer_.cancel();   // wakes a loop that sleeps while frozen
}

void ScanLoop::freeze_clock() { clock_.freeze(); }

void ScanLoop::scan_once() {
    const auto now = clock_.now();
    auto calendar = local_calendar(clock_.calendar());
    for (auto* cpu : cpus_) cpu->runtime().scan(cpu->memory(), now, calendar);
    if (after_scan_) after_scan_(now);
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

asio::awaitable<void> ScanLoop::run() {
    auto next = std::chrono::steady_clock::now();
    while (!stopped_) {
        boost::system::error_code ec;
        if (clock_.frozen()) {
            // Nothing scans on its own; run_clock() or stop() cancels this wait.
            timer_.expires_at(std::chrono::steady_clock::time_point::max());
            co_await timer_.async_wait(asio::redirect_error(asio::use_awaitable, ec));
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
        co_await timer_.async_wait(asio::redirect_error(asio::use_awaitable, ec));
    }
}

}  // namespace slmp::station
