// The rung language: a MELSEC instruction list, one string per rung, run
// every scan while the CPU is in RUN by the same engine as the user's program
// (program/, docs/program.md) — one interpreter for both.
//
//   "LD M0 OR Y0 ANI M1 OUT Y0"        start button M0 latches motor Y0, M1 stops it
//   "LD Y0 OUT T0 K20"                 T0: 2 s on-delay (100 ms base)
//   "LD T0 OUT Y1"
//   "LDP X0 OUT C0 K100"               counter C0 counts rising edges of X0
//   "LD>= D100 K50 SET M10"            compare contact
//   "LD SM400 ADD D0 K1 D0"            16-bit signed arithmetic (ADD/SUB are + and -)
//
// Loading (logic_parser.cpp, no CPU known yet) splits the tokens into
// instructions by the operand counts of the engine's instruction table and
// checks each rung's shape and operands, naming the rung's JSON pointer, the
// instruction and the fix. Starting (logic_runner.cpp) compiles the rungs
// against the station's CPU profile and global labels into one program.
// Reference: docs/scenarios.md "Logic".
#pragma once

#include <chrono>
#include <cstdint>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "devicemodel/cpu.hpp"
#include "devicemodel/device_table.hpp"

namespace slmp::scenarios {

struct RungOperand {
    // What the rung needs there; a global label must be of that type (bind_labels).
    enum class Use : std::uint8_t {
        Bit,     // a contact or coil: a Bit label
        Word,    // a 16-bit word: a Word [Signed/Unsigned] label
        Either,  // RST: a Bit or a Word label
        Other,   // any other operand type: the engine checks the label's type
    };
    Use use = Use::Other;
    std::string text;                                  // as written (a label keeps its case)
    std::optional<devicemodel::DeviceAddress> device;  // a device: checked against the CPU's sizes at start
    bool label = false;                                // neither device nor constant: a global label, bound at start
};

struct RungInstruction {
    std::string mnemonic;      // as the engine names it: "+P" for ADDP
    std::vector<RungOperand> operands;
};

struct Rung {
    std::vector<RungInstruction> code;
    std::string text;
    std::string pointer;       // "/logic/2"
};

struct LogicProgram {
    std::vector<Rung> rungs;
};

// Parses one rung into `program`; throws config::ConfigError naming
// `source`, `pointer`, the instruction and the fix.
void parse_rung(LogicProgram& program, const std::string& text, const std::string& source, const std::string& pointer);

// The rungs as one program of the engine, run after the CPU's scan (spec
// §3.1 phase 4): the rungs in order (a write is seen by the rungs after it),
// then END processing, where timers whose coil is ON accumulate the scan's
// time. Timers and counters follow the real CPU rule (value and contact move
// when OUT T / OUT C executes). Not in RUN: nothing runs; edges and timer
// accumulators start afresh at the next RUN.
class LogicRunner {
public:
    // Compiles `logic` (labels already bound) for `cpu`; throws
    // config::ConfigError naming `source`, the rung's pointer and the problem.
    LogicRunner(const LogicProgram& logic, const std::string& source, const devicemodel::Cpu& cpu);
    ~LogicRunner();
    // One scan in RUN, `elapsed` being the scan's time. Returns a message for
    // an operation error or watchdog the rungs met that differs from the last
    // one reported (the rungs go on: operation errors continue, SM0/SD0 tell).
    std::optional<std::string> scan(devicemodel::DeviceMemory& memory, std::chrono::microseconds elapsed);
    void stopped();

private:
    // The engine's state (program::Execution), kept out of this header so
    // that scenario code does not see namespace slmp::program.
    struct Engine;
    std::unique_ptr<Engine> engine_;   // null: no rungs
    std::string source_;
    std::vector<std::string> pointers_;   // by rung: the JSON pointer of each source row
    bool restart_ = true;
    std::string last_problem_;
};

}  // namespace slmp::scenarios
