// When a station's answers leave (docs/timing.md): at once ("instant", the
// default), at the END of the simulated scan ("end_of_scan"), or after the
// modelled response time Ke + Kdt × points (+ the wait for END) ("model").
// The model's constants come from the profile's "timing" object (defaults:
// TimingModel below) and may be overridden by the configuration's "timing".
#pragma once

#include <cstdint>
#include <optional>
#include <string>
#include <string_view>

namespace slmp::config {

class JsonAt;

enum class TimingMode : std::uint8_t { Instant, EndOfScan, Model };
std::string_view to_string(TimingMode mode);   // "instant", "end_of_scan", "model"
// Throws ConfigError naming `where` and the three modes.
TimingMode parse_timing_mode(const std::string& text, const std::string& where);

// The response-time model's constants (docs/timing.md lists their sources).
// Ke: the fixed part of one request; Kdt: per word of device data, so the
// ASCII code, which moves each word as four characters, costs more.
struct TimingModel {
    double ke_binary_ms = 3.9;       // R08CPU: 4.4 ms measured (real-CPU measurements) - mean scan wait at 1 ms scan
    double ke_ascii_ms = 3.9;        // inferred: the same fixed cost; ASCII shows in Kdt
    double kdt_binary_ms = 0.003;    // FX5 / NZ2GF-ETB manuals' Kdt, binary (issue 13)
    double kdt_ascii_ms = 0.0045;    // the same manuals, ASCII
    bool scan_wait = true;           // the request also waits for the END of the scan it arrived in
};

// The model keys a "timing" object names; the others keep the values below them.
struct TimingOverrides {
    std::optional<double> ke_ms, ke_ascii_ms, kdt_ms, kdt_ascii_ms;
    std::optional<bool> scan_wait;
    TimingModel over(TimingModel base) const;
};

struct TimingConfig {
    TimingMode mode = TimingMode::Instant;
    TimingOverrides model;              // over the profile's constants
    double jitter = 0;                  // ± this fraction of the modelled time, uniformly (0-1)
    std::uint64_t seed = 1;             // the jitter's random stream: the same seed, the same times
};

// The profile's "timing" object over `base` (profile_loader.cpp).
TimingModel parse_timing_model(const JsonAt& at, TimingModel base);
// The configuration's "timing" object (docs/configuration.md).
TimingConfig parse_timing_config(const JsonAt& at);

}  // namespace slmp::config
