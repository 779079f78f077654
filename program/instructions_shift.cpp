// Rotation and shift (docs/program.md "Instructions"). The carry is SM700
// (docs/program.md "The scan", inferred). Rotation and word shift counts are taken mod 16 / 32
// (inferred). variant bit 0: left; bit 1: through the carry (RCR/RCL).
#include "program/handlers.hpp"

namespace slmp::program::detail {

namespace {
constexpr std::uint32_t kCarry = 700;
bool carry(Machine& m) {
    return m.size[static_cast<std::size_t>(Area::SM)] > kCarry && m.bytes[0][static_cast<std::size_t>(Area::SM)][kCarry];
}
void set_carry(Machine& m, bool on) {
    if (m.size[static_cast<std::size_t>(Area::SM)] > kCarry) store_byte(m, Plane::Bits, Area::SM, kCarry, on);
}

template <unsigned Bits>
void rotate(Machine& m, const Step& s) {
    SLMP_WHEN_ON;
    constexpr std::uint64_t mask = (std::uint64_t{1} << Bits) - 1;
    std::uint64_t v = static_cast<std::uint32_t>(Bits == 16 ? get16(m, s.op[0]) : get32(m, s.op[0])) & mask;
    const auto n = static_cast<std::uint32_t>(get16(m, s.op[1])) % Bits;
    SLMP_FAIL_ON_FAULT;
    if (n == 0) return;
    const bool left = s.variant & 1u, through = s.variant & 2u;
    bool c = carry(m);
    for (std::uint32_t i = 0; i < n; ++i) {
        if (left) {
            const bool out = (v >> (Bits - 1)) & 1u;
            v = ((v << 1) | (through ? c : out)) & mask;
            c = out;
        } else {
            const bool out = v & 1u;
            v = (v >> 1) | (std::uint64_t{through ? c : out} << (Bits - 1));
            c = out;
        }
    }
    if (Bits == 16) put16(m, s.op[0], static_cast<std::int32_t>(v));
    else put32(m, s.op[0], static_cast<std::int32_t>(v));
    set_carry(m, c);
}
}  // namespace

SLMP_HANDLER(rotate16) { rotate<16>(m, s); }
SLMP_HANDLER(rotate32) { rotate<32>(m, s); }

// SFR/SFL d n: shift by n (mod 16), zero fill; the carry is the last bit out.
SLMP_HANDLER(shift_word) {
    SLMP_WHEN_ON;
    const auto v = static_cast<std::uint32_t>(get16(m, s.op[0])) & 0xFFFFu;
    const auto n = static_cast<std::uint32_t>(get16(m, s.op[1])) % 16;
    SLMP_FAIL_ON_FAULT;
    if (n == 0) return;
    const bool left = s.variant & 1u;
    const bool out = left ? (v >> (16 - n)) & 1u : (v >> (n - 1)) & 1u;
    put16(m, s.op[0], static_cast<std::int32_t>((left ? v << n : v >> n) & 0xFFFFu));
    set_carry(m, out);
}

// SFT d: d takes the bit before it, which turns OFF.
SLMP_HANDLER(sft) {
    SLMP_WHEN_ON;
    const Operand& d = s.op[0];
    if (d.kind == OperandKind::BitOfWord) {
        const auto n = effective(m, d, 1);
        SLMP_FAIL_ON_FAULT;
        auto word = m.words[static_cast<std::size_t>(d.area)][n];
        if (d.bit > 0) {
            const bool before = (word >> (d.bit - 1)) & 1u;
            word = before ? (word | (1u << d.bit)) : (word & ~(1u << d.bit));
            word &= ~(1u << (d.bit - 1));
        } else {
            word &= ~1u;
        }
        return store_word(m, d.area, n, word);
    }
    const auto n = effective(m, d, 1);
    SLMP_FAIL_ON_FAULT;
    if (n == 0) return store_byte(m, d.plane, d.area, 0, false);
    const bool before = m.bytes[static_cast<std::size_t>(d.plane)][static_cast<std::size_t>(d.area)][n - 1] != 0;
    store_byte(m, d.plane, d.area, n, before);
    store_byte(m, d.plane, d.area, n - 1, false);
}

// BSFR/BSFL d n: n bits from d move one place toward d (R) or away from it (L).
SLMP_HANDLER(bit_shift) {
    SLMP_WHEN_ON;
    const Operand& d = s.op[0];
    const auto [base, n] = counted_block(m, d, s.op[1]);
    if (n == 0) return;
    if (s.variant & 1u) {
        const bool out = block_bit(m, d, base, n - 1);
        for (std::uint32_t i = n - 1; i > 0; --i) set_block_bit(m, d, base, i, block_bit(m, d, base, i - 1));
        set_block_bit(m, d, base, 0, false);
        set_carry(m, out);
    } else {
        const bool out = block_bit(m, d, base, 0);
        for (std::uint32_t i = 0; i + 1 < n; ++i) set_block_bit(m, d, base, i, block_bit(m, d, base, i + 1));
        set_block_bit(m, d, base, n - 1, false);
        set_carry(m, out);
    }
}

// DSFR/DSFL d n: n words move one word; the vacated word is 0.
SLMP_HANDLER(word_shift) {
    SLMP_WHEN_ON;
    const Operand& d = s.op[0];
    const auto [base, n] = counted_block(m, d, s.op[1]);
    if (n == 0) return;
    const auto* w = m.words[static_cast<std::size_t>(d.area)];
    if (s.variant & 1u) {
        for (std::uint32_t i = n - 1; i > 0; --i) store_word(m, d.area, base + i, w[base + i - 1]);
        store_word(m, d.area, base, 0);
    } else {
        for (std::uint32_t i = 0; i + 1 < n; ++i) store_word(m, d.area, base + i, w[base + i + 1]);
        store_word(m, d.area, base + n - 1, 0);
    }
}

// SFTR/SFTL s d n1 n2 (iQ-F): the n1 bits at d shift by n2; the n2 bits at s fill in.
SLMP_HANDLER(fx_bit_shift) {
    SLMP_WHEN_ON;
    const auto n1 = get16(m, s.op[2]), n2 = get16(m, s.op[3]);
    SLMP_FAIL_ON_FAULT;
    if (n1 <= 0 || n2 <= 0) return;
    if (n2 > n1) return m.raise(Cause::Range);
    const Operand& src = s.op[0];
    const Operand& d = s.op[1];
    const auto from = block_start(m, src, static_cast<std::uint32_t>(n2));
    const auto base = block_start(m, d, static_cast<std::uint32_t>(n1));
    SLMP_FAIL_ON_FAULT;
    const auto a = static_cast<std::uint32_t>(n1), b = static_cast<std::uint32_t>(n2);
    m.cost_ps += a * std::uint64_t{m.program->costs.block_ps};
    if (s.variant & 1u) {   // SFTL: toward higher numbers, s fills the bottom
        for (std::uint32_t i = a; i-- > b;) set_block_bit(m, d, base, i, block_bit(m, d, base, i - b));
        for (std::uint32_t j = 0; j < b; ++j) set_block_bit(m, d, base, j, block_bit(m, src, from, j));
    } else {                // SFTR: toward lower numbers, s fills the top
        for (std::uint32_t i = 0; i + b < a; ++i) set_block_bit(m, d, base, i, block_bit(m, d, base, i + b));
        for (std::uint32_t j = 0; j < b; ++j) set_block_bit(m, d, base, a - b + j, block_bit(m, src, from, j));
    }
}

}  // namespace slmp::program::detail
