#include "config/timing_config.hpp"

#include "config/config.hpp"
#include "config/json_path.hpp"
#include "config/settings.hpp"

namespace slmp::config {

namespace {

TimingOverrides read_overrides(const JsonAt& at) {
    TimingOverrides o;
    for (auto [key, value] : {std::pair{"ke_ms", &o.ke_ms}, {"ke_ascii_ms", &o.ke_ascii_ms}, {"kdt_ms", &o.kdt_ms},
                              {"kdt_ascii_ms", &o.kdt_ascii_ms}})
        if (at.has(key)) *value = number_setting(at, Section::Timing, key);
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
    throw ConfigError(where + ": unknown timing mode '" + text + "'; " + std::string(setting(Section::Timing, "mode").fix));
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
    check_keys(at, Section::ProfileTiming);
    return read_overrides(at).over(base);
}

TimingConfig parse_timing_config(const JsonAt& at) {
    check_keys(at, Section::Timing);
    TimingConfig c;
    if (at.has("mode")) c.mode = parse_timing_mode(choice_setting(at, Section::Timing, "mode"), at["mode"].pointer());
    c.model = read_overrides(at);
    if (at.has("jitter")) c.jitter = number_setting(at, Section::Timing, "jitter");
    if (at.has("seed")) c.seed = bounded_setting(at, Section::Timing, "seed");
    return c;
}

}  // namespace slmp::config
