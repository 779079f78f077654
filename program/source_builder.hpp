// What the CSV and text readers (source_csv.cpp, source_text.cpp) share once
// a row is understood: the "row 14 (step 12)" of messages, the step order
// warning, the instruction limit and the end at the first END
// (docs/program.md "Files"). Internal to program/.
#pragma once

#include <cstddef>
#include <cstdint>
#include <optional>
#include <string>
#include <string_view>

#include "program/load_text.hpp"
#include "program/source.hpp"

namespace slmp::program {

// A program that needs more is no program a CPU holds (the largest iQ-R
// program memory is about 1.2 million steps, but a list that long is a
// generated or hostile file); the bound keeps a load's memory in check.
inline constexpr std::size_t max_instructions = 100'000;

class SourceBuilder {
public:
    SourceBuilder(Source& source, load_text::Problems& problems);

    // "row 14 (step 12)" for the CSV list, "line 9" for the text form.
    std::string where(std::size_t row, std::optional<std::uint32_t> step = std::nullopt) const;
    void problem(std::size_t row, std::optional<std::uint32_t> step, const std::string& text);
    void warning(std::size_t row, std::optional<std::uint32_t> step, const std::string& text);

    // True once the first END is in: later rows are ignored (with one warning,
    // given by ignored_after_end).
    bool ended() const { return ended_; }
    void ignored_after_end(std::size_t row);

    // Adds a line; false when it passes the instruction limit (a problem is
    // recorded and reading should stop).
    bool add(SourceLine line);
    // The instruction the next continuation row belongs to, if any.
    SourceLine* open_instruction() { return open_ ? &source_.lines.back() : nullptr; }
    void close_instruction() { open_ = false; }

private:
    Source& source_;
    load_text::Problems& problems_;
    std::size_t instructions_ = 0;
    std::optional<std::uint32_t> last_step_;
    std::size_t last_step_row_ = 0;
    bool ended_ = false;
    bool warned_after_end_ = false;
    bool open_ = false;
};

// The readers behind read_source, on decoded rows.
void read_gx_works_rows(std::string_view text, char separator, Source& source, load_text::Problems& problems);
void read_text_rows(std::string_view text, Source& source, load_text::Problems& problems);

}  // namespace slmp::program
