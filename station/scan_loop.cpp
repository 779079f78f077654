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
                   double speed)
    : timer_(io), cpus_(std::move(cpus)), period_(period), speed_(speed) {}

void ScanLoop::start() {
    asio::co_spawn(timer_.get_executor(), run(), log_exception("scan cycle stopped"));
}

void ScanLoop::stop() {
    stopped_ = true;
    timer_.cancel();
}

asio::awaitable<void> ScanLoop::run() {
    const auto origin = std::chrono::steady_clock::now();
    auto next = origin;
    while (!stopped_) {
        const auto real = std::chrono::steady_clock::now();
        // The CPU's time: real time since start, scaled (--clock-speed).
        const auto now = origin + std::chrono::duration_cast<std::chrono::steady_clock::duration>((real - origin) * speed_);
        auto calendar = local_calendar(std::chrono::system_clock::now());
        for (auto* cpu : cpus_) cpu->runtime().scan(cpu->memory(), now, calendar);
        if (after_scan_) after_scan_(now);
        // A fixed cadence; after a stall (a long request, a suspended process)
        // the next scan starts at once instead of catching up scan by scan.
        next += period_;
        if (next < real) next = real;
        timer_.expires_at(next);
        boost::system::error_code ec;
        co_await timer_.async_wait(asio::redirect_error(asio::use_awaitable, ec));
    }
}

}  // namespace slmp::station
