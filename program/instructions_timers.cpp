// Timers and counters, with the update rule of docs/program.md
// "Timers": the value moves when OUT T executes, from an
// accumulator that end_of_scan() fills for every timer whose coil is ON.
// Step fields: op[0] the timer/counter (number fixed at load), op[1] the
// preset, edge = timer slot, aux = time base in µs, variant bit 0 = retentive,
// bit 1 = 32-bit value (LT, LST, LC).
#include "program/handlers.hpp"

namespace slmp::program::detail {

namespace {
constexpr std::uint8_t kRetentive = 1, kWide = 2;

std::int64_t preset_of(Machine& m, const Step& s) {
    return (s.variant & kWide) ? std::int64_t{get32(m, s.op[1])} : std::int64_t{get16(m, s.op[1])};
}
}  // namespace

SLMP_HANDLER(out_timer) {
    const auto area = s.op[0].area;
    const auto a = static_cast<std::size_t>(area);
    const auto n = s.op[0].number;
    std::uint64_t& accumulated = m.timer_accumulators[s.edge];
    if (!m.condition()) {   // rule 2
        if (!(s.variant & kRetentive)) {
            store_word(m, area, n, 0);
            store_byte(m, Plane::Bits, area, n, false);
            accumulated = 0;
        }
        store_byte(m, Plane::Coils, area, n, false);
        m.timer_coils[s.edge] = 0;
        return;
    }
    const std::int64_t preset = preset_of(m, s);
    if (m.fault) return m.raise(m.cause);
    if (preset < 0) return m.raise(Cause::Range);
    if (!m.bytes[1][a][n]) {   // rule 3: timing starts
        store_byte(m, Plane::Coils, area, n, true);
        accumulated = 0;
    }
    m.timer_coils[s.edge] = 1;
    if (m.bytes[0][a][n]) return;   // timed out: stays stopped even if the preset was raised ([QFE])
    const std::uint64_t base = s.aux;
    std::uint64_t value = m.words[a][n] + accumulated / base;   // rule 4
    accumulated %= base;
    if (value >= static_cast<std::uint64_t>(preset)) {
        value = static_cast<std::uint64_t>(preset);
        store_byte(m, Plane::Bits, area, n, true);
        accumulated = 0;
    }
    store_word(m, area, n, static_cast<std::uint32_t>(value));
}

// Counts on the coil's rising edge compared with the stored coil (CC), docs/program.md "Timers".
SLMP_HANDLER(out_counter) {
    const auto area = s.op[0].area;
    const auto a = static_cast<std::size_t>(area);
    const auto n = s.op[0].number;
    const bool input = m.condition();
    const std::int64_t preset = preset_of(m, s);
    if (m.fault) return m.raise(m.cause);
    if (preset < 0) return m.raise(Cause::Range);
    std::uint64_t value = m.words[a][n];
    if (input && !m.bytes[1][a][n] && value < static_cast<std::uint64_t>(preset)) {
        ++value;
        store_word(m, area, n, static_cast<std::uint32_t>(value));
    }
    store_byte(m, Plane::Coils, area, n, input);
    store_byte(m, Plane::Bits, area, n, value >= static_cast<std::uint64_t>(preset));
}

// RST T / RST C: value 0, contact OFF; a timer's accumulator 0 too. The coil
// stays, so a timer coil still ON restarts timing at the next OUT T (rule 5)
// and a counter coil still ON counts only after it goes OFF and ON again.
// aux = timer slot + 1; 0: none (a counter, or a timer no OUT drives).
SLMP_HANDLER(rst_timer_counter) {
    if (!m.condition()) return;
    const auto area = s.op[0].area;
    const auto n = effective(m, s.op[0], 1);
    if (m.fault) return m.raise(m.cause);
    store_word(m, area, n, 0);
    store_byte(m, Plane::Bits, area, n, false);
    if (s.aux != 0) m.timer_accumulators[s.aux - 1] = 0;
}


}  // namespace slmp::program::detail
