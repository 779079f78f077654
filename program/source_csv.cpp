// The GX Works2/GX Works3 CSV list (docs/program.md "Files"): row 1 the
// program name, row 2 "PLC Information:" and the CPU, row 3 the seven column
// names (any language), then instruction, continuation, statement and
// pointer rows. Hand-edited and tool-made variants are read too: UTF-8,
// commas, unquoted fields, all operands in one cell, re-quoted records.
#include <algorithm>

#include "program/source_builder.hpp"

namespace slmp::program {

namespace {

constexpr std::size_t columns = 7;
enum Column : std::size_t { StepNo, LineStatement, Instruction, Device, Blank, PiStatement, Note };

std::string program_name(std::string_view field) {
    auto name = load_text::trimmed(field);
    // Some generators write "(MAIN)".
    if (name.size() >= 2 && name.front() == '(' && name.back() == ')') name = load_text::trimmed(name.substr(1, name.size() - 2));
    return name.empty() ? std::string("MAIN") : std::string(name);
}

std::string note_of(const std::vector<std::string>& cells) {
    return !cells[Note].empty() ? cells[Note] : cells[PiStatement];
}

}  // namespace

void read_gx_works_rows(std::string_view text, char separator, Source& source, load_text::Problems& problems) {
    SourceBuilder builder(source, problems);
    load_text::RowCursor rows(text);
    while (auto record = rows.next()) {
        const std::size_t row = rows.number();
        if (auto why = load_text::row_problem(*record); !why.empty()) {
            builder.problem(row, std::nullopt, why);
            continue;
        }
        auto fields = load_text::split_record(*record, separator);
        if (!fields) {
            builder.problem(row, std::nullopt, "a quote opens a field and is never closed");
            continue;
        }
        if (row == 1) {
            if (load_text::used_fields(*fields) > 1) {
                builder.problem(row, std::nullopt,
                                "has " + load_text::fields_count(load_text::used_fields(*fields)) +
                                    "; a GX Works list starts with the program name alone");
            }
            source.name = program_name(fields->front());
            continue;
        }
        if (row == 2) {
            if (load_text::used_fields(*fields) > 2) {
                builder.problem(row, std::nullopt,
                                "has " + load_text::fields_count(load_text::used_fields(*fields)) +
                                    "; the second row of a GX Works list is 'PLC Information:' and the CPU type");
            }
            if (fields->size() >= 2) source.plc_info = std::string(load_text::trimmed((*fields)[1]));
            continue;
        }
        if (row == 3) {
            if (fields->size() != columns) {
                builder.problem(row, std::nullopt,
                                "has " + load_text::fields_count(fields->size()) +
                                    "; the column-name row of a GX Works list has 7");
            }
            continue;
        }
        if (fields->size() > columns) {
            builder.problem(row, std::nullopt, "has " + load_text::fields_count(fields->size()) + ", a GX Works list has 7");
            continue;
        }
        std::vector<std::string> cells(columns);
        for (std::size_t k = 0; k < fields->size(); ++k) cells[k] = std::string(load_text::trimmed((*fields)[k]));
        if (std::all_of(cells.begin(), cells.end(), [](const std::string& c) { return c.empty(); })) continue;
        // END's own continuation rows (an END with operands is the
        // compiler's to refuse) are not text after it.
        const bool continuation = cells[LineStatement].empty() && cells[Instruction].empty() && !cells[Device].empty();
        if (builder.ended() && !(continuation && builder.open_instruction())) {
            builder.ignored_after_end(row);
            continue;
        }

        std::optional<std::uint32_t> step;
        if (!cells[StepNo].empty()) {
            step = load_text::parse_step(cells[StepNo]);
            if (!step) {
                builder.problem(row, std::nullopt,
                                "step number " + load_text::quoted_excerpt(cells[StepNo]) + " is not a decimal number");
                continue;
            }
        }
        auto operands = load_text::split_operands(cells[Device]);
        if (!operands) {
            builder.problem(row, step, "a string constant in " + load_text::quoted_excerpt(cells[Device]) +
                                           " is not closed; end it with \"");
            continue;
        }

        if (!cells[LineStatement].empty()) {
            SourceLine line;
            line.kind = SourceLine::Kind::Statement;
            line.row = row;
            line.step = step;
            line.statement = cells[LineStatement];
            if (cells[Instruction].empty() && cells[Device].empty()) line.note = note_of(cells);
            builder.add(std::move(line));
        }
        if (!cells[Instruction].empty()) {
            SourceLine line;
            line.row = row;
            line.step = step;
            line.note = note_of(cells);
            if (operands->empty() && load_text::is_pointer_label(cells[Instruction])) {
                line.kind = SourceLine::Kind::Pointer;
                line.mnemonic = cells[Instruction];
                if (line.mnemonic.ends_with(':')) line.mnemonic.pop_back();
            } else {
                line.mnemonic = cells[Instruction];
                line.operands = std::move(*operands);
            }
            if (!builder.add(std::move(line))) return;
        } else if (!operands->empty()) {
            // A continuation row: the next operand(s) of the instruction above.
            if (auto* instruction = builder.open_instruction()) {
                for (auto& operand : *operands) instruction->operands.push_back(std::move(operand));
            } else {
                builder.problem(row, step,
                                "operand " + load_text::quoted_excerpt(cells[Device]) +
                                    " is on a continuation row with no instruction before it");
            }
        } else if (cells[LineStatement].empty()) {
            builder.warning(row, step, "holds no instruction, operand or statement; ignored");
            builder.close_instruction();
        }
    }
}

}  // namespace slmp::program
