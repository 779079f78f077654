// write_csv and write_text: a Source back in the two forms read_source reads
// (docs/program.md "Files", "Step numbers").
#include <algorithm>
#include <array>
#include <span>

#include "devicemodel/utf16.hpp"
#include "program/load_text.hpp"
#include "program/source.hpp"

namespace slmp::program {

namespace {

// The sequence instructions that take one step whatever their operand. MC and
// MCR are sequence instructions too but count 1 + operands, like the worked
// examples a GX Works2 import accepted.
constexpr std::array one_step_mnemonics{
    "LD",   "LDI",   "AND",   "ANI",   "OR",    "ORI",   "LDP", "LDF", "ANDP", "ANDF", "ORP", "ORF",
    "LDPI", "LDFI",  "ANDPI", "ANDFI", "ORPI",  "ORFI",  "ANB", "ORB", "MPS",  "MRD",  "MPP", "INV",
    "MEP",  "MEF",   "OUT",   "SET",   "RST",   "PLS",   "PLF", "FF",  "ALT",  "NOP",  "NOPLF", "PAGE",
    "END",  "FEND",
};

bool one_step(std::string_view mnemonic) {
    return std::any_of(one_step_mnemonics.begin(), one_step_mnemonics.end(),
                       [&](const char* m) { return load_text::same_mnemonic(mnemonic, m); });
}

constexpr const char* text_form_title = "slmp-sim program, text form: one instruction a line";

std::string quoted(std::string_view field) {
    std::string out = "\"";
    for (char c : field) {
        if (c == '"') out += '"';
        out += c;
    }
    return out + "\"";
}

void put_row(std::string& out, std::initializer_list<std::string_view> fields) {
    bool first = true;
    for (auto field : fields) {
        if (!first) out += '\t';
        out += quoted(field);
        first = false;
    }
    out += "\r\n";
}

void put_data_row(std::string& out, std::string_view step, std::string_view statement, std::string_view instruction,
                  std::string_view device, std::string_view pi_statement, std::string_view note) {
    put_row(out, {step, statement, instruction, device, "", pi_statement, note});
}

}  // namespace

std::uint32_t nominal_steps(const SourceLine& line) {
    switch (line.kind) {
        case SourceLine::Kind::Statement: return 0;
        case SourceLine::Kind::Pointer: return 1;
        case SourceLine::Kind::Instruction: break;
    }
    bool out = load_text::same_mnemonic(line.mnemonic, "OUT") || load_text::same_mnemonic(line.mnemonic, "OUTH");
    if (out && line.operands.size() >= 2) return 4;   // OUT T0 K20, OUT C0 K3
    if (one_step(line.mnemonic)) return 1;
    return 1 + static_cast<std::uint32_t>(line.operands.size());
}

std::string write_csv(const Source& source) {
    std::string text;
    // Row 1 is one field; a TAB in it would read back as the re-quoted
    // record variant (docs/program.md "Files"), and no GX Works name has one.
    std::string name = source.name;
    std::replace(name.begin(), name.end(), '\t', ' ');
    put_row(text, {name});
    put_row(text, {"PLC Information:", source.plc_info});
    put_row(text, {"Step No.", "Line Statement", "Instruction", "I/O(Device)", "Blank", "PI Statement", "Note"});
    std::uint32_t next_step = 0;
    for (const auto& line : source.lines) {
        switch (line.kind) {
            case SourceLine::Kind::Statement: {
                auto step = line.step ? std::to_string(*line.step) : std::string();
                put_data_row(text, step, line.statement, "", "", "", line.note);
                break;
            }
            case SourceLine::Kind::Pointer:
            case SourceLine::Kind::Instruction: {
                // An imported program keeps its numbers; lines without one
                // continue from the last.
                std::uint32_t step = line.step.value_or(next_step);
                next_step = step + nominal_steps(line);
                bool pointer = line.kind == SourceLine::Kind::Pointer;
                std::string_view first = line.operands.empty() ? std::string_view() : line.operands.front();
                put_data_row(text, std::to_string(step), "", line.mnemonic, first, pointer ? line.note : "",
                             pointer ? "" : line.note);
                for (std::size_t k = 1; k < line.operands.size(); ++k) {
                    put_data_row(text, "", "", "", line.operands[k], "", "");
                }
                break;
            }
        }
    }
    auto units = devicemodel::utf8_to_utf16(text);
    std::string bytes = "\xFF\xFE";
    bytes.reserve(2 + 2 * units.size());
    for (auto unit : units) {
        bytes += static_cast<char>(unit & 0xFF);
        bytes += static_cast<char>(unit >> 8);
    }
    return bytes;
}

std::string write_text(const Source& source) {
    // read_source takes a file whose third line is 7 comma- or TAB-separated
    // fields for a CSV list; a fixed third line keeps any program text.
    std::string text = "; " + source.name + "\n; PLC Information: " + source.plc_info + "\n; " + text_form_title + "\n";
    for (const auto& line : source.lines) {
        if (line.kind == SourceLine::Kind::Statement) {
            text += ";; " + line.statement;
        } else {
            if (line.step) text += std::to_string(*line.step) + " ";
            text += line.mnemonic;
            for (const auto& operand : line.operands) text += " " + operand;
        }
        // Notes have no place of their own in the text form; a comment keeps
        // them readable (they are not read back). A statement runs to the end
        // of its line, so its note would become part of it.
        if (!line.note.empty() && line.kind != SourceLine::Kind::Statement) text += "  ; " + line.note;
        text += "\n";
    }
    return text;
}

}  // namespace slmp::program
