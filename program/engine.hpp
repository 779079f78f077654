// The engine's inner types, shared by the compiler (compile.cpp), the
// instruction table and handlers (instructions_*.cpp) and the scan loop
// (execution.cpp). Not part of the public interface (docs/program.md "Engine").
//
// Interpreter design (docs/program.md "Engine"): direct threading through a
// function pointer per step. compile() turns every instruction into a Step
// holding its handler and its operands resolved to (area, plane, number) plus
// digit count, bit, index register and constants; the scan loop is
//     step = steps[pc++]; cost += step.cost; step.run(machine, step); check
// A computed-goto loop would save the indirect call but forces every handler
// into one function; per-group handler files, shared by the table, are worth
// more than the last nanosecond (the target is 3 ns per instruction).
// Memory is reached through plane base pointers fetched once per scan, so a
// restored or replaced DeviceMemory is always seen.
#pragma once

#include <array>
#include <optional>
#include <cstdint>
#include <string>
#include <string_view>
#include <vector>

#include "devicemodel/device_memory.hpp"
#include "program/program.hpp"

namespace slmp::program::detail {

using devicemodel::Area;
constexpr std::size_t kAreas = static_cast<std::size_t>(Area::Count);

// Cost classes of docs/program.md "Modelled time".
enum class Cost : std::uint8_t { Basic, Move, Arith, Float, Block, Label };

// Families an instruction exists in (docs/program.md "Instructions").
enum FamilyBits : std::uint8_t { QL = 1, IQR = 2, IQF = 4, ALL = QL | IQR | IQF };
std::uint8_t family_bit(devicemodel::Family family);
std::string_view family_name(devicemodel::Family family);

// Causes of operation errors (docs/program.md "Operation errors"); codes per family in error_code().
enum class Cause : std::uint8_t {
    None, DivideByZero, Range, Device, Float, CallNest, ReturnWithoutCall, ForNest, NextWithoutFor,
    BreakWithoutFor, Watchdog
};
std::uint16_t error_code(devicemodel::Family family, Cause cause);
std::string_view cause_text(Cause cause);

enum class OperandKind : std::uint8_t {
    None,
    Bit,        // one bit of a bit plane (bits or coils)
    Word,       // a 16-bit word device (32-bit instructions: this one and the next)
    Wide,       // a device holding 32 bits itself: LZ, LT/LST/LC current values
    BitOfWord,  // D0.F
    Digits,     // K4M0: `digits` x 4 bits of a bit plane
    Constant,   // K/H/E: `value` (two's complement, float bits for E)
    String,     // "text": `value` indexes Program::strings
    Pointer,    // P10: `value` is the step index to continue at
    Nesting,    // N0: `value` is the level
    // A global label in the label area (no device; devicemodel/labels.hpp):
    // reached through DeviceMemory's label words, which tell the observer themselves.
    LabelBit,   // `number` is the bit: word x 16 + bit
    LabelWord,  // `number` is the first word (32-bit operands: this one and the next)
};
enum class Plane : std::uint8_t { Bits = 0, Coils = 1, Values = 2 };

constexpr std::uint8_t kNoIndex = 0xFF;

struct Operand {
    OperandKind kind = OperandKind::None;
    Area area = Area::D;
    Plane plane = Plane::Bits;
    std::uint8_t digits = 0;      // Digits: n of Kn
    std::uint8_t bit = 0;         // BitOfWord: 0-15
    std::uint8_t index = kNoIndex;// Z or LZ register number
    bool index_long = false;      // LZ instead of Z
    // A device operand has a number, the others a value, never both: one word
    // keeps a step's four operands in 48 bytes.
    union {
        std::uint32_t number = 0; // device number
        std::uint32_t value;      // Constant / String / Pointer / Nesting
    };
};
static_assert(sizeof(Operand) == 12);

struct Machine;
struct Step;
using Handler = void (*)(Machine&, const Step&);

struct Step {
    Handler run = nullptr;
    Handler body = nullptr;       // the instruction itself, for the P-form and condition wrappers
    std::uint32_t cost_ps = 0;    // modelled cost in picoseconds (docs/program.md "Modelled time")
    std::uint32_t edge = 0;       // edge-memory slot (docs/program.md "The scan") or timer slot
    std::uint32_t aux = 0;        // handler-specific: timer base in µs, jump target ...
    std::uint16_t slot = 0;       // static result-stack / branch-stack slot
    std::uint8_t operand_count = 0;
    std::uint8_t variant = 0;     // handler-specific (time base, 16/32 bit ...)
    std::array<Operand, 4> op{};
};

// A timer the program drives with OUT: the engine's accumulator follows its coil.
struct TimerSlot {
    Area area = Area::T;
    std::uint32_t number = 0;
};

struct Costs {
    std::uint32_t basic_ps, move_ps, arith_ps, float_ps, block_ps;
    std::uint64_t end_ps;
};
Costs costs_for(devicemodel::Family family);

}  // namespace slmp::program::detail

namespace slmp::program {

class Program {
public:
    Source source;
    devicemodel::CpuProfile profile;
    ProgramOptions options;
    std::vector<detail::Step> steps;
    std::vector<CompiledStep> info;
    std::vector<std::string> strings;            // string constants
    std::vector<detail::TimerSlot> timers;
    std::uint32_t edge_count = 0;
    detail::Costs costs{};
    std::size_t end_step = 0;                    // index of END (GOEND goes there)
    // Device specs by plane and area, for the observer (TS/TC/TN for T ...).
    std::array<std::array<const devicemodel::DeviceSpec*, detail::kAreas>, 3> specs{};
};

}  // namespace slmp::program

namespace slmp::program::detail {

// The interpreter's state within one scan (docs/program.md "Engine").
struct Machine {
    std::array<std::array<std::uint8_t*, kAreas>, 2> bytes{};   // [Bits/Coils][area]
    std::array<std::uint32_t*, kAreas> words{};
    std::array<std::uint32_t, kAreas> size{};
    devicemodel::DeviceMemory* memory = nullptr;
    bool observed = false;
    const Program* program = nullptr;
    const Step* steps = nullptr;

    bool acc = false;         // the operation result r
    bool mc_off = false;      // inside an MC block that is OFF
    bool fault = false;       // an operand could not be resolved (index past the end)
    bool stop_requested = false;
    std::uint16_t mc_mask = 0;
    std::array<std::uint8_t, 64> stack{};
    std::array<std::uint8_t, 16> branch{};
    std::array<std::uint32_t, 16> calls{};
    std::uint8_t call_depth = 0;
    struct Loop { std::uint32_t start; std::int32_t remaining; };
    std::array<Loop, 16> loops{};
    std::uint8_t loop_depth = 0;

    std::uint32_t pc = 0;
    std::uint64_t cost_ps = 0;
    std::uint64_t limit_ps = 0;
    std::uint64_t wdt_ps = 0;
    std::uint64_t executed = 0;
    std::uint64_t max_steps = 0;
    enum class Halt : std::uint8_t { Running, End, StopError, Watchdog } halt = Halt::Running;

    std::uint8_t* edges = nullptr;
    std::uint64_t* timer_accumulators = nullptr;   // µs
    std::uint8_t* timer_coils = nullptr;
    std::optional<ScanOutcome::Error> error;
    Cause cause = Cause::None;

    bool condition() const { return acc & !mc_off; }
    // Ends the loop: the scan loop's one check (cost > limit | executed > max) fires.
    void halt_now(Halt why) { halt = why; limit_ps = 0; max_steps = 0; }
    std::uint64_t wdt_limit() const { return limit_ps; }
    // An operation error at the step being executed (docs/program.md "Operation errors").
    void raise(Cause why);
    void fail_device() { fault = true; cause = Cause::Device; }
    std::uint32_t m_size(Area area) const { return size[static_cast<std::size_t>(area)]; }
};

// ---- operand access (inline: every handler uses them) ----

inline std::uint32_t effective(Machine& m, const Operand& o, std::uint32_t span) {
    if (o.index == kNoIndex) [[likely]] return o.number;
    const std::int64_t offset = o.index_long ? static_cast<std::int32_t>(m.words[static_cast<std::size_t>(Area::LZ)][o.index])
                                             : static_cast<std::int16_t>(m.words[static_cast<std::size_t>(Area::Z)][o.index]);
    const std::int64_t n = static_cast<std::int64_t>(o.number) + offset;
    if (n < 0 || n + span > m.size[static_cast<std::size_t>(o.area)]) {
        m.fail_device();
        return 0;
    }
    return static_cast<std::uint32_t>(n);
}

inline std::uint32_t span_of(const Operand& o, std::uint32_t words) {
    switch (o.kind) {
        case OperandKind::Digits: return o.digits * 4u;
        case OperandKind::Word: return words;
        default: return 1;
    }
}

inline void notify(Machine& m, Plane plane, Area area, std::uint32_t number) {
    m.memory->notify(*m.program->specs[static_cast<std::size_t>(plane)][static_cast<std::size_t>(area)], number, 1);
}

inline void store_byte(Machine& m, Plane plane, Area area, std::uint32_t n, bool on) {
    auto& cell = m.bytes[static_cast<std::size_t>(plane)][static_cast<std::size_t>(area)][n];
    const std::uint8_t now = on ? 1 : 0;
    if (cell == now) return;
    cell = now;
    if (m.observed) [[unlikely]] notify(m, plane, area, n);
}

inline void store_word(Machine& m, Area area, std::uint32_t n, std::uint32_t value) {
    auto& cell = m.words[static_cast<std::size_t>(area)][n];
    if (cell == value) return;
    cell = value;
    if (m.observed) [[unlikely]] notify(m, Plane::Values, area, n);
}

inline bool read_label_bit(const Machine& m, std::uint32_t bit) { return (m.memory->label_word(bit / 16) >> (bit % 16)) & 1u; }
inline void write_label_bit(Machine& m, std::uint32_t bit, bool on) {
    const auto word = m.memory->label_word(bit / 16);
    const auto mask = static_cast<std::uint16_t>(1u << (bit % 16));
    m.memory->set_label_word(bit / 16, static_cast<std::uint16_t>(on ? (word | mask) : (word & ~mask)));
}

inline bool read_bit(Machine& m, const Operand& o) {
    if (o.kind == OperandKind::Bit) [[likely]] {
        const auto n = effective(m, o, 1);
        return m.bytes[static_cast<std::size_t>(o.plane)][static_cast<std::size_t>(o.area)][n] != 0;
    }
    if (o.kind == OperandKind::LabelBit) return read_label_bit(m, o.number);
    const auto n = effective(m, o, 1);   // BitOfWord
    return (m.words[static_cast<std::size_t>(o.area)][n] >> o.bit) & 1u;
}

// Checks a destination before anything is written (an instruction that fails writes nothing).
inline void probe(Machine& m, const Operand& o, std::uint32_t words) {
    if (o.index != kNoIndex) effective(m, o, span_of(o, words));
}

inline void write_bit(Machine& m, const Operand& o, bool on) {
    const auto n = effective(m, o, 1);
    if (m.fault) return;
    if (o.kind == OperandKind::Bit) [[likely]] return store_byte(m, o.plane, o.area, n, on);
    if (o.kind == OperandKind::LabelBit) return write_label_bit(m, o.number, on);
    const auto word = m.words[static_cast<std::size_t>(o.area)][n];
    const auto mask = 1u << o.bit;
    store_word(m, o.area, n, on ? (word | mask) : (word & ~mask));
}

inline std::uint32_t gather_digits(Machine& m, const Operand& o) {
    const auto n = effective(m, o, o.digits * 4u);
    const std::uint8_t* p = m.bytes[static_cast<std::size_t>(o.plane)][static_cast<std::size_t>(o.area)] + n;
    std::uint32_t v = 0;
    for (unsigned i = 0, bits = o.digits * 4u; i < bits; ++i) v |= std::uint32_t{p[i] != 0} << i;
    return v;
}

inline void scatter_digits(Machine& m, const Operand& o, std::uint32_t v) {
    const auto n = effective(m, o, o.digits * 4u);
    if (m.fault) return;
    for (unsigned i = 0, bits = o.digits * 4u; i < bits; ++i) store_byte(m, o.plane, o.area, n + i, (v >> i) & 1u);
}

// 16-bit source: sign-extended, except digit designation (zero-extended, docs/program.md "Operands").
inline std::int32_t get16(Machine& m, const Operand& o) {
    switch (o.kind) {
        case OperandKind::Constant:
            if (o.index == kNoIndex) return static_cast<std::int16_t>(o.value);
            return static_cast<std::int16_t>(o.value + static_cast<std::uint32_t>(static_cast<std::int16_t>(
                                                            m.words[static_cast<std::size_t>(Area::Z)][o.index])));
        case OperandKind::Word:
        case OperandKind::Wide: return static_cast<std::int16_t>(m.words[static_cast<std::size_t>(o.area)][effective(m, o, 1)]);
        case OperandKind::Digits: return static_cast<std::int32_t>(gather_digits(m, o));
        case OperandKind::LabelWord: return static_cast<std::int16_t>(m.memory->label_word(o.number));
        default: return 0;
    }
}

inline std::int32_t get32(Machine& m, const Operand& o) {
    switch (o.kind) {
        case OperandKind::Constant: {
            if (o.index == kNoIndex) return static_cast<std::int32_t>(o.value);
            const std::int32_t offset = o.index_long
                                            ? static_cast<std::int32_t>(m.words[static_cast<std::size_t>(Area::LZ)][o.index])
                                            : static_cast<std::int16_t>(m.words[static_cast<std::size_t>(Area::Z)][o.index]);
            return static_cast<std::int32_t>(o.value + static_cast<std::uint32_t>(offset));
        }
        case OperandKind::Word: {
            const auto n = effective(m, o, 2);
            const auto* w = m.words[static_cast<std::size_t>(o.area)];
            return static_cast<std::int32_t>((w[n] & 0xFFFFu) | (w[n + 1] << 16));
        }
        case OperandKind::Wide: return static_cast<std::int32_t>(m.words[static_cast<std::size_t>(o.area)][effective(m, o, 1)]);
        case OperandKind::Digits: return static_cast<std::int32_t>(gather_digits(m, o));
        case OperandKind::LabelWord:
            return static_cast<std::int32_t>(m.memory->label_word(o.number) | std::uint32_t{m.memory->label_word(o.number + 1)} << 16);
        default: return 0;
    }
}

inline void put16(Machine& m, const Operand& o, std::int32_t v) {
    switch (o.kind) {
        case OperandKind::Word: {
            const auto n = effective(m, o, 1);
            if (!m.fault) store_word(m, o.area, n, static_cast<std::uint32_t>(v) & 0xFFFFu);
            return;
        }
        case OperandKind::Wide: {
            const auto n = effective(m, o, 1);
            if (!m.fault) store_word(m, o.area, n, static_cast<std::uint32_t>(static_cast<std::int32_t>(static_cast<std::int16_t>(v))));
            return;
        }
        case OperandKind::Digits: return scatter_digits(m, o, static_cast<std::uint32_t>(v));
        case OperandKind::LabelWord: return m.memory->set_label_word(o.number, static_cast<std::uint16_t>(v));
        default: return;
    }
}

inline void put32(Machine& m, const Operand& o, std::int32_t v) {
    switch (o.kind) {
        case OperandKind::Word: {
            const auto n = effective(m, o, 2);
            if (m.fault) return;
            store_word(m, o.area, n, static_cast<std::uint32_t>(v) & 0xFFFFu);
            store_word(m, o.area, n + 1, static_cast<std::uint32_t>(v) >> 16);
            return;
        }
        case OperandKind::Wide: {
            const auto n = effective(m, o, 1);
            if (!m.fault) store_word(m, o.area, n, static_cast<std::uint32_t>(v));
            return;
        }
        case OperandKind::Digits: return scatter_digits(m, o, static_cast<std::uint32_t>(v));
        case OperandKind::LabelWord:
            m.memory->set_label_word(o.number, static_cast<std::uint16_t>(v));
            m.memory->set_label_word(o.number + 1, static_cast<std::uint16_t>(static_cast<std::uint32_t>(v) >> 16));
            return;
        default: return;
    }
}

}  // namespace slmp::program::detail
