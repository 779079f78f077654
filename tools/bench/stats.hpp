// Counting outcomes and summarising latencies.
//
// Every measured request ends in exactly one outcome: ok (latency recorded) or
// one error kind. Latencies are kept whole (one 8-byte sample per request) and
// sorted once at the end, so the percentiles are exact, not bucketed.
#pragma once

#include <array>
#include <chrono>
#include <cstdint>
#include <map>
#include <vector>

namespace slmp::bench {

using Clock = std::chrono::steady_clock;

enum class ErrorKind : std::uint8_t {
    EndCode,      // a well-formed response with a non-zero end code
    Timeout,      // no response within --timeout (the request and all others in flight on that connection)
    Garbage,      // bytes that are not the expected response (bad frame, unknown serial, wrong data size)
    Connection,   // connect failed, or the peer closed/reset with requests in flight
    Count
};

const char* to_string(ErrorKind kind);

struct Recorder {
    std::vector<std::uint64_t> latencies_ns;
    std::array<std::uint64_t, static_cast<std::size_t>(ErrorKind::Count)> errors{};
    std::map<std::uint16_t, std::uint64_t> end_codes;   // non-zero end code -> how many

    void ok(Clock::duration latency);
    void error(ErrorKind kind, std::uint16_t end_code = 0);
    void merge(const Recorder& other);
    std::uint64_t error_total() const;
};

struct Latency {
    double p50 = 0, p90 = 0, p99 = 0, p999 = 0, max = 0, mean = 0;   // microseconds
};

// Sorts the samples in place.
Latency summarize_latency(std::vector<std::uint64_t>& samples_ns);

}  // namespace slmp::bench
