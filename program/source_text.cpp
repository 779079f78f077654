// The plain-text form (docs/program.md "Files"): one instruction a line, an
// optional step number first, `;;` a kept line statement, `;` and `//`
// comments, `P10` or `P10:` a pointer label. `*` is the multiplication
// mnemonic, never a comment.
#include <algorithm>

#include "program/source_builder.hpp"

namespace slmp::program {

namespace {

bool all_digits(std::string_view s) {
    return !s.empty() && std::all_of(s.begin(), s.end(), [](char c) { return c >= '0' && c <= '9'; });
}

std::string without_colon(std::string_view label) {
    if (label.ends_with(':')) label.remove_suffix(1);
    return std::string(label);
}

}  // namespace

void read_text_rows(std::string_view file_text, Source& source, load_text::Problems& problems) {
    SourceBuilder builder(source, problems);
    load_text::RowCursor rows(file_text);
    while (auto physical = rows.next()) {
        const std::size_t row = rows.number();
        auto text = load_text::trimmed(*physical);
        if (text.empty()) continue;
        if (auto why = load_text::row_problem(text); !why.empty()) {
            builder.problem(row, std::nullopt, why);
            continue;
        }
        if (text.starts_with(";;")) {
            if (builder.ended()) {
                builder.ignored_after_end(row);
                continue;
            }
            // ";;" alone is an empty statement: a list has no row for one.
            if (auto statement = load_text::trimmed(text.substr(2)); !statement.empty()) {
                SourceLine line;
                line.kind = SourceLine::Kind::Statement;
                line.row = row;
                line.statement = std::string(statement);
                builder.add(std::move(line));
            }
            continue;
        }
        auto tokens = load_text::split_operands(text.substr(0, load_text::comment_start(text)));
        if (!tokens) {
            builder.problem(row, std::nullopt, "a string constant is not closed; end it with \"");
            continue;
        }
        if (tokens->empty()) continue;   // a comment line
        if (builder.ended()) {
            builder.ignored_after_end(row);
            continue;
        }
        auto token = tokens->begin();
        std::optional<std::uint32_t> step;
        // A leading number is the step; false when the line is refused.
        auto take_step = [&] {
            step.reset();
            if (!all_digits(*token)) return true;
            step = load_text::parse_step(*token);
            if (!step) {
                builder.problem(row, std::nullopt, "step number " + load_text::quoted_excerpt(*token) + " is too large");
                return false;
            }
            if (++token == tokens->end()) {
                builder.problem(row, step, "a step number with no instruction after it");
                return false;
            }
            return true;
        };
        if (!take_step()) continue;
        // "P10" alone is a label; "P10: LD X0" a label and an instruction
        // (which may have its own step number, as on a line of its own).
        bool line_done = false;
        while (!line_done && load_text::is_pointer_label(*token) &&
               (token + 1 == tokens->end() || token->ends_with(':'))) {
            SourceLine label;
            label.kind = SourceLine::Kind::Pointer;
            label.row = row;
            label.step = step;
            label.mnemonic = without_colon(*token);
            builder.add(std::move(label));
            line_done = ++token == tokens->end() || !take_step();
        }
        if (line_done) continue;
        SourceLine line;
        line.row = row;
        line.step = step;
        line.mnemonic = *token;
        line.operands.assign(token + 1, tokens->end());
        if (!builder.add(std::move(line))) return;
    }
}

}  // namespace slmp::program
