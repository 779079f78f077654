#include "devicemodel/special_registers.hpp"

#include <array>

namespace slmp::devicemodel::special {
namespace {

const DeviceSpec& sm_spec() { return *find_by_symbol("SM"); }
const DeviceSpec& sd_spec() { return *find_by_symbol("SD"); }

std::uint32_t bcd(int value) { return static_cast<std::uint32_t>((value / 10 % 10) << 4 | value % 10); }

bool pulse(std::chrono::microseconds since, std::int64_t period_us) {
    if (period_us <= 0) return false;
    return since.count() % period_us < period_us / 2;
}

}  // namespace

// Writes outside a profile's SM/SD size are skipped: a profile with fewer
// special devices simply does not publish those.
void set_sm(DeviceMemory& memory, std::uint32_t number, bool on) {
    if (number < memory.size(Area::SM)) memory.set_bit(sm_spec(), number, on);
}

void set_sd(DeviceMemory& memory, std::uint32_t number, std::uint32_t value) {
    if (number < memory.size(Area::SD)) memory.set_value(sd_spec(), number, value & 0xFFFF);
}

std::uint32_t sd(const DeviceMemory& memory, std::uint32_t number) {
    return number < memory.size(Area::SD) ? memory.value(sd_spec(), number) : 0;
}

bool sm(const DeviceMemory& memory, std::uint32_t number) {
    return number < memory.size(Area::SM) && memory.bit(sm_spec(), number);
}

void publish_constants(DeviceMemory& memory) {
    set_sm(memory, 400, true);
    set_sm(memory, 401, false);
    set_sd(memory, 414, 30);
    set_sd(memory, 415, 30);
}

void publish_state(DeviceMemory& memory, RunState state, StopCause cause) {
    auto value = static_cast<std::uint32_t>(state);
    if (state != RunState::Run) value |= static_cast<std::uint32_t>(cause) << 4;
    set_sd(memory, 203, value);
}

void publish_error(DeviceMemory& memory, const std::optional<CpuError>& error) {
    set_sm(memory, 0, error.has_value());
    set_sm(memory, 1, error.has_value());
    set_sd(memory, 0, error ? error->code : 0);
}

void publish_first_scan(DeviceMemory& memory, bool first_scan) {
    set_sm(memory, 402, first_scan);
    set_sm(memory, 403, !first_scan);
}

void publish_clock_pulses(DeviceMemory& memory, std::chrono::microseconds since) {
    set_sm(memory, 409, pulse(since, 10'000));
    set_sm(memory, 410, pulse(since, 100'000));
    set_sm(memory, 411, pulse(since, 200'000));
    set_sm(memory, 412, pulse(since, 1'000'000));
    set_sm(memory, 413, pulse(since, 2'000'000));
    set_sm(memory, 414, pulse(since, 2'000'000LL * sd(memory, 414)));
    set_sm(memory, 415, pulse(since, 2'000LL * sd(memory, 415)));
}

void publish_calendar(DeviceMemory& memory, const CalendarTime& t, Family family) {
    if (family == Family::IQR || family == Family::IQF) {
        const int fields[] = {t.year, t.month, t.day, t.hour, t.minute, t.second, t.weekday};
        for (std::uint32_t i = 0; i < 7; ++i) set_sd(memory, 210 + i, static_cast<std::uint32_t>(fields[i]));
        return;
    }
    set_sd(memory, 210, bcd(t.year % 100) << 8 | bcd(t.month));
    set_sd(memory, 211, bcd(t.day) << 8 | bcd(t.hour));
    set_sd(memory, 212, bcd(t.minute) << 8 | bcd(t.second));
    set_sd(memory, 213, bcd(t.year / 100) << 8 | static_cast<std::uint32_t>(t.weekday));
}

void publish_second_counter(DeviceMemory& memory, std::chrono::microseconds since) {
    set_sd(memory, 412, static_cast<std::uint32_t>(since.count() / 1'000'000));
}

void publish_scan_times(DeviceMemory& memory, Family family, const ScanTimeValues& times) {
    const bool q_layout = family == Family::QnU || family == Family::L || family == Family::QJ71E71;
    const std::array<std::chrono::microseconds, 4> values =
        q_layout ? std::array{times.current, times.initial, times.min, times.max}
                 : std::array{times.current, times.min, times.max, std::chrono::microseconds{}};
    for (std::uint32_t i = 0; i < (q_layout ? 4u : 3u); ++i) {
        auto us = values[i].count();
        set_sd(memory, 520 + 2 * i, static_cast<std::uint32_t>(us / 1000));
        set_sd(memory, 521 + 2 * i, static_cast<std::uint32_t>(us % 1000));
    }
}

}  // namespace slmp::devicemodel::special
