// read_comments (program/device_comments.cpp): GX Works2's TAB file and
// GX Converter's device,label,comment CSV; hostile files are refused by name.
#include <catch2/catch.hpp>

#include "program/source.hpp"
#include "tests/program/source_test_support.hpp"

using namespace slmp::program;
using namespace slmp::program::test;
using Lines = std::vector<std::string>;

namespace {

Lines flat(const std::vector<DeviceComment>& comments) {
    Lines out;
    for (const auto& c : comments) out.push_back(c.device + "=" + c.comment);
    return out;
}

}  // namespace

TEST_CASE("GX Works2's UTF-16LE comment file: title row, column names, one device a row") {
    auto file = utf16le_file("\"Device Comment\"\r\n\"Device Name\"\t\"Comment\"\r\n\"X0A1\"\t\"STOP PB L0\"\r\n"
                             "\"Y0\"\t\"モーター 1 \"\"運転\"\"\"\r\n\"M0\"\t\"\"\r\n\"D0.F\"\t\"" + std::string(40, 'W') + "\"\r\n");
    CHECK(flat(read_comments(file, "c.csv")) ==
          Lines{"X0A1=STOP PB L0", "Y0=モーター 1 \"運転\"", "D0.F=" + std::string(40, 'W')});
}

TEST_CASE("GX Converter's device,label,comment CSV, UTF-8: the comment, else the label, neither: omitted") {
    auto file = "Device,Label,Comment\nX0,START,Start button\nX1,STOP,\nY0,,\"Lamp, red\"\nU3E0\\G10,,Buffer\nM5,,\n";
    CHECK(flat(read_comments(file, "c.csv")) == Lines{"X0=Start button", "X1=STOP", "Y0=Lamp, red", "U3E0\\G10=Buffer"});
    CHECK(flat(read_comments("\xEF\xBB\xBF" "Device,Comment\r\nX0,Start\r\n", "c.csv")) == Lines{"X0=Start"});
}

TEST_CASE("hostile comment files are refused with the row and the problem") {
    auto problems = problems_of([] {
        read_comments(utf16le_file("\"Device Comment\"\r\n\"Device Name\"\t\"Comment\"\r\n"
                                   "\"X0\"\t\"bell\x07\"\r\n"
                                   "\"<script>alert(1)</script>\"\t\"x\"\r\n"
                                   "\"\"\t\"orphan\"\r\n"
                                   "\"Y0\"\t\"" + std::string(5000, 'A') + "\"\r\n"
                                   "\"Y1\"\t\"open\r\n"),
                      "c.csv");
    });
    CHECK(problems == Lines{"c.csv: row 3: holds the control character U+0007; only printable text and TAB may appear",
                            "c.csv: row 4: '<script>alert(1)</script>' is no device name (letters, digits, '.' or '\\', "
                            "at most 16 characters)",
                            "c.csv: row 5: the comment 'orphan' names no device",
                            "c.csv: row 6: is 5007 bytes long; the limit is 4096 bytes",
                            "c.csv: row 7: a quote opens a field and is never closed"});
    CHECK(problems_of([] { read_comments(std::string("\0\0", 2), "b.bin"); }).size() == 1);
    CHECK(problems_of([] { read_comments(std::string("\xFF\xFE\x00\xD8", 4), "b.csv"); }) ==
          Lines{"b.csv: is not valid UTF-16LE: an unpaired surrogate at byte offset 2"});
    CHECK(read_comments("", "empty.csv").empty());
}

TEST_CASE("characters beyond the BMP (UTF-16 surrogate pairs) and long comments are kept as written") {
    auto file = utf16le_file("\"Title\"\r\n\"Device Name\"\t\"Comment\"\r\n\"M10\"\t\"Alarm 🚨 \u30a2\u30e9\u30fc\u30e0\"\r\n"
                             "\"D100\"\t\"" + std::string(100, 'x') + "\"\t\"\"\r\n");
    CHECK(flat(read_comments(file, "c.csv")) == Lines{"M10=Alarm 🚨 アラーム", "D100=" + std::string(100, 'x')});
}
