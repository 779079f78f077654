// Helpers of the loader tests (source_*_test.cpp): files built the way
// GX Works writes them, and a Source reduced to what a comparison needs.
#pragma once

#include <span>
#include <string>
#include <string_view>
#include <vector>

#include "devicemodel/utf16.hpp"
#include "program/source.hpp"

namespace slmp::program::test {

// UTF-8 text as a UTF-16LE file with its BOM.
inline std::string utf16le_file(std::string_view utf8) {
    std::string bytes = "\xFF\xFE";
    for (auto unit : devicemodel::utf8_to_utf16(utf8)) {
        bytes += static_cast<char>(unit & 0xFF);
        bytes += static_cast<char>(unit >> 8);
    }
    return bytes;
}

// LF-terminated rows with CR LF instead.
inline std::string crlf(std::string_view rows) {
    std::string out;
    for (char c : rows) {
        if (c == '\n') out += '\r';
        out += c;
    }
    return out;
}

// The three header rows of the worked examples, CR LF terminated.
inline const std::string example_header =
    "\"MAIN\"\r\n\"PLC Information:\"\t\"RCPU R08\"\r\n"
    "\"Step No.\"\t\"Line Statement\"\t\"Instruction\"\t\"I/O(Device)\"\t\"Blank\"\t\"PI Statement\"\t\"Note\"\r\n";

// A worked example's data rows as the complete UTF-16LE file GX Works writes.
inline std::string example_csv_file(std::string_view data_rows) { return utf16le_file(example_header + crlf(data_rows)); }

// One string a line: "LD X0 Y1" (instruction), "P10:" (pointer), ";; text" (statement).
inline std::vector<std::string> summary(const Source& source) {
    std::vector<std::string> out;
    for (const auto& line : source.lines) {
        switch (line.kind) {
            case SourceLine::Kind::Instruction: {
                std::string text = line.mnemonic;
                for (const auto& operand : line.operands) text += " " + operand;
                out.push_back(text);
                break;
            }
            case SourceLine::Kind::Pointer: out.push_back(line.mnemonic + ":"); break;
            case SourceLine::Kind::Statement: out.push_back(";; " + line.statement); break;
        }
    }
    return out;
}

// The problems of a load that must fail ("" when it loads).
template <class F>
std::vector<std::string> problems_of(F&& load) {
    try {
        load();
    } catch (const LoadError& e) {
        return e.problems;
    }
    return {};
}

}  // namespace slmp::program::test
