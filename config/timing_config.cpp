#include "config/timing_config.hpp"

#include "config/config.hpp"
#include "config/json_path.hpp"

namespace slmp::config {

namespace {

constexpr const char* kModeFix = "use \"instant\" (default), \"end_of_scan\" or \"model\"";

double milliseconds(const JsonAt& at, double max) {
    if (!at.json().is_number()) at.fail("expected a number of milliseconds", "write it like 3.9");
    auto v = at.json().get<double>();
    if (!(v >= 0 && v <= max)) at.fail("out of range", "use 0 to " + std::to_string(static_cast<int>(max)) + " ms");
    return v;
}

TimingOverrides read_overrides(const JsonAt& at) {
    TimingOverrides o;
    if (at.has("ke_ms")) o.ke_ms = milliseconds(at["ke_ms"], 60000);
    if (at.has("ke_ascii_ms")) o.ke_ascii_ms = milliseconds(at["ke_ascii_ms"], 60000);
    if (at.has("kdt_ms")) o.kdt_ms = milliseconds(at["kdt_ms"], 100);
    if (at.has("kdt_ascii_ms")) o.kdt_ascii_ms = milliseconds(at["kdt_ascii_ms"], 100);
    if (at.has("scan_wait")) o.scan_wait = at["scan_wait"].boolean();
    return o;
}

}  // namespace

std::string_view to_string(TimingMode mode) {
    switch (mode) {
        case TimingMode::Instant: return "instant";
        case TimingMode::EndOfScan: return "end_of_scan";
        case TimingMode::Model: return "model";
    }
    return "instant";
}

TimingMode parse_timing_mode(const std::string& text, const std::string& where) {
    for (auto mode : {TimingMode::Instant, TimingMode::EndOfScan, TimingMode::Model})
        if (text == to_string(mode)) return mode;
    throw ConfigError(where + ": unknown timing mode '" + text + "'; " + kModeFix);
}

TimingModel TimingOverrides::over(TimingModel m) const {
    // ke_ms sets both codes' Ke; ke_ascii_ms then sets ASCII's alone.
    if (ke_ms) m.ke_binary_ms = m.ke_ascii_ms = *ke_ms;
    if (ke_ascii_ms) m.ke_ascii_ms = *ke_ascii_ms;
    if (kdt_ms) m.kdt_binary_ms = *kdt_ms;
    if (kdt_ascii_ms) m.kdt_ascii_ms = *kdt_ascii_ms;
    if (scan_wait) m.scan_wait = *scan_wait;
    return m;
}

TimingModel parse_timing_model(const JsonAt& at, TimingModel base) {
    at.only_keys({"ke_ms", "ke_ascii_ms", "kdt_ms", "kdt_ascii_ms", "scan_wait"});
    return read_overrides(at).over(base);
}

TimingConfig parse_timing_config(const JsonAt& at) {
    at.only_keys({"mode", "ke_ms", "ke_ascii_ms", "kdt_ms", "kdt_ascii_ms", "scan_wait", "jitter", "seed"});
    TimingConfig c;
    if (at.has("mode")) c.mode = parse_timing_mode(at["mode"].string(), at.source() + ": " + at["mode"].pointer());
    c.model = read_overrides(at);
    if (at.has("jitter")) {
        const auto j = at["jitter"];
        if (!j.json().is_number() || !(j.json().get<double>() >= 0 && j.json().get<double>() <= 1))
            j.fail("expected a fraction", "use 0 (none) to 1 (± the whole modelled time), e.g. 0.1");
        c.jitter = j.json().get<double>();
    }
    if (at.has("seed")) c.seed = at["seed"].unsigned_int(~std::uint64_t{0});
    return c;
}

}  // namespace slmp::config
