// write_csv and write_text (program/source_write.cpp): GX Works' bytes,
// nominal step numbers, and round trips through both forms.
#include <catch2/catch.hpp>

#include "program/source.hpp"
#include "tests/program/source_examples.hpp"
#include "tests/program/source_test_support.hpp"

using namespace slmp::program;
using namespace slmp::program::test;
using Lines = std::vector<std::string>;

namespace {

std::string bytes_of(std::initializer_list<unsigned> values) {
    std::string out;
    for (auto v : values) out += static_cast<char>(v);
    return out;
}

}  // namespace

TEST_CASE("write_csv starts a file with the bytes GX Works writes") {
    Source source;
    source.plc_info = "RCPU R08";
    source.lines.push_back({SourceLine::Kind::Instruction, 1, std::nullopt, "LD", {"X0"}, "", ""});
    source.lines.push_back({SourceLine::Kind::Instruction, 2, std::nullopt, "OUT", {"T0", "K20"}, "", ""});
    auto bytes = write_csv(source);
    // BOM "MAIN" CR LF
    CHECK(bytes.substr(0, 18) == bytes_of({0xFF, 0xFE, 0x22, 0x00, 0x4D, 0x00, 0x41, 0x00, 0x49, 0x00, 0x4E, 0x00, 0x22,
                                           0x00, 0x0D, 0x00, 0x0A, 0x00}));
    const std::string header_rows = utf16le_file(example_header);
    REQUIRE(bytes.substr(0, header_rows.size()) == header_rows);
    // "0" TAB "" TAB "LD" TAB "X0" TAB "" TAB "" TAB "" CR LF: 54 bytes
    const std::string instruction_row =
        bytes_of({0x22, 0x00, 0x30, 0x00, 0x22, 0x00, 0x09, 0x00, 0x22, 0x00, 0x22, 0x00, 0x09, 0x00, 0x22, 0x00, 0x4C, 0x00,
                  0x44, 0x00, 0x22, 0x00, 0x09, 0x00, 0x22, 0x00, 0x58, 0x00, 0x30, 0x00, 0x22, 0x00, 0x09, 0x00, 0x22, 0x00,
                  0x22, 0x00, 0x09, 0x00, 0x22, 0x00, 0x22, 0x00, 0x09, 0x00, 0x22, 0x00, 0x22, 0x00, 0x0D, 0x00, 0x0A, 0x00});
    REQUIRE(instruction_row.size() == 54);
    CHECK(bytes.substr(header_rows.size(), 54) == instruction_row);
    auto rest = bytes.substr(header_rows.size() + 54);
    CHECK(rest.substr(0, rest.size() - 50) == utf16le_file("\"1\"\t\"\"\t\"OUT\"\t\"T0\"\t\"\"\t\"\"\t\"\"\r\n").substr(2));
    // "" TAB "" TAB "" TAB "K20" TAB "" TAB "" TAB "" CR LF: 50 bytes, the last row, CR LF included
    CHECK(rest.substr(rest.size() - 50) ==
          bytes_of({0x22, 0x00, 0x22, 0x00, 0x09, 0x00, 0x22, 0x00, 0x22, 0x00, 0x09, 0x00, 0x22, 0x00, 0x22, 0x00, 0x09,
                    0x00, 0x22, 0x00, 0x4B, 0x00, 0x32, 0x00, 0x30, 0x00, 0x22, 0x00, 0x09, 0x00, 0x22, 0x00, 0x22, 0x00,
                    0x09, 0x00, 0x22, 0x00, 0x22, 0x00, 0x09, 0x00, 0x22, 0x00, 0x22, 0x00, 0x0D, 0x00, 0x0A, 0x00}));
}

TEST_CASE("every worked example written as CSV from its text form is the specification's file, byte for byte") {
    for (const auto& example : worked_examples) {
        if (example.csv_rows.empty()) continue;
        INFO(example.number << " " << example.title);
        auto source = read_source(example.text, "example.il");
        source.plc_info = "RCPU R08";
        CHECK(write_csv(source) == example_csv_file(example.csv_rows));
    }
}

TEST_CASE("nominal steps: sequence instructions and labels 1, OUT of a timer or counter with a preset 4, else 1 + operands") {
    auto steps = [](std::string mnemonic, Lines operands, SourceLine::Kind kind = SourceLine::Kind::Instruction) {
        return nominal_steps({kind, 1, std::nullopt, std::move(mnemonic), std::move(operands), "", ""});
    };
    CHECK(steps("LD", {"X0"}) == 1);
    CHECK(steps("ldp", {"X0"}) == 1);
    CHECK(steps("RST", {"D0"}) == 1);
    CHECK(steps("OUT", {"Y0"}) == 1);
    CHECK(steps("OUT", {"T0", "K20"}) == 4);
    CHECK(steps("OUTH", {"T0", "K20"}) == 4);
    CHECK(steps("MC", {"N0", "M100"}) == 3);
    CHECK(steps("MCR", {"N0"}) == 2);
    CHECK(steps("/", {"K36", "K-5", "D0"}) == 4);
    CHECK(steps("RET", {}) == 1);
    CHECK(steps("P10", {}, SourceLine::Kind::Pointer) == 1);
    CHECK(steps("", {}, SourceLine::Kind::Statement) == 0);
}

TEST_CASE("an imported program keeps its step numbers on export, lines without one continue from the last") {
    auto source = read_source(example_csv_file("\"100\"\t\"\"\t\"LD\"\t\"X0\"\t\"\"\t\"\"\t\"\"\n"
                                               "\"107\"\t\"\"\t\"OUT\"\t\"Y0\"\t\"\"\t\"\"\t\"\"\n"),
                              "a.csv");
    source.lines.push_back({SourceLine::Kind::Instruction, 0, std::nullopt, "END", {}, "", ""});
    auto again = read_source(write_csv(source), "a.csv");
    REQUIRE(again.lines.size() == 3);
    CHECK(again.lines[0].step == 100u);
    CHECK(again.lines[1].step == 107u);
    CHECK(again.lines[2].step == 108u);
}

TEST_CASE("write_csv: statements, labels, notes and string constants as GX Works writes them") {
    auto source = read_source(";; Start \"now\"\nLD X0\nP10\n$MOV \"AB\" D0\nEND\n", "s.il");
    source.lines[1].note = "input";
    auto expected = utf16le_file("\"MAIN\"\r\n\"PLC Information:\"\t\"\"\r\n" + example_header.substr(example_header.find("\"Step")) +
                                 "\"\"\t\"Start \"\"now\"\"\"\t\"\"\t\"\"\t\"\"\t\"\"\t\"\"\r\n"
                                 "\"0\"\t\"\"\t\"LD\"\t\"X0\"\t\"\"\t\"\"\t\"input\"\r\n"
                                 "\"1\"\t\"\"\t\"P10\"\t\"\"\t\"\"\t\"\"\t\"\"\r\n"
                                 "\"2\"\t\"\"\t\"$MOV\"\t\"\"\"AB\"\"\"\t\"\"\t\"\"\t\"\"\r\n"
                                 "\"\"\t\"\"\t\"\"\t\"D0\"\t\"\"\t\"\"\t\"\"\r\n"
                                 "\"5\"\t\"\"\t\"END\"\t\"\"\t\"\"\t\"\"\t\"\"\r\n");
    CHECK(write_csv(source) == expected);
}

TEST_CASE("write_text: one line each, ,, for statements, steps where the source had them") {
    auto csv = read_source(example_csv_file("\"\"\t\"Timer\"\t\"\"\t\"\"\t\"\"\t\"\"\t\"\"\n"
                                            "\"0\"\t\"\"\t\"LD\"\t\"X0\"\t\"\"\t\"\"\t\"\"\n"
                                            "\"1\"\t\"\"\t\"OUT\"\t\"T0\"\t\"\"\t\"\"\t\"coil\"\n"
                                            "\"\"\t\"\"\t\"\"\t\"K20\"\t\"\"\t\"\"\t\"\"\n"
                                            "\"5\"\t\"\"\t\"P10\"\t\"\"\t\"\"\t\"\"\t\"\"\n"
                                            "\"6\"\t\"\"\t\"END\"\t\"\"\t\"\"\t\"\"\t\"\"\n"),
                           "a.csv");
    const std::string title = "; slmp-sim program, text form: one instruction a line\n";
    CHECK(write_text(csv) == "; MAIN\n; PLC Information: RCPU R08\n" + title +
                                 ";; Timer\n0 LD X0\n1 OUT T0 K20  ; coil\n5 P10\n6 END\n");
    CHECK(write_text(read_source("LD X0\nOUT T0 K20\nEND\n", "a.il")) ==
          "; MAIN\n; PLC Information: \n" + title + "LD X0\nOUT T0 K20\nEND\n");
}

TEST_CASE("write_text's output stays text even when a line holds 7 comma-separated fields") {
    auto source = read_source("; 1\n; 2\n; 3\nLD a,b,c,d,e,f,g\nEND\n", "a.il");
    auto again = read_source(write_text(source), "a.il");
    CHECK(again.format == Format::Text);
    CHECK(summary(again) == Lines{"LD a,b,c,d,e,f,g", "END"});
}

TEST_CASE("round trips: text -> CSV -> lines and CSV -> text -> lines give the same lines for every worked example") {
    for (const auto& example : worked_examples) {
        INFO(example.number << " " << example.title);
        auto from_text = read_source(example.text, "e.il");
        auto via_csv = read_source(write_csv(from_text), "e.csv");
        CHECK(via_csv.format == Format::GxWorksCsv);
        CHECK(summary(via_csv) == summary(from_text));
        CHECK(summary(read_source(write_text(from_text), "e.il")) == summary(from_text));
        if (example.csv_rows.empty()) continue;
        auto from_csv = read_source(example_csv_file(example.csv_rows), "e.csv");
        auto via_text = read_source(write_text(from_csv), "e.il");
        CHECK(via_text.format == Format::Text);
        CHECK(summary(via_text) == summary(from_csv));
        REQUIRE(via_text.lines.size() == from_csv.lines.size());
        for (std::size_t k = 0; k < from_csv.lines.size(); ++k) CHECK(via_text.lines[k].step == from_csv.lines[k].step);
        via_text.plc_info = from_csv.plc_info;   // the text form has no place for it
        CHECK(write_csv(via_text) == write_csv(from_csv));
    }
}

TEST_CASE("round trip of statements, labels and string constants with quotes, blanks and Japanese text") {
    auto source = read_source(";; 起動 \"A\"\nP0:\n$MOV \"x \"\"y\"\" ;z\" D0\nCALL P0\nEND\n", "a.il");
    auto via_csv = read_source(write_csv(source), "a.csv");
    CHECK(summary(via_csv) == summary(source));
    CHECK(summary(via_csv) == Lines{";; 起動 \"A\"", "P0:", "$MOV \"x \"\"y\"\" ;z\" D0", "CALL P0", "END"});
    CHECK(summary(read_source(write_text(via_csv), "a.il")) == summary(source));
}
