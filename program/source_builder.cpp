#include "program/source_builder.hpp"

namespace slmp::program {

SourceBuilder::SourceBuilder(Source& source, load_text::Problems& problems) : source_(source), problems_(problems) {}

std::string SourceBuilder::where(std::size_t row, std::optional<std::uint32_t> step) const {
    std::string text = (source_.format == Format::GxWorksCsv ? "row " : "line ") + std::to_string(row);
    if (step) text += " (step " + std::to_string(*step) + ")";
    return text;
}

void SourceBuilder::problem(std::size_t row, std::optional<std::uint32_t> step, const std::string& text) {
    problems_.add(where(row, step) + ": " + text);
}

void SourceBuilder::warning(std::size_t row, std::optional<std::uint32_t> step, const std::string& text) {
    source_.warnings.push_back(source_.file + ": " + where(row, step) + ": " + text);
}

void SourceBuilder::ignored_after_end(std::size_t row) {
    if (warned_after_end_) return;
    warned_after_end_ = true;
    warning(row, std::nullopt, "text after END is ignored");
}

bool SourceBuilder::add(SourceLine line) {
    const bool counts_steps = line.kind != SourceLine::Kind::Statement;
    if (counts_steps && line.step) {
        // A statement row may carry the step of the instruction below it, so
        // only instructions and pointers must increase; rows run in file order
        // whatever the numbers say, hence a warning.
        if (last_step_ && *line.step <= *last_step_) {
            warning(line.row, line.step,
                    "step number " + std::to_string(*line.step) + " does not increase (" + where(last_step_row_) +
                        " has step " + std::to_string(*last_step_) + "); rows run in file order");
        }
        last_step_ = line.step;
        last_step_row_ = line.row;
    }
    if (line.kind == SourceLine::Kind::Instruction) {
        if (++instructions_ > max_instructions) {
            problem(line.row, line.step,
                    "more than " + std::to_string(max_instructions) + " instructions; the limit is " +
                        std::to_string(max_instructions));
            return false;
        }
        if (load_text::same_mnemonic(line.mnemonic, "END")) ended_ = true;
    }
    open_ = line.kind == SourceLine::Kind::Instruction;
    source_.lines.push_back(std::move(line));
    return true;
}

}  // namespace slmp::program
