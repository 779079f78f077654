// The loader (program/source_*.cpp): the worked examples in both forms read
// to the same lines, the GX Works list variants, the text form's grammar and
// the bytes write_csv produces (docs/program.md "Files").
#include <catch2/catch.hpp>

#include "program/source.hpp"
#include "tests/program/source_examples.hpp"
#include "tests/program/source_test_support.hpp"

using namespace slmp::program;
using namespace slmp::program::test;
using Lines = std::vector<std::string>;

TEST_CASE("every worked example reads to the same lines from its text and its UTF-16 CSV form") {
    for (const auto& example : worked_examples) {
        if (example.csv_rows.empty()) continue;
        INFO(example.number << " " << example.title);
        auto text = read_source(example.text, "example.il");
        auto csv = read_source(example_csv_file(example.csv_rows), "example.csv");
        CHECK(text.format == Format::Text);
        CHECK(csv.format == Format::GxWorksCsv);
        CHECK(csv.name == "MAIN");
        CHECK(csv.plc_info == "RCPU R08");
        CHECK(summary(text) == summary(csv));
        CHECK(text.warnings.empty());
        CHECK(csv.warnings.empty());
        REQUIRE(!text.lines.empty());
        CHECK(text.lines.back().mnemonic == "END");
    }
}

TEST_CASE("the worked examples read to exactly the lines the specification lists") {
    CHECK(summary(read_source(worked_examples[0].text, "a.il")) == Lines{"LD X0", "OR Y0", "ANI X1", "OUT Y0", "END"});
    CHECK(summary(read_source(example_csv_file(worked_examples[5].csv_rows), "a.csv")) ==
          Lines{"LD X0", "CJ P10", "LD X1", "OUT Y0", "LD SM400", "INC D1", "P10:", "LD SM400", "INC D2", "END"});
    CHECK(summary(read_source(example_csv_file(worked_examples[8].csv_rows), "a.csv")) ==
          Lines{"LD SM400", "/ K36 K-5 D0", "/ K-36 K5 D2", "* K300 K400 D4", "D/ K100000 K7 D6", "BCD K1234 D20",
                "BIN H0987 D21", "DBCD K12345678 D22", "END"});
    CHECK(summary(read_source(worked_examples[14].text, "wdt.il")) == Lines{"P0:", "LD SM400", "CJ P0", "END"});
    CHECK(worked_examples[3].text.find("OUT Y3\nEND") != std::string_view::npos);   // 8.4 spans two spec lines
}

TEST_CASE("CSV rows, steps and kinds are the file's: continuation rows count as rows") {
    auto source = read_source(example_csv_file(worked_examples[1].csv_rows), "line1.csv");   // 8.2
    REQUIRE(source.lines.size() == 5);
    CHECK(source.lines[1].mnemonic == "OUT");
    CHECK(source.lines[1].operands == Lines{"T0", "K20"});
    CHECK(source.lines[1].row == 5);
    CHECK(source.lines[1].step == 1u);
    CHECK(source.lines[2].row == 7);   // row 6 is the K20 continuation
    CHECK(source.lines[2].step == 5u);
    CHECK(source.lines[4].step == 7u);
    CHECK(source.lines[4].kind == SourceLine::Kind::Instruction);
}

TEST_CASE("text lines are numbered from 1 counting blank and comment lines, steps are optional") {
    auto source = read_source("; self-hold\n\nLD X0\n  // comment\n10 OR Y0 ; note\nEND\n", "line1.il");
    REQUIRE(source.lines.size() == 3);
    CHECK(source.lines[0].row == 3);
    CHECK_FALSE(source.lines[0].step.has_value());
    CHECK(source.lines[1].row == 5);
    CHECK(source.lines[1].step == 10u);
    CHECK(source.lines[1].operands == Lines{"Y0"});
    CHECK(source.lines[2].row == 6);
}

TEST_CASE("the text form: * is a mnemonic, ,, a statement, P10 and P10: labels, string constants keep blanks and quotes") {
    auto source = read_source(
        ";; Motor 1 start\n"
        "ld x0\n"
        "* K300 K400 D4\n"
        "$MOV \"A B;C//D\" D0 ; copy\n"
        "$MOV \"say \"\"hi\"\"\" D10\n"
        "P10\n"
        "P11:\n"
        "P12: LD X1\n"
        "P13: P14: 7 LD X2\n"
        "\tOUT\tT0\tK20\r\n"
        "END\n",
        "t.il");
    CHECK(summary(source) == Lines{";; Motor 1 start", "ld x0", "* K300 K400 D4", "$MOV \"A B;C//D\" D0",
                                   "$MOV \"say \"\"hi\"\"\" D10", "P10:", "P11:", "P12:", "LD X1", "P13:", "P14:", "LD X2", "OUT T0 K20", "END"});
    CHECK(source.lines[11].step == 7u);
    CHECK(source.lines[0].kind == SourceLine::Kind::Statement);
    CHECK(source.lines[5].kind == SourceLine::Kind::Pointer);
    CHECK(source.lines[6].mnemonic == "P11");
    CHECK(source.lines[7].row == 8);
    CHECK(source.lines[8].row == 8);
}

TEST_CASE("a CSV list is recognised without a BOM, with a UTF-8 BOM, with commas and with LF line ends") {
    std::string rows = example_header + crlf(worked_examples[1].csv_rows);
    Lines expected{"LD X0", "OUT T0 K20", "LD T0", "OUT Y0", "END"};
    SECTION("UTF-8 without BOM") {
        auto s = read_source(rows, "a.csv");
        CHECK(s.format == Format::GxWorksCsv);
        CHECK(summary(s) == expected);
    }
    SECTION("UTF-8 with BOM") { CHECK(summary(read_source("\xEF\xBB\xBF" + rows, "a.csv")) == expected); }
    SECTION("commas, LF only, unquoted fields") {
        auto s = read_source(
            "MAIN\nPLC Information:,RCPU R08\nStep No.,Line Statement,Instruction,I/O(Device),Blank,PI Statement,Note\n"
            "0,,LD,X0,,,\n1,,OUT,T0,,,\n,,,K20,,,\n5,,LD,T0,,,\n6,,OUT,Y0,,,\n7,,END,,,,\n",
            "a.csv");
        CHECK(s.format == Format::GxWorksCsv);
        CHECK(s.plc_info == "RCPU R08");
        CHECK(summary(s) == expected);
    }
    SECTION("a text program with a UTF-8 BOM stays text") {
        auto s = read_source("\xEF\xBB\xBFLD X0\nOUT T0 K20\nLD T0\nOUT Y0\nEND\n", "a.il");
        CHECK(s.format == Format::Text);
        CHECK(summary(s) == expected);
    }
}

TEST_CASE("all operands in one cell (the [G-C] layout) are split outside string constants") {
    auto s = read_source(utf16le_file("\"(FX3U Retry Verification Suite)\"\r\n\"PLC Information:\"\t\"FXCPU FX3U/FX3UC\"\r\n"
                                      "\"Step No.\"\t\"Line Statement\"\t\"Instruction\"\t\"I/O(Device)\"\t\"Blank\"\t\"PI Statement\"\t\"Note\"\r\n"
                                      "\"0\"\t\"\"\t\"LD\"\t\"X0\"\t\"\"\t\"\"\t\"\"\r\n"
                                      "\"1\"\t\"\"\t\"SFTL\"\t\"M200 M210 K8 K1\"\t\"\"\t\"\"\t\"\"\r\n"
                                      "\"10\"\t\"\"\t\"$MOV\"\t\"\"\"A B\"\" D0\"\t\"\"\t\"\"\t\"\"\r\n"
                                      "\"\"\t\"\"\t\"\"\t\"D9 D10\"\t\"\"\t\"\"\t\"\"\r\n"
                                      "\"20\"\t\"\"\t\"END\"\t\"\"\t\"\"\t\"\"\t\"\"\r\n"),
                         "gc.csv");
    CHECK(s.name == "FX3U Retry Verification Suite");
    CHECK(s.plc_info == "FXCPU FX3U/FX3UC");
    CHECK(summary(s) == Lines{"LD X0", "SFTL M200 M210 K8 K1", "$MOV \"A B\" D0 D9 D10", "END"});
}

TEST_CASE("a re-quoted record (one quoted field holding TABs and doubled quotes) is parsed again") {
    // What a comma-CSV tool writes when it re-saves the TAB file, both shapes.
    auto s = read_source(utf16le_file("\"MAIN\"\r\n"
                                      "\"PLC Information:\"\t\"QCPU (Q mode) Q03UDV\"\r\n"
                                      "\"\"\"Step No.\"\"\t\"\"Line Statement\"\"\t\"\"Instruction\"\"\t\"\"I/O(Device)\"\"\t"
                                      "\"\"Blank\"\"\t\"\"PI Statement\"\"\t\"\"Note\"\"\"\r\n"
                                      "\"0\t\"\"\"\"\t\"\"LD\"\"\t\"\"X0\"\"\t\"\"\"\"\t\"\"\"\"\t\"\"\"\"\"\r\n"
                                      "\"\"\"1\"\"\t\"\"\"\"\t\"\"$MOV\"\"\t\"\"\"\"\"\"ABC\"\"\"\"\"\"\t\"\"\"\"\t\"\"\"\"\t\"\"\"\"\"\r\n"
                                      "\"\t\t\tD0\t\t\t\"\r\n"
                                      "\"\"\"5\"\"\t\"\"\"\"\t\"\"END\"\"\t\"\"\"\"\t\"\"\"\"\t\"\"\"\"\t\"\"\"\"\"\r\n"),
                         "requoted.csv");
    CHECK(s.plc_info == "QCPU (Q mode) Q03UDV");
    CHECK(summary(s) == Lines{"LD X0", "$MOV \"ABC\" D0", "END"});
    CHECK(s.lines[1].step == 1u);
}

TEST_CASE("Japanese column names and the 機種情報 row are read like the English ones") {
    auto s = read_source(utf16le_file("\"E5482L_220317\"\r\n\"機種情報\"\t\"RCPU R16N\"\r\n"
                                      "\"ステップ番号\"\t\"行間ステートメント\"\t\"命令\"\t\"I/Oデバイス\"\t\"空欄\"\t\"PIステートメント\"\t\"ノート\"\r\n"
                                      "\"0\"\t\"起動 回路\"\t\"\"\t\"\"\t\"\"\t\"\"\t\"\"\r\n"
                                      "\"0\"\t\"\"\t\"LD\"\t\"X0\"\t\"\"\t\"\"\t\"\"\r\n"
                                      "\"1\"\t\"\"\t\"OUT\"\t\"Y0\"\t\"\"\t\"\"\t\"モーター\"\r\n"
                                      "\"2\"\t\"\"\t\"END\"\t\"\"\t\"\"\t\"\"\t\"\"\r\n"),
                         "jp.csv");
    CHECK(s.name == "E5482L_220317");
    CHECK(s.plc_info == "RCPU R16N");
    CHECK(summary(s) == Lines{";; 起動 回路", "LD X0", "OUT Y0", "END"});
    CHECK(s.lines[0].step == 0u);   // a statement may carry the next instruction's step
    CHECK(s.lines[2].note == "モーター");
    CHECK(s.warnings.empty());
}

TEST_CASE("statement and pointer rows, a PI statement and a note are kept, never executed") {
    auto s = read_source(example_csv_file("\"\"\t\"Start\"\t\"\"\t\"\"\t\"\"\t\"\"\t\"\"\n"
                                          "\"0\"\t\"\"\t\"LD\"\t\"X0\"\t\"\"\t\"\"\t\"\"\n"
                                          "\"1\"\t\"\"\t\"CJ\"\t\"P10\"\t\"\"\t\"\"\t\"\"\n"
                                          "\"3\"\t\"\"\t\"P10\"\t\"\"\t\"\"\t\"jump here\"\t\"\"\n"
                                          "\"4\"\t\"\"\t\"END\"\t\"\"\t\"\"\t\"\"\t\"\"\n"),
                         "p.csv");
    REQUIRE(s.lines.size() == 5);
    CHECK(s.lines[0].kind == SourceLine::Kind::Statement);
    CHECK(s.lines[0].statement == "Start");
    CHECK_FALSE(s.lines[0].step.has_value());
    CHECK(s.lines[3].kind == SourceLine::Kind::Pointer);
    CHECK(s.lines[3].mnemonic == "P10");
    CHECK(s.lines[3].note == "jump here");
    CHECK(s.lines[3].step == 3u);
}

TEST_CASE("the program name loses one pair of parentheses, an empty one is MAIN") {
    CHECK(read_source(utf16le_file("\"(MAIN2)\"\r\n\"PLC Information:\"\t\"RCPU R08\"\r\n" + example_header.substr(example_header.find("\"Step")) +
                                   "\"0\"\t\"\"\t\"END\"\t\"\"\t\"\"\t\"\"\t\"\"\r\n"),
                      "n.csv")
              .name == "MAIN2");
    CHECK(read_source(utf16le_file("\"\"\r\n\"PLC Information:\"\t\"\"\r\n" + example_header.substr(example_header.find("\"Step"))),
                      "n.csv")
              .name == "MAIN");
}

TEST_CASE("warnings: text after the first END is ignored, step numbers that do not increase are named") {
    SECTION("CSV") {
        auto s = read_source(example_csv_file("\"0\"\t\"\"\t\"LD\"\t\"X0\"\t\"\"\t\"\"\t\"\"\n"
                                              "\"5\"\t\"\"\t\"OUT\"\t\"Y0\"\t\"\"\t\"\"\t\"\"\n"
                                              "\"3\"\t\"\"\t\"END\"\t\"\"\t\"\"\t\"\"\t\"\"\n"
                                              "\"4\"\t\"\"\t\"LD\"\t\"X1\"\t\"\"\t\"\"\t\"\"\n"
                                              "\"5\"\t\"\"\t\"MOVV\"\t\"X1\"\t\"\"\t\"\"\t\"\"\n"),
                             "line1.csv");
        CHECK(summary(s) == Lines{"LD X0", "OUT Y0", "END"});
        CHECK(s.warnings ==
              Lines{"line1.csv: row 6 (step 3): step number 3 does not increase (row 5 has step 5); rows run in file order",
                    "line1.csv: row 7: text after END is ignored"});
    }
    SECTION("text") {
        auto s = read_source("LD X0\nEND\n\n; fine\nLD X1\nOUT Y1\n", "line1.il");
        CHECK(summary(s) == Lines{"LD X0", "END"});
        CHECK(s.warnings == Lines{"line1.il: line 5: text after END is ignored"});
    }
    SECTION("no END is the compiler's to report") {
        CHECK(summary(read_source("LD X0\nOUT Y0\n", "a.il")) == Lines{"LD X0", "OUT Y0"});
    }
}

TEST_CASE("an empty file is an empty text program") {
    auto s = read_source("", "empty.il");
    CHECK(s.format == Format::Text);
    CHECK(s.lines.empty());
}

TEST_CASE("spreadsheet leftovers: empty trailing fields in rows 1 and 2, short data rows, blank rows") {
    auto s = read_source(
        "MAIN,,,,,,\r\nPLC Information:,QCPU (Q mode) Q03UDV,,,,,\r\nStep No.,Line Statement,Instruction,I/O(Device),Blank,PI Statement,Note\r\n"
        "0,,LD,X0\r\n\r\n,,,,,,\r\n1,,OUT,T0\r\n,,,K20\r\n5,,END\r\n",
        "sheet.csv");
    CHECK(s.name == "MAIN");
    CHECK(s.plc_info == "QCPU (Q mode) Q03UDV");
    CHECK(summary(s) == Lines{"LD X0", "OUT T0 K20", "END"});
    CHECK(s.lines[1].row == 7);
    CHECK(s.warnings.empty());
}
