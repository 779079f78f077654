// §5.7 logical operations (docs/program.md "Instructions"): variant 0 AND, 1 OR, 2 XOR, 3 XNR.
#include "program/handlers.hpp"

namespace slmp::program::detail {

namespace {
std::uint32_t logic(std::uint8_t variant, std::uint32_t a, std::uint32_t b) {
    switch (variant) {
        case 0: return a & b;
        case 1: return a | b;
        case 2: return a ^ b;
        default: return ~(a ^ b);
    }
}
}  // namespace

SLMP_HANDLER(logic16) {
    SLMP_WHEN_ON;
    const auto a = static_cast<std::uint32_t>(get16(m, s.op[0])), b = static_cast<std::uint32_t>(get16(m, s.op[1]));
    probe(m, s.op[2], 1);
    SLMP_FAIL_ON_FAULT;
    put16(m, s.op[2], static_cast<std::int32_t>(logic(s.variant, a, b) & 0xFFFFu));
}
SLMP_HANDLER(logic32) {
    SLMP_WHEN_ON;
    const auto a = static_cast<std::uint32_t>(get32(m, s.op[0])), b = static_cast<std::uint32_t>(get32(m, s.op[1]));
    probe(m, s.op[2], 2);
    SLMP_FAIL_ON_FAULT;
    put32(m, s.op[2], static_cast<std::int32_t>(logic(s.variant, a, b)));
}

}  // namespace slmp::program::detail
