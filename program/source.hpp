// A PLC program as the engineering tools write it, before it is compiled: the
// rows of a GX Works2/GX Works3 CSV list or the lines of the plain-text form
// (docs/program.md "Files"). Pure text handling: no device, no profile.
#pragma once

#include <cstddef>
#include <cstdint>
#include <optional>
#include <stdexcept>
#include <string>
#include <string_view>
#include <vector>

namespace slmp::program {

// Every problem a load finds, one line each ("line1.csv: row 14 (step 12):
// 'MOVV' is no instruction of R08CPU (family iQ-R)"). Thrown by read_source,
// read_comments and compile.
struct LoadError : std::runtime_error {
    explicit LoadError(std::vector<std::string> problems);
    std::vector<std::string> problems;
};

enum class Format : std::uint8_t {
    GxWorksCsv,   // 7-column list: UTF-16LE+BOM (or UTF-8), TAB (or comma), quoted, continuation rows
    Text,         // one instruction a line: "LD X0", "OUT T0 K20", "P10", ";; statement"
};

struct SourceLine {
    enum class Kind : std::uint8_t { Instruction, Pointer, Statement };
    Kind kind = Kind::Instruction;
    std::size_t row = 0;                  // CSV row / text line, 1-based, for messages
    std::optional<std::uint32_t> step;    // the step number as written (diagnostics only)
    std::string mnemonic;                 // Instruction: "LD", "OUT", "MOVP" as written; Pointer: "P10"
    std::vector<std::string> operands;    // Instruction: "X0", "K20", "\"ABC\"" (string constants keep their quotes)
    std::string statement;                // Statement: its text
    std::string note;                     // a note (CSV column 7) or PI statement (column 6)
};

struct Source {
    std::string file;                     // as named in messages ("line1.csv")
    Format format = Format::Text;
    std::string name = "MAIN";            // CSV row 1
    std::string plc_info;                 // CSV row 2, second field ("RCPU R08")
    std::vector<SourceLine> lines;
    std::vector<std::string> warnings;    // text after END, non-increasing step numbers, ...
};

// The format is recognised by content: a UTF-16 BOM, or a third row of 7
// TAB- or comma-separated fields, is the CSV list; anything else the text form.
Source read_source(std::string_view bytes, std::string file);
// The program written back: CSV as GX Works writes it (UTF-16LE, BOM, TAB,
// quoted fields, CR LF, continuation rows, nominal step numbers where the
// source had none), or the text form (UTF-8).
std::string write_csv(const Source& source);
std::string write_text(const Source& source);
// The steps slmp-sim counts for a line when it numbers an export
// (docs/program.md "Step numbers"): 1 for a sequence instruction and a
// pointer label, 4 for OUT/OUTH of a timer or counter with a preset, 1 + the
// operand count otherwise; 0 for a statement. Not the CPU's real step count.
std::uint32_t nominal_steps(const SourceLine& line);

// Device comments (cpu.program.comments): GX Works2's 2-column file
// ("Device Name", "Comment") or GX Converter's device,label,comment CSV.
struct DeviceComment {
    std::string device;    // as written ("X0A1")
    std::string comment;
};
std::vector<DeviceComment> read_comments(std::string_view bytes, std::string file);

}  // namespace slmp::program
