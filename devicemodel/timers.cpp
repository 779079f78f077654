#include "devicemodel/timers.hpp"

#include <algorithm>

namespace slmp::devicemodel {
namespace {

struct Parts {
    const DeviceSpec* contact = nullptr;
    const DeviceSpec* coil = nullptr;
    const DeviceSpec* value = nullptr;
};

Parts parts_of(Area area) {
    Parts p;
    for (const auto& spec : all_devices()) {
        if (spec.area != area) continue;
        if (spec.part == Part::Contact) p.contact = &spec;
        if (spec.part == Part::Coil) p.coil = &spec;
        if (spec.part == Part::Value) p.value = &spec;
    }
    return p;
}

bool retentive(Area area) { return area == Area::ST || area == Area::LST; }

// 16-bit timers and counters stop at K32767; long ones at the 32-bit maximum.
std::uint32_t max_value(Area area) {
    return area == Area::LT || area == Area::LST || area == Area::LC ? 0xFFFFFFFFu : 32767u;
}

}  // namespace

void TimerBank::configure(std::span<const TimerRange> timers, std::span<const CounterRange> counters) {
    timers_.clear();
    counters_.clear();
    for (const auto& r : timers) timers_.push_back({r, std::vector<std::uint8_t>(r.count), std::vector<std::int64_t>(r.count)});
    for (const auto& r : counters) counters_.push_back({r, std::vector<std::uint8_t>(r.count)});
}

void TimerBank::reset_tracking() {
    for (auto& t : timers_) {
        std::fill(t.timing.begin(), t.timing.end(), 0);
        std::fill(t.remainder_us.begin(), t.remainder_us.end(), 0);
    }
    for (auto& c : counters_) std::fill(c.coil_before.begin(), c.coil_before.end(), 0);
}

void TimerBank::run(DeviceMemory& memory, std::chrono::microseconds elapsed) {
    for (auto& t : timers_) run_timer(memory, t, elapsed);
    for (auto& c : counters_) run_counter(memory, c);
}

std::optional<std::uint64_t> TimerBank::scans_until_due(const DeviceMemory& memory, std::chrono::microseconds per_scan) const {
    std::optional<std::uint64_t> due;
    auto sooner = [&due](std::uint64_t scans) { due = due ? std::min(*due, scans) : scans; };
    for (const auto& t : timers_) {
        const auto p = parts_of(t.range.area);
        const auto size = memory.size(t.range.area);
        const auto base = std::max<std::int64_t>(1, t.range.base.count());
        for (std::uint32_t i = 0; i < t.range.count && t.range.first + i < size; ++i) {
            const auto n = t.range.first + i;
            const std::uint64_t value = memory.value(*p.value, n);
            const bool contact = memory.bit(*p.contact, n);
            if (!memory.bit(*p.coil, n)) {
                // The next scan resets what a coil-off timer still holds.
                if (t.timing[i] || t.remainder_us[i] || (!retentive(t.range.area) && (value || contact))) return 1;
                continue;
            }
            if (!t.timing[i] || value > t.range.preset || contact != (value >= t.range.preset)) return 1;
            if (value == t.range.preset || per_scan.count() <= 0) continue;   // done: only the remainder moves
            // The scan at which the value reaches the preset turns the contact on.
            const auto needed = static_cast<std::int64_t>(t.range.preset - value) * base - t.remainder_us[i];
            sooner(static_cast<std::uint64_t>((needed + per_scan.count() - 1) / per_scan.count()));
        }
    }
    for (const auto& c : counters_) {
        const auto p = parts_of(c.range.area);
        const auto size = memory.size(c.range.area);
        for (std::uint32_t i = 0; i < c.range.count && c.range.first + i < size; ++i) {
            const auto n = c.range.first + i;
            const std::uint64_t value = memory.value(*p.value, n);
            if (memory.bit(*p.coil, n) != static_cast<bool>(c.coil_before[i]) ||
                memory.bit(*p.contact, n) != (value >= c.range.preset) || value > max_value(c.range.area))
                return 1;
        }
    }
    return due;
}

void TimerBank::run_timer(DeviceMemory& memory, Timer& t, std::chrono::microseconds elapsed) {
    const auto p = parts_of(t.range.area);
    const auto size = memory.size(t.range.area);
    const auto base = std::max<std::int64_t>(1, t.range.base.count());
    for (std::uint32_t i = 0; i < t.range.count && t.range.first + i < size; ++i) {
        const auto n = t.range.first + i;
        if (!memory.bit(*p.coil, n)) {
            t.timing[i] = 0;
            t.remainder_us[i] = 0;
            if (!retentive(t.range.area)) {
                memory.set_value(*p.value, n, 0);
                memory.set_bit(*p.contact, n, false);
            }
            continue;
        }
        std::uint64_t value = memory.value(*p.value, n);
        if (t.timing[i]) {
            auto total = t.remainder_us[i] + elapsed.count();
            value = std::min<std::uint64_t>(value + static_cast<std::uint64_t>(total / base), max_value(t.range.area));
            t.remainder_us[i] = total % base;
        }
        t.timing[i] = 1;
        value = std::min<std::uint64_t>(value, t.range.preset);   // the current value stops at the preset
        memory.set_value(*p.value, n, static_cast<std::uint32_t>(value));
        memory.set_bit(*p.contact, n, value >= t.range.preset);
    }
}

void TimerBank::run_counter(DeviceMemory& memory, Counter& c) {
    const auto p = parts_of(c.range.area);
    const auto size = memory.size(c.range.area);
    for (std::uint32_t i = 0; i < c.range.count && c.range.first + i < size; ++i) {
        const auto n = c.range.first + i;
        const bool coil = memory.bit(*p.coil, n);
        std::uint64_t value = memory.value(*p.value, n);
        if (coil && !c.coil_before[i] && value < c.range.preset) ++value;
        c.coil_before[i] = coil ? 1 : 0;
        memory.set_value(*p.value, n, static_cast<std::uint32_t>(std::min<std::uint64_t>(value, max_value(c.range.area))));
        memory.set_bit(*p.contact, n, value >= c.range.preset);
    }
}

}  // namespace slmp::devicemodel
