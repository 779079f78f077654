// The scan cycle on the io_context: a steady_timer fires every scan time and
// runs one scan of each CPU. Requests are handled on the same thread, so a
// request is applied whole between two scans (the real CPU's END processing).
#pragma once

#include <chrono>
#include <functional>
#include <vector>

#include "station/asio.hpp"

#include "devicemodel/cpu.hpp"

namespace slmp::station {

// The host's local time as the CPU's calendar (SD210-SD216).
devicemodel::CalendarTime local_calendar(std::chrono::system_clock::time_point now);

class ScanLoop {
public:
    // `speed` > 1 runs the CPU's clock faster than the host's (scans still come
    // every `period` of real time, each covering period × speed of CPU time).
    ScanLoop(boost::asio::io_context& io, std::vector<devicemodel::Cpu*> cpus, std::chrono::milliseconds period,
             double speed = 1);

    void start();
    void stop();
    // Called after every scan with the scan's time (the scenarios' clock).
    void after_scan(std::function<void(std::chrono::steady_clock::time_point)> callback) { after_scan_ = std::move(callback); }

private:
    boost::asio::awaitable<void> run();

    boost::asio::steady_timer timer_;
    std::vector<devicemodel::Cpu*> cpus_;
    std::chrono::milliseconds period_;
    double speed_;
    bool stopped_ = false;
    std::function<void(std::chrono::steady_clock::time_point)> after_scan_;
};

}  // namespace slmp::station
