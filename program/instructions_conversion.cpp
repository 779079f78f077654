// Conversion (docs/program.md "Instructions").
#include <limits>

#include "program/handlers.hpp"

namespace slmp::program::detail {

namespace {
std::uint32_t to_bcd(std::uint32_t v) {
    std::uint32_t r = 0;
    for (unsigned shift = 0; v != 0; shift += 4, v /= 10) r |= (v % 10) << shift;
    return r;
}
// -1 when a nibble is above 9.
std::int64_t from_bcd(std::uint32_t v, unsigned nibbles) {
    std::int64_t r = 0;
    for (int i = static_cast<int>(nibbles) - 1; i >= 0; --i) {
        const auto digit = (v >> (i * 4)) & 0xFu;
        if (digit > 9) return -1;
        r = r * 10 + digit;
    }
    return r;
}
// Half away from zero on Q/L and iQ-R (docs/program.md "Instructions", inferred; used for iQ-F too).
double rounded(float f) { return std::round(static_cast<double>(f)); }
}  // namespace

SLMP_HANDLER(bcd16) {
    SLMP_WHEN_ON;
    const auto v = get16(m, s.op[0]);
    probe(m, s.op[1], 1);
    SLMP_FAIL_ON_FAULT;
    if (v < 0 || v > 9999) return m.raise(Cause::Range);
    put16(m, s.op[1], static_cast<std::int32_t>(to_bcd(static_cast<std::uint32_t>(v))));
}
SLMP_HANDLER(bcd32) {
    SLMP_WHEN_ON;
    const auto v = get32(m, s.op[0]);
    probe(m, s.op[1], 2);
    SLMP_FAIL_ON_FAULT;
    if (v < 0 || v > 99999999) return m.raise(Cause::Range);
    put32(m, s.op[1], static_cast<std::int32_t>(to_bcd(static_cast<std::uint32_t>(v))));
}
SLMP_HANDLER(bin16) {
    SLMP_WHEN_ON;
    const auto v = static_cast<std::uint32_t>(get16(m, s.op[0])) & 0xFFFFu;
    probe(m, s.op[1], 1);
    SLMP_FAIL_ON_FAULT;
    const auto r = from_bcd(v, 4);
    if (r < 0) return m.raise(Cause::Range);
    put16(m, s.op[1], static_cast<std::int32_t>(r));
}
SLMP_HANDLER(bin32) {
    SLMP_WHEN_ON;
    const auto v = static_cast<std::uint32_t>(get32(m, s.op[0]));
    probe(m, s.op[1], 2);
    SLMP_FAIL_ON_FAULT;
    const auto r = from_bcd(v, 8);
    if (r < 0) return m.raise(Cause::Range);
    put32(m, s.op[1], static_cast<std::int32_t>(r));
}
SLMP_HANDLER(flt16) {
    SLMP_WHEN_ON;
    const auto v = get16(m, s.op[0]);
    probe(m, s.op[1], 2);
    SLMP_FAIL_ON_FAULT;
    put_float(m, s.op[1], static_cast<float>(v));
}
SLMP_HANDLER(flt32) {
    SLMP_WHEN_ON;
    const auto v = get32(m, s.op[0]);
    probe(m, s.op[1], 2);
    SLMP_FAIL_ON_FAULT;
    put_float(m, s.op[1], static_cast<float>(v));
}
SLMP_HANDLER(int16) {
    SLMP_WHEN_ON;
    const float f = get_float(m, s.op[0]);
    probe(m, s.op[1], 1);
    SLMP_FAIL_ON_FAULT;
    if (bad_float(f)) return m.raise(Cause::Float);
    const double r = rounded(f);
    if (r < -32768.0 || r > 32767.0) return m.raise(Cause::Range);
    put16(m, s.op[1], static_cast<std::int32_t>(r));
}
SLMP_HANDLER(int32) {
    SLMP_WHEN_ON;
    const float f = get_float(m, s.op[0]);
    probe(m, s.op[1], 2);
    SLMP_FAIL_ON_FAULT;
    if (bad_float(f)) return m.raise(Cause::Float);
    const double r = rounded(f);
    if (r < -2147483648.0 || r > 2147483647.0) return m.raise(Cause::Range);
    put32(m, s.op[1], static_cast<std::int32_t>(r));
}

}  // namespace slmp::program::detail
