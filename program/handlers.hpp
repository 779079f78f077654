// Every instruction handler, by group (one instructions_*.cpp per docs/program.md "Instructions"
// table). Application handlers test the operation result themselves
// (`if (!m.condition()) return;`) so a step costs one indirect call; their P
// forms run through `pulse`, which tests the edge and then calls the body.
#pragma once

#include <bit>
#include <cmath>

#include "program/engine.hpp"

namespace slmp::program::detail {

#define SLMP_HANDLER(name) void name(Machine& m, const Step& s)
// An application instruction does nothing while r is OFF (docs/program.md "Instructions").
#define SLMP_WHEN_ON \
    if (!m.condition()) return
// An operand that could not be resolved (index past the end): the error, nothing written.
#define SLMP_FAIL_ON_FAULT \
    if (m.fault) [[unlikely]] return m.raise(m.cause)

// The two shapes most application instructions share, for 16 bits (1 word) or
// 32 (2 words): sources read, destination checked, then written — so a
// failing operand writes nothing. `s d`: d = f(s); `s1 s2 d`: d = f(s1, s2).
template <unsigned Words>
inline std::int32_t get_wide(Machine& m, const Operand& o) {
    return Words == 1 ? get16(m, o) : get32(m, o);
}
template <unsigned Words>
inline void put_wide(Machine& m, const Operand& o, std::int32_t v) {
    if constexpr (Words == 1) put16(m, o, v); else put32(m, o, v);
}
template <unsigned Words, class F>
inline void transform(Machine& m, const Step& s, F f) {
    SLMP_WHEN_ON;
    const auto v = get_wide<Words>(m, s.op[0]);
    probe(m, s.op[1], Words);
    SLMP_FAIL_ON_FAULT;
    put_wide<Words>(m, s.op[1], f(v));
}
template <unsigned Words, class F>
inline void combine(Machine& m, const Step& s, F f) {
    SLMP_WHEN_ON;
    const auto a = get_wide<Words>(m, s.op[0]), b = get_wide<Words>(m, s.op[1]);
    probe(m, s.op[2], Words);
    SLMP_FAIL_ON_FAULT;
    put_wide<Words>(m, s.op[2], f(a, b));
}

// P form (docs/program.md "Instructions", "The scan"): the body runs when r went OFF->ON since this step last ran.
SLMP_HANDLER(pulse);

// Sequence (instructions_sequence.cpp)
SLMP_HANDLER(ld); SLMP_HANDLER(ldi); SLMP_HANDLER(and_); SLMP_HANDLER(ani); SLMP_HANDLER(or_); SLMP_HANDLER(ori);
SLMP_HANDLER(ldp); SLMP_HANDLER(ldf); SLMP_HANDLER(andp); SLMP_HANDLER(andf); SLMP_HANDLER(orp); SLMP_HANDLER(orf);
SLMP_HANDLER(ldpi); SLMP_HANDLER(ldfi); SLMP_HANDLER(andpi); SLMP_HANDLER(andfi); SLMP_HANDLER(orpi); SLMP_HANDLER(orfi);
SLMP_HANDLER(anb); SLMP_HANDLER(orb); SLMP_HANDLER(mps); SLMP_HANDLER(mrd); SLMP_HANDLER(mpp);
SLMP_HANDLER(inv); SLMP_HANDLER(mep); SLMP_HANDLER(mef);
SLMP_HANDLER(out_bit); SLMP_HANDLER(set_bit); SLMP_HANDLER(rst_bit); SLMP_HANDLER(rst_word);
SLMP_HANDLER(pls); SLMP_HANDLER(plf); SLMP_HANDLER(ff);
SLMP_HANDLER(mc); SLMP_HANDLER(mcr); SLMP_HANDLER(nop); SLMP_HANDLER(end); SLMP_HANDLER(fend);

// Timers and counters (instructions_timers.cpp)
SLMP_HANDLER(out_timer); SLMP_HANDLER(out_counter); SLMP_HANDLER(rst_timer_counter);

// Comparison contacts (instructions_compare.cpp): variant = kind | op << 2 | combine << 5
SLMP_HANDLER(compare_ld); SLMP_HANDLER(compare_and); SLMP_HANDLER(compare_or);
enum CompareKind : std::uint8_t { CmpI16 = 0, CmpI32 = 1, CmpFloat = 2, CmpString = 3 };
enum CompareOp : std::uint8_t { CmpEq = 0, CmpNe, CmpGt, CmpLe, CmpLt, CmpGe };

// Arithmetic (instructions_arithmetic.cpp)
SLMP_HANDLER(add16); SLMP_HANDLER(sub16); SLMP_HANDLER(mul16); SLMP_HANDLER(div16);
SLMP_HANDLER(add32); SLMP_HANDLER(sub32); SLMP_HANDLER(mul32); SLMP_HANDLER(div32);
SLMP_HANDLER(inc16); SLMP_HANDLER(dec16); SLMP_HANDLER(inc32); SLMP_HANDLER(dec32);
SLMP_HANDLER(neg16); SLMP_HANDLER(neg32);
SLMP_HANDLER(fadd); SLMP_HANDLER(fsub); SLMP_HANDLER(fmul); SLMP_HANDLER(fdiv); SLMP_HANDLER(fneg);

// Conversion (instructions_conversion.cpp)
SLMP_HANDLER(bcd16); SLMP_HANDLER(bcd32); SLMP_HANDLER(bin16); SLMP_HANDLER(bin32);
SLMP_HANDLER(flt16); SLMP_HANDLER(flt32); SLMP_HANDLER(int16); SLMP_HANDLER(int32);

// Transfer (instructions_transfer.cpp)
SLMP_HANDLER(mov16); SLMP_HANDLER(mov32); SLMP_HANDLER(cml16); SLMP_HANDLER(cml32);
SLMP_HANDLER(bmov); SLMP_HANDLER(fmov16); SLMP_HANDLER(fmov32); SLMP_HANDLER(xch16); SLMP_HANDLER(xch32);
SLMP_HANDLER(swap); SLMP_HANDLER(smov);

// Logic (instructions_logic.cpp): variant 0 AND, 1 OR, 2 XOR, 3 XNR
SLMP_HANDLER(logic16); SLMP_HANDLER(logic32);

// Rotation and shift (instructions_shift.cpp): variant = direction/carry form
SLMP_HANDLER(rotate16); SLMP_HANDLER(rotate32); SLMP_HANDLER(shift_word); SLMP_HANDLER(sft);
SLMP_HANDLER(bit_shift); SLMP_HANDLER(word_shift); SLMP_HANDLER(fx_bit_shift);

// Bit and data processing (instructions_data.cpp)
SLMP_HANDLER(bset); SLMP_HANDLER(brst); SLMP_HANDLER(test16); SLMP_HANDLER(test32); SLMP_HANDLER(bkrst);
SLMP_HANDLER(zrst); SLMP_HANDLER(sum16); SLMP_HANDLER(sum32); SLMP_HANDLER(deco); SLMP_HANDLER(enco);
SLMP_HANDLER(seg);

// Program control (instructions_control.cpp)
SLMP_HANDLER(cj); SLMP_HANDLER(scj); SLMP_HANDLER(jmp); SLMP_HANDLER(goend); SLMP_HANDLER(call);
SLMP_HANDLER(ret); SLMP_HANDLER(for_); SLMP_HANDLER(next); SLMP_HANDLER(break_); SLMP_HANDLER(wdt);
SLMP_HANDLER(stop);

// The fast form of `general` for this step's operands, or `general` (fast_paths.cpp).
Handler specialised(Handler general, const Step& step);

// Floats (docs/program.md "Operation errors" float): -0, denormals, NaN and infinities are refused as operands.
inline bool bad_float(float f) {
    const int c = std::fpclassify(f);
    return c == FP_NAN || c == FP_INFINITE || c == FP_SUBNORMAL || (c == FP_ZERO && std::signbit(f));
}
inline float get_float(Machine& m, const Operand& o) { return std::bit_cast<float>(get32(m, o)); }
inline void put_float(Machine& m, const Operand& o, float f) {
    if (f == 0.0f) f = 0.0f;   // a -0 result is stored as +0 (a -0 operand is an error)
    put32(m, o, std::bit_cast<std::int32_t>(f));
}

// The operand k words further on (d+1 of a quotient/remainder pair).
inline Operand next_word(const Operand& o, std::uint32_t k) {
    Operand n = o;
    n.number += k;
    return n;
}

// Bit i of a block starting at a bit device or a word device (16 bits a word).
inline bool block_bit(Machine& m, const Operand& o, std::uint32_t base, std::uint32_t i) {
    if (o.kind == OperandKind::Word) return (m.words[static_cast<std::size_t>(o.area)][base + i / 16] >> (i % 16)) & 1u;
    return m.bytes[static_cast<std::size_t>(o.plane)][static_cast<std::size_t>(o.area)][base + i] != 0;
}
inline void set_block_bit(Machine& m, const Operand& o, std::uint32_t base, std::uint32_t i, bool on) {
    if (o.kind == OperandKind::Word) {
        const auto n = base + i / 16;
        const auto word = m.words[static_cast<std::size_t>(o.area)][n];
        const auto mask = 1u << (i % 16);
        return store_word(m, o.area, n, on ? (word | mask) : (word & ~mask));
    }
    store_byte(m, o.plane, o.area, base + i, on);
}
// Start of a block of `count` devices (bits, or words when o is a word device);
// sets the device fault when the block runs past the area's end.
inline std::uint32_t block_start(Machine& m, const Operand& o, std::uint64_t count) {
    const auto base = effective(m, o, 1);
    if (m.fault) return 0;
    if (base + count > m.size[static_cast<std::size_t>(o.area)]) m.fail_device();
    return base;
}

// `d n` block instructions (BKRST, BSFR/BSFL, DSFR/DSFL): n devices from d,
// range-checked whole and charged `block` a device before any moves. A count
// of 0 means nothing to do: n <= 0, or an operation error was raised.
struct Block {
    std::uint32_t base = 0, count = 0;
};
inline Block counted_block(Machine& m, const Operand& d, const Operand& n) {
    const auto count = get16(m, n);
    if (m.fault) [[unlikely]] return m.raise(m.cause), Block{};
    if (count <= 0) return {};
    const auto points = static_cast<std::uint32_t>(count);
    const auto base = block_start(m, d, points);
    if (m.fault) [[unlikely]] return m.raise(m.cause), Block{};
    m.cost_ps += points * std::uint64_t{m.program->costs.block_ps};
    return {base, points};
}

}  // namespace slmp::program::detail
