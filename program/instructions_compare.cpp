// Comparison contacts (docs/program.md "Instructions"): 16-bit, 32-bit,
// float and string, LD/AND/OR. variant = kind | op << 2.
#include <cstring>

#include "program/handlers.hpp"

namespace slmp::program::detail {

namespace {

// Character i of a string operand: a constant, or words holding 2 characters
// each, first in the low byte (docs/program.md "Instructions" $MOV). -1 past the device's end.
int char_at(Machine& m, const Operand& o, std::uint32_t base, std::uint32_t i) {
    if (o.kind == OperandKind::String) {
        const auto& text = m.program->strings[o.value];
        return i < text.size() ? static_cast<unsigned char>(text[i]) : 0;
    }
    const std::uint64_t n = std::uint64_t{base} + i / 2;
    if (n >= m.size[static_cast<std::size_t>(o.area)]) return -1;
    const auto word = m.words[static_cast<std::size_t>(o.area)][n];
    return static_cast<int>((i & 1u) ? (word >> 8) & 0xFFu : word & 0xFFu);
}

// Character code by character code; with an equal prefix the shorter string is smaller (docs/program.md "Instructions").
int compare_strings(Machine& m, const Operand& a, const Operand& b) {
    const auto base_a = a.kind == OperandKind::String ? 0 : effective(m, a, 1);
    const auto base_b = b.kind == OperandKind::String ? 0 : effective(m, b, 1);
    if (m.fault) return 0;
    for (std::uint32_t i = 0;; ++i) {
        const int x = char_at(m, a, base_a, i), y = char_at(m, b, base_b, i);
        if (x < 0 || y < 0) {
            m.fail_device();
            return 0;
        }
        if (x != y) return x < y ? -1 : 1;
        if (x == 0) return 0;
    }
}

template <class T>
int order(T a, T b) { return (a > b) - (a < b); }

// The comparison's result, OFF after an operation error.
bool compare(Machine& m, const Step& s) {
    int c = 0;
    switch (s.variant & 3u) {
        case CmpI16: c = order(get16(m, s.op[0]), get16(m, s.op[1])); break;
        case CmpI32: c = order(get32(m, s.op[0]), get32(m, s.op[1])); break;
        case CmpFloat: {
            const float a = get_float(m, s.op[0]), b = get_float(m, s.op[1]);
            if (!m.fault && (bad_float(a) || bad_float(b))) {
                m.raise(Cause::Float);
                return false;
            }
            c = order(a, b);
            break;
        }
        default: c = compare_strings(m, s.op[0], s.op[1]); break;
    }
    if (m.fault) [[unlikely]] {
        m.raise(m.cause);
        return false;
    }
    switch (s.variant >> 2) {
        case CmpEq: return c == 0;
        case CmpNe: return c != 0;
        case CmpGt: return c > 0;
        case CmpLe: return c <= 0;
        case CmpLt: return c < 0;
        default: return c >= 0;
    }
}

}  // namespace

SLMP_HANDLER(compare_ld) {
    const bool result = compare(m, s);
    m.stack[s.slot] = m.acc;
    m.acc = result;
}
SLMP_HANDLER(compare_and) { m.acc = m.acc & compare(m, s); }
SLMP_HANDLER(compare_or) { m.acc = m.acc | compare(m, s); }

}  // namespace slmp::program::detail
