// Logical operations (docs/program.md "Instructions"): variant 0 AND, 1 OR, 2 XOR, 3 XNR.
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

SLMP_HANDLER(logic16) { combine<1>(m, s, [&s](std::int32_t a, std::int32_t b) {
        return static_cast<std::int32_t>(logic(s.variant, static_cast<std::uint32_t>(a), static_cast<std::uint32_t>(b)) & 0xFFFFu);
    }); }
SLMP_HANDLER(logic32) { combine<2>(m, s, [&s](std::int32_t a, std::int32_t b) {
        return static_cast<std::int32_t>(logic(s.variant, static_cast<std::uint32_t>(a), static_cast<std::uint32_t>(b)));
    }); }

}  // namespace slmp::program::detail
