// Arithmetic (docs/program.md "Instructions"): signed two's complement,
// wrapping silently; ÷0 and bad floats are operation errors (docs/program.md "Operation errors").
// Sources are read and destinations probed before anything is written, so a
// failing instruction writes nothing.
#include <limits>

#include "program/handlers.hpp"

namespace slmp::program::detail {

namespace {
std::int32_t wrap16(std::int32_t v) { return static_cast<std::int16_t>(static_cast<std::uint16_t>(v)); }
std::int32_t add32w(std::int32_t a, std::int32_t b) {
    return static_cast<std::int32_t>(static_cast<std::uint32_t>(a) + static_cast<std::uint32_t>(b));
}
std::int32_t sub32w(std::int32_t a, std::int32_t b) {
    return static_cast<std::int32_t>(static_cast<std::uint32_t>(a) - static_cast<std::uint32_t>(b));
}
}  // namespace

SLMP_HANDLER(add16) { combine<1>(m, s, [](std::int32_t a, std::int32_t b) { return wrap16(a + b); }); }
SLMP_HANDLER(sub16) { combine<1>(m, s, [](std::int32_t a, std::int32_t b) { return wrap16(a - b); }); }
// 16 x 16 -> 32 bits in d, d+1.
SLMP_HANDLER(mul16) {
    SLMP_WHEN_ON;
    const auto a = get16(m, s.op[0]), b = get16(m, s.op[1]);
    probe(m, s.op[2], 2);
    SLMP_FAIL_ON_FAULT;
    put32(m, s.op[2], a * b);
}
// Quotient toward 0 in d, remainder with the dividend's sign in d+1; a
// digit-designated d gets the quotient only ([FX3]).
SLMP_HANDLER(div16) {
    SLMP_WHEN_ON;
    const auto a = get16(m, s.op[0]), b = get16(m, s.op[1]);
    probe(m, s.op[2], 2);
    SLMP_FAIL_ON_FAULT;
    if (b == 0) return m.raise(Cause::DivideByZero);
    const std::int32_t quotient = wrap16(a / b), remainder = a % b;   // -32768 / -1 wraps to -32768
    put16(m, s.op[2], quotient);
    if (s.op[2].kind == OperandKind::Word) put16(m, next_word(s.op[2], 1), remainder);
}
SLMP_HANDLER(add32) { combine<2>(m, s, add32w); }
SLMP_HANDLER(sub32) { combine<2>(m, s, sub32w); }
// 32 x 32 -> 64 bits in d..d+3, low word first (a digit-designated d gets the low 32 bits).
SLMP_HANDLER(mul32) {
    SLMP_WHEN_ON;
    const std::int64_t a = get32(m, s.op[0]), b = get32(m, s.op[1]);
    probe(m, s.op[2], 4);
    SLMP_FAIL_ON_FAULT;
    const auto product = static_cast<std::uint64_t>(a * b);
    put32(m, s.op[2], static_cast<std::int32_t>(product));
    if (s.op[2].kind == OperandKind::Word) put32(m, next_word(s.op[2], 2), static_cast<std::int32_t>(product >> 32));
}
// Quotient in d, d+1 and remainder in d+2, d+3 ([FX3] DDIV layout).
SLMP_HANDLER(div32) {
    SLMP_WHEN_ON;
    const std::int64_t a = get32(m, s.op[0]), b = get32(m, s.op[1]);
    probe(m, s.op[2], 4);
    SLMP_FAIL_ON_FAULT;
    if (b == 0) return m.raise(Cause::DivideByZero);
    put32(m, s.op[2], static_cast<std::int32_t>(static_cast<std::uint32_t>(a / b)));
    if (s.op[2].kind == OperandKind::Word) put32(m, next_word(s.op[2], 2), static_cast<std::int32_t>(a % b));
}
SLMP_HANDLER(inc16) {
    SLMP_WHEN_ON;
    const auto v = get16(m, s.op[0]);
    SLMP_FAIL_ON_FAULT;
    put16(m, s.op[0], wrap16(v + 1));
}
SLMP_HANDLER(dec16) {
    SLMP_WHEN_ON;
    const auto v = get16(m, s.op[0]);
    SLMP_FAIL_ON_FAULT;
    put16(m, s.op[0], wrap16(v - 1));
}
SLMP_HANDLER(inc32) {
    SLMP_WHEN_ON;
    const auto v = get32(m, s.op[0]);
    SLMP_FAIL_ON_FAULT;
    put32(m, s.op[0], add32w(v, 1));
}
SLMP_HANDLER(dec32) {
    SLMP_WHEN_ON;
    const auto v = get32(m, s.op[0]);
    SLMP_FAIL_ON_FAULT;
    put32(m, s.op[0], sub32w(v, 1));
}
// Two's complement; -32768 stays -32768.
SLMP_HANDLER(neg16) {
    SLMP_WHEN_ON;
    const auto v = get16(m, s.op[0]);
    SLMP_FAIL_ON_FAULT;
    put16(m, s.op[0], wrap16(-v));
}
SLMP_HANDLER(neg32) {
    SLMP_WHEN_ON;
    const auto v = get32(m, s.op[0]);
    SLMP_FAIL_ON_FAULT;
    put32(m, s.op[0], sub32w(0, v));
}

namespace {
template <class Op>
void float_op(Machine& m, const Step& s, Op op, bool divide) {
    if (!m.condition()) return;
    const float a = get_float(m, s.op[0]), b = get_float(m, s.op[1]);
    probe(m, s.op[2], 2);
    SLMP_FAIL_ON_FAULT;
    if (bad_float(a) || bad_float(b)) return m.raise(Cause::Float);
    if (divide && b == 0.0f) return m.raise(Cause::DivideByZero);
    const float r = op(a, b);
    if (!std::isfinite(r)) return m.raise(Cause::Float);
    put_float(m, s.op[2], r);
}
}  // namespace

SLMP_HANDLER(fadd) { float_op(m, s, [](float a, float b) { return a + b; }, false); }
SLMP_HANDLER(fsub) { float_op(m, s, [](float a, float b) { return a - b; }, false); }
SLMP_HANDLER(fmul) { float_op(m, s, [](float a, float b) { return a * b; }, false); }
SLMP_HANDLER(fdiv) { float_op(m, s, [](float a, float b) { return a / b; }, true); }
SLMP_HANDLER(fneg) {
    SLMP_WHEN_ON;
    const float v = get_float(m, s.op[0]);
    SLMP_FAIL_ON_FAULT;
    if (bad_float(v)) return m.raise(Cause::Float);
    put_float(m, s.op[0], -v);
}

}  // namespace slmp::program::detail
