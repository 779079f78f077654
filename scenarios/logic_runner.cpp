// The rungs as a client of the program engine (logic.hpp): translated into a
// program::Source (one line per instruction, the rung's number as its line),
// compiled against the CPU's profile and global labels, executed per scan.
#include <charconv>

#include "config/config_error.hpp"
#include "program/program.hpp"
#include "scenarios/logic.hpp"

namespace slmp::scenarios {
namespace {

// Messages of the engine name "<file>: line <n>: …"; the rungs are the lines.
constexpr const char* kSourceName = "logic";

// Operation errors do not stop the CPU for the scenario's rungs: they stand
// for plant wiring, not the user's program; SM0/SM1/SD0 still tell.
program::ProgramOptions rung_options() {
    program::ProgramOptions options;
    options.operation_error = program::OnOperationError::Continue;
    return options;
}

}  // namespace

struct LogicRunner::Engine {
    program::Execution execution;
};

LogicRunner::~LogicRunner() = default;

LogicRunner::LogicRunner(const LogicProgram& logic, const std::string& source, const devicemodel::Cpu& cpu)
    : source_(source) {
    if (logic.rungs.empty()) return;
    program::Source rungs;
    rungs.file = kSourceName;
    for (const auto& rung : logic.rungs) {
        pointers_.push_back(rung.pointer);
        for (const auto& ins : rung.code) {
            program::SourceLine line;
            line.row = pointers_.size();
            line.mnemonic = ins.mnemonic;
            for (const auto& o : ins.operands) line.operands.push_back(o.text);
            rungs.lines.push_back(std::move(line));
        }
    }
    program::SourceLine end;
    end.row = pointers_.size() + 1;
    end.mnemonic = "END";
    rungs.lines.push_back(end);

    try {
        engine_ = std::make_unique<Engine>(Engine{program::Execution(program::compile(rungs, cpu.profile(), rung_options(), cpu.labels()))});
    } catch (const program::LoadError& e) {
        // The first problem, as "<scenario file>: /logic/<n>: <problem>".
        const std::string prefix = std::string(kSourceName) + ": line ";
        std::string text = e.problems.empty() ? "the rungs do not compile" : e.problems.front();
        std::string where = "/logic";
        if (text.starts_with(prefix)) {
            std::size_t row = 0;
            const char* digits = text.data() + prefix.size();
            auto [end_of_number, ec] = std::from_chars(digits, text.data() + text.size(), row);
            if (ec == std::errc{} && row >= 1 && row <= pointers_.size()) where = pointers_[row - 1];
            text = std::string(end_of_number);
            if (text.starts_with(": ")) text = text.substr(2);
        }
        throw config::ConfigError(source_ + ": " + where + ": " + text +
                                  "; change the rung (docs/scenarios.md \"Logic\", docs/program.md list the instructions and operands)");
    }
}

std::optional<std::string> LogicRunner::scan(devicemodel::DeviceMemory& memory, std::chrono::microseconds elapsed) {
    if (!engine_) return std::nullopt;
    auto& execution = engine_->execution;
    if (restart_) {   // the first scan in RUN: edges and accumulators start afresh
        execution.restart();
        restart_ = false;
    }
    const auto outcome = execution.scan(memory);
    execution.end_of_scan(elapsed);
    if (!outcome.error) {
        last_problem_.clear();
        return std::nullopt;
    }
    const auto& error = *outcome.error;
    const auto rung = error.row >= 1 && error.row <= pointers_.size() ? pointers_[error.row - 1] : std::string("/logic");
    auto problem = source_ + ": " + rung + ": '" + error.mnemonic + "': " + error.message;
    if (problem == last_problem_) return std::nullopt;
    last_problem_ = problem;
    return problem;
}

void LogicRunner::stopped() { restart_ = true; }

}  // namespace slmp::scenarios
