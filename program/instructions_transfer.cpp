// Transfer (docs/program.md "Instructions"). Blocks are range-checked
// whole before the first word moves and cost `block` per word (docs/program.md "Modelled time").
#include "program/handlers.hpp"

namespace slmp::program::detail {

SLMP_HANDLER(mov16) { transform<1>(m, s, [](std::int32_t v) { return v; }); }
SLMP_HANDLER(mov32) { transform<2>(m, s, [](std::int32_t v) { return v; }); }
SLMP_HANDLER(cml16) { transform<1>(m, s, [](std::int32_t v) { return ~v; }); }
SLMP_HANDLER(cml32) { transform<2>(m, s, [](std::int32_t v) { return ~v; }); }
// Overlapping blocks behave as if copied through a buffer: the direction follows the addresses.
SLMP_HANDLER(bmov) {
    SLMP_WHEN_ON;
    const auto n = get16(m, s.op[2]);
    SLMP_FAIL_ON_FAULT;
    if (n <= 0) return;
    const auto from = block_start(m, s.op[0], static_cast<std::uint64_t>(n));
    const auto to = block_start(m, s.op[1], static_cast<std::uint64_t>(n));
    SLMP_FAIL_ON_FAULT;
    m.cost_ps += static_cast<std::uint64_t>(n) * m.program->costs.block_ps;
    const std::uint32_t* source = m.words[static_cast<std::size_t>(s.op[0].area)] + from;
    const std::uint32_t* target = m.words[static_cast<std::size_t>(s.op[1].area)] + to;
    const auto count = static_cast<std::uint32_t>(n);
    if (target <= source) {
        for (std::uint32_t i = 0; i < count; ++i) store_word(m, s.op[1].area, to + i, source[i] & 0xFFFFu);
    } else {
        for (std::uint32_t i = count; i-- > 0;) store_word(m, s.op[1].area, to + i, source[i] & 0xFFFFu);
    }
}
SLMP_HANDLER(fmov16) {
    SLMP_WHEN_ON;
    const auto v = static_cast<std::uint32_t>(get16(m, s.op[0])) & 0xFFFFu;
    const auto n = get16(m, s.op[2]);
    SLMP_FAIL_ON_FAULT;
    if (n <= 0) return;
    const auto to = block_start(m, s.op[1], static_cast<std::uint64_t>(n));
    SLMP_FAIL_ON_FAULT;
    m.cost_ps += static_cast<std::uint64_t>(n) * m.program->costs.block_ps;
    for (std::uint32_t i = 0; i < static_cast<std::uint32_t>(n); ++i) store_word(m, s.op[1].area, to + i, v);
}
SLMP_HANDLER(fmov32) {
    SLMP_WHEN_ON;
    const auto v = static_cast<std::uint32_t>(get32(m, s.op[0]));
    const auto n = get16(m, s.op[2]);
    SLMP_FAIL_ON_FAULT;
    if (n <= 0) return;
    const auto to = block_start(m, s.op[1], 2 * static_cast<std::uint64_t>(n));
    SLMP_FAIL_ON_FAULT;
    m.cost_ps += 2 * static_cast<std::uint64_t>(n) * m.program->costs.block_ps;
    for (std::uint32_t i = 0; i < static_cast<std::uint32_t>(n); ++i) {
        store_word(m, s.op[1].area, to + 2 * i, v & 0xFFFFu);
        store_word(m, s.op[1].area, to + 2 * i + 1, v >> 16);
    }
}
SLMP_HANDLER(xch16) {
    SLMP_WHEN_ON;
    const auto a = get16(m, s.op[0]), b = get16(m, s.op[1]);
    SLMP_FAIL_ON_FAULT;
    put16(m, s.op[0], b);
    put16(m, s.op[1], a);
}
SLMP_HANDLER(xch32) {
    SLMP_WHEN_ON;
    const auto a = get32(m, s.op[0]), b = get32(m, s.op[1]);
    SLMP_FAIL_ON_FAULT;
    put32(m, s.op[0], b);
    put32(m, s.op[1], a);
}
SLMP_HANDLER(swap) {
    SLMP_WHEN_ON;
    const auto v = static_cast<std::uint32_t>(get16(m, s.op[0])) & 0xFFFFu;
    SLMP_FAIL_ON_FAULT;
    put16(m, s.op[0], static_cast<std::int32_t>(((v & 0xFFu) << 8) | (v >> 8)));
}

// $MOV: a NUL-terminated string, 2 characters a word, first in the low byte;
// the terminating NUL is always written ("ABC" -> 0x4241 0x0043, "AB" -> 0x4241 0x0000).
SLMP_HANDLER(smov) {
    SLMP_WHEN_ON;
    const Operand& source = s.op[0];
    std::uint32_t length = 0;
    std::uint32_t from = 0;
    if (source.kind == OperandKind::String) {
        length = static_cast<std::uint32_t>(m.program->strings[source.value].size());
    } else {
        from = effective(m, source, 1);
        SLMP_FAIL_ON_FAULT;
        const auto size = m.size[static_cast<std::size_t>(source.area)];
        const auto* w = m.words[static_cast<std::size_t>(source.area)];
        for (;; ++length) {
            const auto n = from + length / 2;
            if (n >= size) return m.raise(Cause::Device);
            if (((length & 1u) ? (w[n] >> 8) & 0xFFu : w[n] & 0xFFu) == 0) break;
        }
    }
    const auto words = length / 2 + 1;
    const auto to = block_start(m, s.op[1], words);
    SLMP_FAIL_ON_FAULT;
    auto char_at = [&](std::uint32_t i) -> std::uint32_t {
        if (i >= length) return 0;
        if (source.kind == OperandKind::String) return static_cast<unsigned char>(m.program->strings[source.value][i]);
        const auto w = m.words[static_cast<std::size_t>(source.area)][from + i / 2];
        return (i & 1u) ? (w >> 8) & 0xFFu : w & 0xFFu;
    };
    // Word by word: a source overlapping its destination is not supported (chosen).
    for (std::uint32_t k = 0; k < words; ++k) {
        const auto word = char_at(2 * k) | (char_at(2 * k + 1) << 8);
        store_word(m, s.op[1].area, to + k, word);
    }
}

}  // namespace slmp::program::detail
