// The user's PLC program on a simulated CPU: compiled once from a Source
// against the CPU's profile into a flat array of steps with resolved operands,
// then executed scan by scan (docs/program.md).
#pragma once

#include <chrono>
#include <cstdint>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "devicemodel/cpu_profile.hpp"
#include "devicemodel/device_memory.hpp"
#include "devicemodel/labels.hpp"
#include "program/source.hpp"

namespace slmp::program {

enum class OnOperationError : std::uint8_t { Stop, Continue };
enum class OutputModeAtRun : std::uint8_t { Previous, Recalculate };

// cpu.program in the configuration (docs/configuration.md).
struct ProgramOptions {
    OnOperationError operation_error = OnOperationError::Stop;
    std::uint32_t wdt_ms = 200;                   // 10-2000, steps of 10
    std::uint32_t timer_low_ms = 100;             // OUT T time base
    std::uint32_t timer_high_ms = 10;             // OUTH T time base
    OutputModeAtRun output_mode_at_run = OutputModeAtRun::Previous;
    std::uint64_t max_steps_per_scan = 10'000'000;
    bool allow_double_timer_coils = false;
};

// A compiled program: immutable once built; shared by the station and the HTTP API.
class Program;

// Compiles `source` for `profile`'s CPU. Throws LoadError with every problem
// (unknown mnemonic, operand count or type, device outside the profile's
// sizes, missing or duplicate pointer, unbalanced MC/MCR, FOR/NEXT, CALL/RET,
// a mnemonic the family lacks, no END). `warnings` gets what loads anyway.
std::shared_ptr<const Program> compile(const Source& source, const devicemodel::CpuProfile& profile,
                                       const ProgramOptions& options, std::vector<std::string>* warnings = nullptr);
// The same, where an operand that is no device may name a global label of
// `labels` (as GX Works3 programs do): a Bit element where a bit is read or
// written, Word [Signed/Unsigned] where a 16-bit word is, Double Word and Time
// where a 32-bit one is, FLOAT [Single Precision] where a real is. A label on
// a device is that device; one in the label area is reached there. The table
// must keep its layout while the program runs (labels are declared at start).
std::shared_ptr<const Program> compile(const Source& source, const devicemodel::CpuProfile& profile,
                                       const ProgramOptions& options, const devicemodel::LabelTable& labels,
                                       std::vector<std::string>* warnings = nullptr);

// What a one-line instruction list (the scenario rung language, one string
// of blank-separated tokens) needs from the instruction table to split its
// tokens into instructions and check a rung's shape before any CPU is known.
struct InstructionShape {
    enum class Role : std::uint8_t {
        Load, Combine, Join, BranchPush, BranchRead, BranchPop, Modify, Output,
        Control,   // program flow: END, FEND, MC/MCR, jumps, calls, FOR/NEXT, STOP, GOEND, WDT, NOP
    };
    Role role = Role::Output;
    // One string per form, one letter per operand (program/instruction_table.hpp
    // explains the letters: b bit read, o bit write, w 16-bit source, W 16-bit destination …).
    std::vector<std::string_view> forms;
    std::vector<std::string_view> names;   // per form: "s1 s2 d"
};
// `mnemonic` in upper case; P forms ("MOVP") give their base's shape. Family
// restrictions are compile()'s to report.
std::optional<InstructionShape> instruction_shape(std::string_view mnemonic);

const Source& source_of(const Program& program);
std::size_t step_count(const Program& program);   // compiled steps (instructions, END included)

// One compiled step as the HTTP API shows it: the mnemonic as the instruction
// table names it ("MOVP", "LD<="), the operand texts as written and where the
// step came from in the source.
struct CompiledStep {
    std::string mnemonic;
    std::vector<std::string> operands;
    std::size_t row = 0;                        // CSV row / text line
    std::optional<std::uint32_t> written_step;  // the step number of the source, if it had one
};
const std::vector<CompiledStep>& compiled_steps(const Program& program);

// What one scan did.
struct ScanOutcome {
    enum class Kind : std::uint8_t {
        Ok,               // ran to END/FEND (continuation errors, if any, in `error`)
        StopError,        // an operation error with operation_error = stop: the scan ended at `step`
        Watchdog,         // the modelled time passed wdt_ms, or max_steps_per_scan
        StopInstruction,  // STOP executed: the CPU goes to STOP after this scan
    };
    Kind kind = Kind::Ok;
    // The last operation error of the scan (Ok with continue, StopError, Watchdog).
    struct Error {
        std::uint16_t code = 0;        // for SD0 in the family's format (Q/L decimal as binary, iQ-R/iQ-F hex)
        std::size_t step_index = 0;    // index into the compiled steps
        std::size_t row = 0;           // source row/line
        std::string mnemonic;
        std::string message;           // "division by 0"
    };
    std::optional<Error> error;
    std::chrono::nanoseconds modelled{0};   // modelled execution time of the scan (instructions + END processing)
    std::uint64_t executed = 0;             // instructions executed
};

// The engine state of one CPU running one program: edge memory per step,
// timer accumulators, SCJ bits; the stacks live only within a scan.
class Execution {
public:
    explicit Execution(std::shared_ptr<const Program> program);
    ~Execution();
    Execution(Execution&&) noexcept;
    Execution& operator=(Execution&&) noexcept;

    const Program& program() const;
    // One program execution from step 0 to END/FEND, on `memory` (phase 3 of
    // the scan). Continuation errors set SM0/SM1/SD0 (and SM56 on Q/L) in
    // memory themselves; a stop error or watchdog is for the caller to raise.
    ScanOutcome scan(devicemodel::DeviceMemory& memory);
    // END processing (phase 5): every timer whose coil is ON accumulates `scan_time`.
    void end_of_scan(std::chrono::microseconds scan_time);
    // STOP->RUN, power-on, RESET: edge bits, accumulators and SCJ state cleared.
    void restart();
    // PAUSE->RUN: timer accumulators 0 (the pause does not count), edge bits kept (docs/program.md "The scan").
    void resume();

    // The last operation error or watchdog of any scan since the program was
    // loaded (GET /api/program); kept over restart(), cleared by clear_last_error().
    const std::optional<ScanOutcome::Error>& last_error() const;
    void clear_last_error();
    // Modelled execution time (instructions + END processing) of the last scan
    // and the least and most since restart(); 0 before the first scan.
    struct ModelledTimes {
        std::chrono::nanoseconds last{0}, min{0}, max{0};
    };
    ModelledTimes modelled_times() const;

    // Engine state for snapshots and persistence (opaque bytes, same program only).
    std::vector<std::uint8_t> save_state() const;
    bool restore_state(const std::vector<std::uint8_t>& bytes);

private:
    struct State;
    std::unique_ptr<State> state_;
};

}  // namespace slmp::program
