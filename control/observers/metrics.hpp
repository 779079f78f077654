// Prometheus metrics of the SLMP side, collected from the listeners' activity
// reports and rendered as text exposition format 0.0.4 for GET /metrics.
// Collecting costs a map lookup and a few additions per request; names and
// labels are only formatted when /metrics is read. docs/api.md lists them.
#pragma once

#include <array>
#include <cstdint>
#include <map>
#include <string>
#include <tuple>
#include <utility>
#include <vector>

#include "station/station.hpp"

namespace slmp::control {

class Metrics final : public station::ActivityObserver {
public:
    // Upper bounds of the request latency histogram, in seconds.
    static constexpr std::array<double, 14> kBuckets = {0.00005, 0.0001, 0.00025, 0.0005, 0.001, 0.0025, 0.005,
                                                        0.01,    0.025,  0.05,    0.1,    0.25,   0.5,   1.0};

    explicit Metrics(station::Station& station);
    ~Metrics();
    Metrics(const Metrics&) = delete;
    Metrics& operator=(const Metrics&) = delete;

    void on_request(const station::RequestRecord& record) override;
    void on_frontend_request(const station::FrontEndRecord& record) override;
    void on_opened(const station::Connection& connection) override;
    void on_closed(const station::Connection& connection, std::string_view why) override;

    std::string render() const;

    // For the plant overview: requests handled, and of those the ones not
    // answered 0000 (error end codes, no answer, closed, unparsed frames).
    struct Totals {
        std::uint64_t requests = 0;
        std::uint64_t errors = 0;
    };
    Totals totals() const;

private:
    // transport, command, subcommand, reaction (end code 0x0000-0xFFFF; kNoAnswer; kClosed)
    using RequestKey = std::tuple<std::uint8_t, std::uint16_t, std::uint16_t, std::uint32_t>;
    static constexpr std::uint32_t kNoAnswer = 0x10000;
    static constexpr std::uint32_t kClosed = 0x10001;

    struct PerTransport {
        std::uint64_t bytes_in = 0;
        std::uint64_t bytes_out = 0;
        std::uint64_t unparsed = 0;
    };

    // A front end's requests: protocol, transport, command, code. Bounded: the
    // protocol is one of two, a command outside the front end's table is
    // "other" (none read: "none"), a code is two hex digits, "IC", "none" or "closed".
    using FrontEndKey = std::tuple<std::string, std::uint8_t, std::string, std::string>;

    station::Station& station_;
    std::map<RequestKey, std::uint64_t> requests_;
    std::map<FrontEndKey, std::uint64_t> frontend_requests_;
    std::array<PerTransport, 2> transports_{};
    std::array<std::uint64_t, kBuckets.size() + 1> latency_buckets_{};   // not cumulative; last = +Inf
    double latency_sum_ = 0;
    std::uint64_t latency_count_ = 0;
    // The "model" timing mode's response time of each request (docs/timing.md), the same buckets.
    std::array<std::uint64_t, kBuckets.size() + 1> modelled_buckets_{};
    double modelled_sum_ = 0;
    std::uint64_t modelled_count_ = 0;
    std::uint64_t accepted_ = 0;
    std::uint64_t closed_ = 0;
};

// Prometheus texts of several stations as one exposition: each family's HELP
// and TYPE once, its samples from every station with station="NAME" first
// among the labels (metrics_merge.cpp).
std::string merge_metrics(const std::vector<std::pair<std::string, std::string>>& texts);

// The same texts summed per group (here: the stations' profile), for a plant
// too large for per-station series: each sample gets profile="GROUP" first
// among its labels and holds the sum over the group's stations; gauges that
// do not add up (the CPU state, scan and program times) are left out and
// slmp_stations{profile, state} counts the stations in RUN, STOP and PAUSE.
std::string sum_metrics(const std::vector<std::pair<std::string, std::string>>& texts);

}  // namespace slmp::control
