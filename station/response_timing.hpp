// The "model" timing mode's arithmetic (docs/timing.md): how long the port
// takes to answer one request — Ke + Kdt × words (+ the wait for the scan's
// END), Ke and Kdt by the request's data code, ± a seeded jitter — and what
// its monitoring timer allows. Pure: the station asks, the transports hold
// the answer until the virtual clock says so.
#pragma once

#include <chrono>
#include <cstdint>
#include <span>

#include "config/timing_config.hpp"
#include "protocol/request.hpp"

namespace slmp::station {

class ResponseTiming {
public:
    ResponseTiming(config::TimingModel model, double jitter, std::uint64_t seed);

    const config::TimingModel& model() const { return model_; }
    // The modelled time for `request`; `scan_wait` is the time left until the
    // END of the current scan (counted when the model says so). Each call
    // draws the next jitter value.
    std::chrono::microseconds modelled(const protocol::Request& request, std::chrono::microseconds scan_wait);
    // Words of device data a request moves (a bit-unit point counts as 1/16
    // word, a double word as 2; commands that name no devices move none).
    static std::uint64_t words(const protocol::Request& request);
    // The request's monitoring timer in time (units of 250 ms, §3.1.8; 1E
    // too); zero for 0 ("wait forever") and for a timer that does not decode.
    static std::chrono::milliseconds monitoring_timer(const protocol::Request& request, std::span<const std::uint8_t> input) {
        return monitoring_timer(request.header, input);
    }
    // The same from the frame's header alone (a request framed, not decoded yet).
    static std::chrono::milliseconds monitoring_timer(const protocol::FrameHeader& header, std::span<const std::uint8_t> input);

private:
    double next_unit();   // [0, 1), the same sequence for the same seed on every platform

    config::TimingModel model_;
    double jitter_;
    std::uint64_t state_;
};

}  // namespace slmp::station
