// Specialised handlers for the commonest steps with plain operands (no index,
// no digit designation): contacts and OUT of a bit, MOV/+/- of words and
// constants, 16-bit compare contacts. Same semantics as the general handlers
// of the group files, minus the operand-kind dispatch; the compiler picks one
// through specialised() after resolving the operands (docs/program.md
// "Performance": ≤ 3 ns per executed instruction).
#include "program/handlers.hpp"

namespace slmp::program::detail {

namespace {

inline bool plain_bit(const Operand& o) { return o.kind == OperandKind::Bit && o.index == kNoIndex; }
inline bool plain_word(const Operand& o) { return o.kind == OperandKind::Word && o.index == kNoIndex; }
inline bool plain_source(const Operand& o) {
    return (o.kind == OperandKind::Word || o.kind == OperandKind::Constant) && o.index == kNoIndex;
}
inline bool bit_at(const Machine& m, const Operand& o) {
    return m.bytes[static_cast<std::size_t>(o.plane)][static_cast<std::size_t>(o.area)][o.number] != 0;
}
inline std::int32_t word_or_constant(const Machine& m, const Operand& o) {
    return o.kind == OperandKind::Constant ? static_cast<std::int16_t>(o.value)
                                           : static_cast<std::int16_t>(m.words[static_cast<std::size_t>(o.area)][o.number]);
}

SLMP_HANDLER(ld_plain) {
    m.stack[s.slot] = m.acc;
    m.acc = bit_at(m, s.op[0]);
}
SLMP_HANDLER(ldi_plain) {
    m.stack[s.slot] = m.acc;
    m.acc = !bit_at(m, s.op[0]);
}
SLMP_HANDLER(and_plain) { m.acc = m.acc & bit_at(m, s.op[0]); }
SLMP_HANDLER(ani_plain) { m.acc = m.acc & !bit_at(m, s.op[0]); }
SLMP_HANDLER(or_plain) { m.acc = m.acc | bit_at(m, s.op[0]); }
SLMP_HANDLER(ori_plain) { m.acc = m.acc | !bit_at(m, s.op[0]); }
SLMP_HANDLER(out_plain) { store_byte(m, s.op[0].plane, s.op[0].area, s.op[0].number, m.condition()); }
SLMP_HANDLER(set_plain) {
    if (m.condition()) store_byte(m, s.op[0].plane, s.op[0].area, s.op[0].number, true);
}
SLMP_HANDLER(rst_plain) {
    if (m.condition()) store_byte(m, s.op[0].plane, s.op[0].area, s.op[0].number, false);
}
SLMP_HANDLER(mov_plain) {
    SLMP_WHEN_ON;
    store_word(m, s.op[1].area, s.op[1].number, static_cast<std::uint32_t>(word_or_constant(m, s.op[0])) & 0xFFFFu);
}
SLMP_HANDLER(add_plain) {
    SLMP_WHEN_ON;
    const auto v = word_or_constant(m, s.op[0]) + word_or_constant(m, s.op[1]);
    store_word(m, s.op[2].area, s.op[2].number, static_cast<std::uint32_t>(v) & 0xFFFFu);
}
SLMP_HANDLER(sub_plain) {
    SLMP_WHEN_ON;
    const auto v = word_or_constant(m, s.op[0]) - word_or_constant(m, s.op[1]);
    store_word(m, s.op[2].area, s.op[2].number, static_cast<std::uint32_t>(v) & 0xFFFFu);
}

template <CompareOp Op>
inline bool compare_plain(const Machine& m, const Step& s) {
    const auto a = word_or_constant(m, s.op[0]), b = word_or_constant(m, s.op[1]);
    if constexpr (Op == CmpEq) return a == b;
    if constexpr (Op == CmpNe) return a != b;
    if constexpr (Op == CmpGt) return a > b;
    if constexpr (Op == CmpLe) return a <= b;
    if constexpr (Op == CmpLt) return a < b;
    return a >= b;
}
template <CompareOp Op>
void compare_ld_plain(Machine& m, const Step& s) {
    const bool r = compare_plain<Op>(m, s);
    m.stack[s.slot] = m.acc;
    m.acc = r;
}
template <CompareOp Op>
void compare_and_plain(Machine& m, const Step& s) { m.acc = m.acc & compare_plain<Op>(m, s); }
template <CompareOp Op>
void compare_or_plain(Machine& m, const Step& s) { m.acc = m.acc | compare_plain<Op>(m, s); }

constexpr std::array<Handler, 6> kLd{compare_ld_plain<CmpEq>, compare_ld_plain<CmpNe>, compare_ld_plain<CmpGt>,
                                     compare_ld_plain<CmpLe>, compare_ld_plain<CmpLt>, compare_ld_plain<CmpGe>};
constexpr std::array<Handler, 6> kAnd{compare_and_plain<CmpEq>, compare_and_plain<CmpNe>, compare_and_plain<CmpGt>,
                                      compare_and_plain<CmpLe>, compare_and_plain<CmpLt>, compare_and_plain<CmpGe>};
constexpr std::array<Handler, 6> kOr{compare_or_plain<CmpEq>, compare_or_plain<CmpNe>, compare_or_plain<CmpGt>,
                                     compare_or_plain<CmpLe>, compare_or_plain<CmpLt>, compare_or_plain<CmpGe>};

}  // namespace

Handler specialised(Handler general, const Step& s) {
    const auto& a = s.op[0];
    const auto& b = s.op[1];
    if (plain_bit(a)) {
        if (general == ld) return ld_plain;
        if (general == ldi) return ldi_plain;
        if (general == and_) return and_plain;
        if (general == ani) return ani_plain;
        if (general == or_) return or_plain;
        if (general == ori) return ori_plain;
        if (general == out_bit) return out_plain;
        if (general == set_bit) return set_plain;
        if (general == rst_bit) return rst_plain;
    }
    if (general == mov16 && plain_source(a) && plain_word(b)) return mov_plain;
    if ((general == add16 || general == sub16) && plain_source(a) && plain_source(b) && plain_word(s.op[2]))
        return general == add16 ? add_plain : sub_plain;
    if ((general == compare_ld || general == compare_and || general == compare_or) && (s.variant & 3u) == CmpI16 &&
        plain_source(a) && plain_source(b)) {
        const auto op = static_cast<std::size_t>(s.variant >> 2);
        return general == compare_ld ? kLd[op] : general == compare_and ? kAnd[op] : kOr[op];
    }
    return general;
}

}  // namespace slmp::program::detail
