#include "tools/bench/stats.hpp"

#include <algorithm>
#include <cmath>
#include <numeric>

namespace slmp::bench {

const char* to_string(ErrorKind kind) {
    switch (kind) {
    case ErrorKind::EndCode: return "end_code";
    case ErrorKind::Timeout: return "timeout";
    case ErrorKind::Garbage: return "garbage";
    case ErrorKind::Connection: return "connection";
    case ErrorKind::Count: break;
    }
    return "?";
}

void Recorder::ok(Clock::duration latency) {
    latencies_ns.push_back(static_cast<std::uint64_t>(std::chrono::nanoseconds(latency).count()));
}

void Recorder::error(ErrorKind kind, std::uint16_t end_code) {
    ++errors[static_cast<std::size_t>(kind)];
    if (kind == ErrorKind::EndCode) ++end_codes[end_code];
}

void Recorder::merge(const Recorder& other) {
    latencies_ns.insert(latencies_ns.end(), other.latencies_ns.begin(), other.latencies_ns.end());
    for (std::size_t i = 0; i < errors.size(); ++i) errors[i] += other.errors[i];
    for (auto [code, n] : other.end_codes) end_codes[code] += n;
}

std::uint64_t Recorder::error_total() const {
    return std::accumulate(errors.begin(), errors.end(), std::uint64_t{0});
}

namespace {

// Nearest rank: the smallest sample with at least p of all samples at or below it.
double percentile_us(const std::vector<std::uint64_t>& sorted, double p) {
    auto rank = static_cast<std::size_t>(std::ceil(p * static_cast<double>(sorted.size())));
    rank = std::clamp<std::size_t>(rank, 1, sorted.size());
    return static_cast<double>(sorted[rank - 1]) / 1000.0;
}

}  // namespace

Latency summarize_latency(std::vector<std::uint64_t>& samples_ns) {
    Latency l;
    if (samples_ns.empty()) return l;
    std::sort(samples_ns.begin(), samples_ns.end());
    l.p50 = percentile_us(samples_ns, 0.50);
    l.p90 = percentile_us(samples_ns, 0.90);
    l.p99 = percentile_us(samples_ns, 0.99);
    l.p999 = percentile_us(samples_ns, 0.999);
    l.max = static_cast<double>(samples_ns.back()) / 1000.0;
    long double sum = std::accumulate(samples_ns.begin(), samples_ns.end(), 0.0L);
    l.mean = static_cast<double>(sum / samples_ns.size()) / 1000.0;
    return l;
}

}  // namespace slmp::bench
