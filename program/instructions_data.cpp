// Bit and data processing (docs/program.md "Instructions").
#include <bit>

#include "program/handlers.hpp"

namespace slmp::program::detail {

namespace {
bool is_timer_or_counter(Area area) {
    return area == Area::T || area == Area::ST || area == Area::C || area == Area::LT || area == Area::LST ||
           area == Area::LC;
}
}  // namespace

// BSET/BRST d n: bit n (mod 16, inferred) of word d.
SLMP_HANDLER(bset) {
    SLMP_WHEN_ON;
    const auto v = static_cast<std::uint32_t>(get16(m, s.op[0]));
    const auto n = static_cast<std::uint32_t>(get16(m, s.op[1])) % 16;
    SLMP_FAIL_ON_FAULT;
    put16(m, s.op[0], static_cast<std::int32_t>(v | (1u << n)));
}
SLMP_HANDLER(brst) {
    SLMP_WHEN_ON;
    const auto v = static_cast<std::uint32_t>(get16(m, s.op[0]));
    const auto n = static_cast<std::uint32_t>(get16(m, s.op[1])) % 16;
    SLMP_FAIL_ON_FAULT;
    put16(m, s.op[0], static_cast<std::int32_t>(v & ~(1u << n)));
}
// TEST/DTEST s1 s2 d: bit d = bit s2 of s1.
SLMP_HANDLER(test16) {
    SLMP_WHEN_ON;
    const auto v = static_cast<std::uint32_t>(get16(m, s.op[0]));
    const auto n = static_cast<std::uint32_t>(get16(m, s.op[1])) % 16;
    probe(m, s.op[2], 1);
    SLMP_FAIL_ON_FAULT;
    write_bit(m, s.op[2], (v >> n) & 1u);
}
SLMP_HANDLER(test32) {
    SLMP_WHEN_ON;
    const auto v = static_cast<std::uint32_t>(get32(m, s.op[0]));
    const auto n = static_cast<std::uint32_t>(get16(m, s.op[1])) % 32;
    probe(m, s.op[2], 1);
    SLMP_FAIL_ON_FAULT;
    write_bit(m, s.op[2], (v >> n) & 1u);
}
// BKRST d n: n bits from d OFF.
SLMP_HANDLER(bkrst) {
    SLMP_WHEN_ON;
    const auto [base, n] = counted_block(m, s.op[0], s.op[1]);
    for (std::uint32_t i = 0; i < n; ++i) store_byte(m, s.op[0].plane, s.op[0].area, base + i, false);
}
// ZRST d1 d2: bits or words d1..d2 (either order); timers/counters lose value, contact and coil.
SLMP_HANDLER(zrst) {
    SLMP_WHEN_ON;
    auto first = effective(m, s.op[0], 1);
    auto last = effective(m, s.op[1], 1);
    SLMP_FAIL_ON_FAULT;
    if (last < first) std::swap(first, last);
    const Operand& d = s.op[0];
    m.cost_ps += (last - first + 1) * std::uint64_t{m.program->costs.block_ps};
    for (std::uint32_t n = first; n <= last; ++n) {
        if (is_timer_or_counter(d.area)) {
            store_word(m, d.area, n, 0);
            store_byte(m, Plane::Bits, d.area, n, false);
            store_byte(m, Plane::Coils, d.area, n, false);
        } else if (d.kind == OperandKind::Word || d.kind == OperandKind::Wide) {
            store_word(m, d.area, n, 0);
        } else {
            store_byte(m, d.plane, d.area, n, false);
        }
    }
}
SLMP_HANDLER(sum16) {
    SLMP_WHEN_ON;
    const auto v = static_cast<std::uint32_t>(get16(m, s.op[0])) & 0xFFFFu;
    probe(m, s.op[1], 1);
    SLMP_FAIL_ON_FAULT;
    put16(m, s.op[1], std::popcount(v));
}
SLMP_HANDLER(sum32) {
    SLMP_WHEN_ON;
    const auto v = static_cast<std::uint32_t>(get32(m, s.op[0]));
    probe(m, s.op[1], 1);
    SLMP_FAIL_ON_FAULT;
    put16(m, s.op[1], std::popcount(v));
}
// DECO s d n: bit (s mod 2^n) of the 2^n bits at d ON, the others OFF; n = 0 does nothing.
SLMP_HANDLER(deco) {
    SLMP_WHEN_ON;
    const auto v = static_cast<std::uint32_t>(get16(m, s.op[0]));
    const auto n = get16(m, s.op[2]);
    SLMP_FAIL_ON_FAULT;
    if (n < 0 || n > 8) return m.raise(Cause::Range);
    if (n == 0) return;
    const std::uint32_t bits = 1u << n;
    const Operand& d = s.op[1];
    const auto base = block_start(m, d, d.kind == OperandKind::Word ? (bits + 15) / 16 : bits);
    SLMP_FAIL_ON_FAULT;
    const auto on = v & (bits - 1);
    for (std::uint32_t i = 0; i < bits; ++i) set_block_bit(m, d, base, i, i == on);
}
// ENCO s d n: the number of the highest ON bit among the 2^n bits at s; none ON is an error.
SLMP_HANDLER(enco) {
    SLMP_WHEN_ON;
    const auto n = get16(m, s.op[2]);
    probe(m, s.op[1], 1);
    SLMP_FAIL_ON_FAULT;
    if (n < 0 || n > 8) return m.raise(Cause::Range);
    if (n == 0) return;
    const std::uint32_t bits = 1u << n;
    const Operand& from = s.op[0];
    const auto base = block_start(m, from, from.kind == OperandKind::Word ? (bits + 15) / 16 : bits);
    SLMP_FAIL_ON_FAULT;
    for (std::uint32_t i = bits; i-- > 0;)
        if (block_bit(m, from, base, i)) return put16(m, s.op[1], static_cast<std::int32_t>(i));
    m.raise(Cause::Range);
}
// SEG s d: the 7-segment pattern of s's low nibble into d's low byte (high byte kept, inferred).
SLMP_HANDLER(seg) {
    static constexpr std::uint8_t kPatterns[16] = {0x3F, 0x06, 0x5B, 0x4F, 0x66, 0x6D, 0x7D, 0x27,
                                                   0x7F, 0x6F, 0x77, 0x7C, 0x39, 0x5E, 0x79, 0x71};
    SLMP_WHEN_ON;
    const auto v = static_cast<std::uint32_t>(get16(m, s.op[0]));
    const auto d = static_cast<std::uint32_t>(get16(m, s.op[1]));
    SLMP_FAIL_ON_FAULT;
    put16(m, s.op[1], static_cast<std::int32_t>((d & 0xFF00u) | kPatterns[v & 0xFu]));
}

}  // namespace slmp::program::detail
