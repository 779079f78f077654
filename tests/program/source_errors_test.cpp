// Files the loader refuses (program/source_*.cpp, program/load_text.cpp):
// every refusal is a LoadError naming the file, the row and the problem,
// every problem of the file at once; nothing crashes.
#include <catch2/catch.hpp>

#include "program/source.hpp"
#include "tests/program/source_test_support.hpp"

using namespace slmp::program;
using namespace slmp::program::test;
using Lines = std::vector<std::string>;

namespace {

std::string row(std::string_view step, std::string_view instruction, std::string_view device) {
    return "\"" + std::string(step) + "\"\t\"\"\t\"" + std::string(instruction) + "\"\t\"" + std::string(device) +
           "\"\t\"\"\t\"\"\t\"\"\n";
}

Lines read_problems(const std::string& bytes, const std::string& file) {
    return problems_of([&] { read_source(bytes, file); });
}

}  // namespace

TEST_CASE("a file over 10 MiB is refused by its size") {
    std::string big(10u * 1024 * 1024 + 1, ' ');
    CHECK(read_problems(big, "big.il") == Lines{"big.il: is 10485761 bytes; the limit is 10 MiB (10485760 bytes)"});
    CHECK(problems_of([&] { read_comments(big, "big.csv"); }) ==
          Lines{"big.csv: is 10485761 bytes; the limit is 10 MiB (10485760 bytes)"});
    std::string limit(10u * 1024 * 1024, '\n');
    CHECK(read_source(limit, "limit.il").lines.empty());
}

TEST_CASE("binary and wrongly encoded files are refused by what they are") {
    CHECK(read_problems(std::string("LD X0\n\0\x01\x02", 9), "bin.il") ==
          Lines{"bin.il: is a binary file (a NUL byte at offset 6), not a program or comment list; a UTF-16 file needs "
                "its byte order mark FF FE"});
    CHECK(read_problems("LD X0\nOUT \x82\xA0\n", "sjis.il") ==
          Lines{"sjis.il: is not UTF-8 (byte 0x82 at offset 10); save it as UTF-16LE (Unicode) or UTF-8"});
    CHECK(read_problems("\xED\xA0\x80", "surrogate.il") ==
          Lines{"surrogate.il: is not UTF-8 (byte 0xED at offset 0); save it as UTF-16LE (Unicode) or UTF-8"});
    CHECK(read_problems(std::string("\xFF\xFE\x22\x00\x4D", 5), "odd.csv") ==
          Lines{"odd.csv: is not valid UTF-16LE: an odd number of bytes (5)"});
    CHECK(read_problems(std::string("\xFF\xFE\x22\x00\x00\xDC", 6), "lone.csv") ==
          Lines{"lone.csv: is not valid UTF-16LE: an unpaired surrogate at byte offset 4"});
    CHECK(read_problems("\xFE\xFF", "be.csv") == Lines{"be.csv: is UTF-16 big-endian; save it as UTF-16LE (Unicode) or UTF-8"});
}

TEST_CASE("a CSV list with 8 columns, a continuation row without an instruction and an unclosed quote: all at once") {
    auto file = example_csv_file(row("", "", "K20") + row("0", "LD", "X0") +
                                 "\"1\"\t\"\"\t\"OUT\"\t\"Y0\"\t\"\"\t\"\"\t\"\"\t\"extra\"\n" +
                                 "\"2\"\t\"\"\t\"LD\"\t\"X1\n" + row("3", "$MOV", "\"\"AB") + row("4", "X", "9") +
                                 "\"\"\t\"\"\t\"\"\t\"\"\t\"\"\t\"\"\t\"\"\n" + row("5", "END", "") +
                                 "\"\"\t\"Statement\"\t\"\"\t\"\"\t\"\"\t\"\"\t\"\"\n" + row("", "", "K1"));
    CHECK(read_problems(file, "line1.csv") ==
          Lines{"line1.csv: row 4: operand 'K20' is on a continuation row with no instruction before it",
                "line1.csv: row 6: has 8 fields, a GX Works list has 7",
                "line1.csv: row 7: a quote opens a field and is never closed",
                "line1.csv: row 8 (step 3): a string constant in '\"AB' is not closed; end it with \""});
}

TEST_CASE("a statement between an instruction and its continuation row leaves the operand without an instruction") {
    auto file = example_csv_file(row("0", "OUT", "T0") + "\"\"\t\"note\"\t\"\"\t\"\"\t\"\"\t\"\"\t\"\"\n" + row("", "", "K20"));
    CHECK(read_problems(file, "a.csv") ==
          Lines{"a.csv: row 6: operand 'K20' is on a continuation row with no instruction before it"});
}

TEST_CASE("bad header rows of a list are named") {
    auto file = utf16le_file("\"MAIN\"\t\"X\"\r\n\"PLC Information:\"\t\"RCPU R08\"\t\"more\"\r\n\"Step No.\"\t\"Instruction\"\r\n");
    CHECK(read_problems(file, "h.csv") ==
          Lines{"h.csv: row 1: has 2 fields; a GX Works list starts with the program name alone",
                "h.csv: row 2: has 3 fields; the second row of a GX Works list is 'PLC Information:' and the CPU type",
                "h.csv: row 3: has 2 fields; the column-name row of a GX Works list has 7"});
}

TEST_CASE("bad step numbers: not a number in a list, too large in the text form, alone on a text line") {
    CHECK(read_problems(example_csv_file(row("x1", "LD", "X0")), "s.csv") ==
          Lines{"s.csv: row 4: step number 'x1' is not a decimal number"});
    CHECK(read_problems("99999999999 LD X0\n17\n", "s.il") ==
          Lines{"s.il: line 1: step number '99999999999' is too large",
                "s.il: line 2 (step 17): a step number with no instruction after it"});
}

TEST_CASE("more than 100 000 instructions are refused, naming the limit and the row") {
    std::string text;
    for (int k = 0; k < 100'001; ++k) text += "LD X0\n";
    CHECK(read_problems(text, "long.il") ==
          Lines{"long.il: line 100001: more than 100000 instructions; the limit is 100000"});
    std::string rows;
    for (int k = 0; k < 100'001; ++k) rows += row(std::to_string(k), "LD", "X0");
    CHECK(read_problems(example_csv_file(rows), "long.csv") ==
          Lines{"long.csv: row 100004 (step 100000): more than 100000 instructions; the limit is 100000"});
    text.resize(text.size() - 6);   // 100 000 instructions load
    CHECK(read_source(text, "limit.il").lines.size() == 100'000);
}

TEST_CASE("hostile statements and operands: control characters, megabyte rows, unclosed strings") {
    SECTION("control characters in a statement and an operand") {
        CHECK(read_problems(";; bell\x07\nLD X0\x1B[2J\nLD \"\xC2\x85\"\nEND\n", "h.il") ==
              Lines{"h.il: line 1: holds the control character U+0007; only printable text and TAB may appear",
                    "h.il: line 2: holds the control character U+001B; only printable text and TAB may appear",
                    "h.il: line 3: holds the control character U+0085; only printable text and TAB may appear"});
        CHECK(read_problems(utf16le_file(example_header + "\"\"\t\"a\rb\"\t\"\"\t\"\"\t\"\"\t\"\"\t\"\"\r\n"), "h.csv") ==
              Lines{"h.csv: row 4: holds the control character U+000D; only printable text and TAB may appear"});
        CHECK(read_problems(utf16le_file(example_header + std::string("\"0\"\t\"\"\t\"LD\"\t\"X\0\"\r\n", 18)), "nul.csv") ==
              Lines{"nul.csv: row 4: holds the control character U+0000; only printable text and TAB may appear"});
    }
    SECTION("a megabyte statement") {
        CHECK(read_problems(";; " + std::string(1'000'000, 'A') + "\nEND\n", "h.il") ==
              Lines{"h.il: line 1: is 1000003 bytes long; the limit is 4096 bytes"});
    }
    SECTION("an unclosed string constant in the text form") {
        CHECK(read_problems("$MOV \"ABC D0\n", "h.il") ==
              Lines{"h.il: line 1: a string constant is not closed; end it with \""});
    }
    SECTION("a flood of bad rows reports the first hundred and counts the rest") {
        std::string text;
        for (int k = 0; k < 150; ++k) text += "LD \"X\n";
        auto problems = read_problems(text, "flood.il");
        REQUIRE(problems.size() == 101);
        CHECK(problems[99] == "flood.il: line 100: a string constant is not closed; end it with \"");
        CHECK(problems[100] == "flood.il: ... and 50 more problems");
    }
}

TEST_CASE("a damaged UTF-16 list is still read as a list and says what is wrong") {
    CHECK(read_problems(utf16le_file("LD X0\r\nOUT Y0\r\nEND\r\n"), "t.csv") ==
          Lines{"t.csv: row 3: has 1 field; the column-name row of a GX Works list has 7"});
}

TEST_CASE("LoadError's message is every problem, one a line") {
    try {
        read_source("LD \"X\nLD \"Y\n", "m.il");
        FAIL("loaded");
    } catch (const LoadError& e) {
        CHECK(std::string(e.what()) ==
              "m.il: line 1: a string constant is not closed; end it with \"\n"
              "m.il: line 2: a string constant is not closed; end it with \"");
    }
}
