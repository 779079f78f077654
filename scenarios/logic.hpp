// The rung language: a small MELSEC-style instruction list, one string per
// rung, evaluated in order every scan while the CPU is in RUN.
//
//   "LD M0 OR Y0 ANI M1 OUT Y0"        start button M0 latches motor Y0, M1 stops it
//   "LD Y0 OUT T0 K20"                 T0: 2 s on-delay (100 ms base)
//   "LD T0 OUT Y1"
//   "LDP X0 OUT C0 K100"               counter C0 counts rising edges of X0
//   "LD>= D100 K50 SET M10"            compare contact
//   "LD SM400 ADD D0 K1 D0"            arithmetic on 16-bit signed words
//
// Contacts: LD LDI LDP LDF, AND ANI ANDP ANDF, OR ORI ORP ORF, ANB ORB (MELSEC's
// block stack), compare contacts LD= LD<> LD< LD<= LD> LD>= (and AND…/OR…).
// Outputs: OUT (bit, or T/ST/C with a K preset), SET, RST (a T/C: value and
// contact), MOV, ADD, SUB (S1 S2 D), INC, DEC, each with a P form (MOVP …)
// that runs on the rung's rising edge only. Operands: bit and word devices
// (D100, M0, X1F, W1A), T/ST/C numbers (contact in a contact, current value in
// a word operand, coil in OUT), constants K123 / H7F, and Bit or Word global
// labels (case as declared: "LD StartButton OUT Motor"). Reference and the exact
// evaluation rules: docs/scenarios.md "Logic".
#pragma once

#include <chrono>
#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "devicemodel/device_table.hpp"
#include "devicemodel/device_memory.hpp"
#include "devicemodel/labels.hpp"
#include "devicemodel/runtime_config.hpp"
#include "devicemodel/timers.hpp"
#include "scenarios/compare.hpp"

namespace slmp::scenarios {

struct LogicOperand {
    enum class Kind : std::uint8_t { Bit, Word, Timer, Constant };
    Kind kind = Kind::Constant;
    devicemodel::DeviceAddress device;   // Bit/Word; Timer: area T/ST/C and number
    std::int32_t constant = 0;
    // A Bit or Word global label instead of a device (spec null): the name as
    // written, resolved by bind_labels() when the scenario starts.
    std::string label = {};
    std::optional<devicemodel::LabelRef> bound = {};
};

enum class LogicOp : std::uint8_t {
    Load, And, Or,          // contact forms, see Contact
    LoadBlock, AndBlock, OrBlock,
    Out, Set, Reset,
    Move, Add, Sub, Inc, Dec,
};

enum class Contact : std::uint8_t { Normal, Inverted, Rising, Falling, Compare };

struct Instruction {
    LogicOp op = LogicOp::Load;
    Contact contact = Contact::Normal;
    Compare compare = Compare::Eq;
    bool pulse = false;                   // MOVP …: on the rung's rising edge
    std::vector<LogicOperand> operands;
    std::size_t memory = 0;               // edge memory slot (edge contacts, pulse forms)
    bool new_line = false;                // an LD after an output starts a new line (IL style)
};

struct Rung {
    std::vector<Instruction> code;
    std::string text;
    std::string pointer;                  // "/logic/2"
};

struct LogicProgram {
    std::vector<Rung> rungs;
    std::vector<devicemodel::TimerRange> timers;       // from OUT T/ST (preset per timer)
    std::vector<devicemodel::CounterRange> counters;   // from OUT C
    std::size_t memory_slots = 0;
};

// Runs a program every scan in RUN: the rungs in order (a write is seen by
// the rungs after it in the same scan), then the program's timers and
// counters as the CPU updates them at END processing. Not in RUN: nothing
// runs, and edges and timing start afresh at the next RUN.
class LogicRunner {
public:
    explicit LogicRunner(const LogicProgram& program);
    void scan(devicemodel::DeviceMemory& memory, std::chrono::microseconds elapsed);
    void stopped();

private:
    bool contact(const devicemodel::DeviceMemory& memory, const Instruction& ins);
    void output(devicemodel::DeviceMemory& memory, const Instruction& ins, bool power);

    const LogicProgram& program_;
    std::vector<std::uint8_t> memory_;    // edge memory, one slot per edge contact / pulse form
    devicemodel::TimerBank timers_;
};

// Parses one rung into `program`; throws config::ConfigError naming
// `source`, `pointer`, the instruction and the fix.
void parse_rung(LogicProgram& program, const std::string& text, const std::string& source, const std::string& pointer);

}  // namespace slmp::scenarios
