// Label access 041A/141A/041C/141B (SLMP Reference Manual §5.3): every
// worked example byte for byte in all four frame shapes, round trips of every
// data type through both command pairs with the device view checked by 0401,
// the error table (end code and memory unchanged), and the families that
// refuse label commands (§12).
#include "support/labels.hpp"

#include "devicemodel/snapshot.hpp"

using namespace slmp;
using namespace slmp::test;

namespace {

// The manuals' labels. "Lbl" is a 16-bit array in examples 2 (type ID 02) and
// a bit array in example 1, so each example gets its own CPU.
const char* kWordLbl = R"J({"labels": [{"name": "Lbl", "type": "Word [Unsigned]/Bit String [16-bit](0..9)"}]})J";
const char* kBitLbl = R"J({"labels": [{"name": "Lbl", "type": "Bit(0..9)"}]})J";
// Example 3: Typ1.led and Typ1.No. The manual prints type ID 03 for No while
// its data are two words (§2.7 "Manual inconsistency"); slmp-sim answers the
// label's real type, so No is declared as words and the vector carries 02.
const char* kTyp1 = R"J({"structures": [{"name": "T1Type", "members": [
                          {"name": "led", "type": "Word [Unsigned]/Bit String [16-bit]", "dims": [10]},
                          {"name": "No", "type": "Word [Unsigned]/Bit String [16-bit]", "dims": [10]}]}],
                        "labels": [{"name": "Typ1", "type": "T1Type"}]})J";
// 041C/141B: LabelB (bit), LabelW (word, ID 02) and Sw.led (word member).
const char* kRandom = R"J({"structures": [{"name": "SwType", "members": [{"name": "led", "type": "WORD"}]}],
                          "labels": [{"name": "LabelB", "type": "Bit", "device": "M100"},
                                     {"name": "LabelW", "type": "UINT", "device": "D9000"},
                                     {"name": "Sw", "type": "SwType"}]})J";

const auto kAll = {kBinary3E, kBinary4E, kAscii3E, kAscii4E};

std::vector<std::uint16_t> read_d(devicemodel::Cpu& cpu, std::uint32_t from, std::size_t n) {
    std::vector<std::uint16_t> out(n);
    cpu.memory().read_words(*devicemodel::find_by_symbol("D"), from, out);
    return out;
}

}  // namespace

TEST_CASE("§2.7 041A example 1: bit array Lbl[2], 2 bits", "[labels][spec]") {
    auto wire = GENERATE(values<Wire>(kAll));
    auto cpu = cpu_with_labels(kBitLbl);
    const Payload req{"1A 04 00 00 01 00 00 00 06 00 4C 00 62 00 6C 00 5B 00 32 00 5D 00 00 00 02 00",
                      "041A0000000100000006004C0062006C005B0032005D00000002"};
    CHECK(wire.data(array_read_req({{"Lbl[2]", 0, 2}})) == wire.data(req));
    CHECK(wire.exchange(cpu, random_label_write_req({{"Lbl[3]", 2, word(1)}})) == wire.expect(ok()));
    CHECK(wire.exchange(cpu, req) == wire.expect(ok(Payload{"01 00 01 00 02 00 02 00", "0001010000020002"})));
}

TEST_CASE("§2.7 041A example 2: word array Lbl[2], 5 words", "[labels][spec]") {
    auto wire = GENERATE(values<Wire>(kAll));
    auto cpu = cpu_with_labels(kWordLbl);
    const Payload req{"1A 04 00 00 01 00 00 00 06 00 4C 00 62 00 6C 00 5B 00 32 00 5D 00 01 00 0A 00",
                      "041A0000000100000006004C0062006C005B0032005D0100000A"};
    CHECK(wire.data(array_read_req({{"Lbl[2]", 1, 10}})) == wire.data(req));
    CHECK(wire.exchange(cpu, array_write_req({{"Lbl[2]", 1, 10, words({0x44, 0x61, 0x74, 0x61, 0x31})}})) ==
          wire.expect(ok()));
    CHECK(wire.exchange(cpu, req) ==
          wire.expect(ok(Payload{"01 00 02 01 0A 00 44 00 61 00 74 00 61 00 31 00", "00010201000A00440061007400610031"})));
}

TEST_CASE("§2.7 041A example 3: structure members with the abbreviation %1 = Typ1", "[labels][spec]") {
    auto wire = GENERATE(values<Wire>(kAll));
    auto cpu = cpu_with_labels(kTyp1);
    const Payload req{"1A 04 00 00 02 00 01 00 04 00 54 00 79 00 70 00 31 00 09 00 25 00 31 00 2E 00 6C 00 65 00 64 "
                      "00 5B 00 32 00 5D 00 01 00 08 00 08 00 25 00 31 00 2E 00 4E 00 6F 00 5B 00 31 00 5D 00 01 00 "
                      "04 00",
                      "041A000000020001"
                      "00040054007900700031"
                      "000900250031002E006C00650064005B0032005D01000008"
                      "000800250031002E004E006F005B0031005D01000004"};
    CHECK(wire.data(array_read_req({{"%1.led[2]", 1, 8}, {"%1.No[1]", 1, 4}}, {"Typ1"})) == wire.data(req));
    REQUIRE(wire.exchange(cpu, array_write_req({{"Typ1.led[2]", 1, 8, words({0x31, 0x32, 0x33, 0x34})},
                                                {"Typ1.No[1]", 1, 4, words({0x30, 0x31})}})) == wire.expect(ok()));
    // The manual's second entry says 03; the label is 16-bit, so 02 (see kTyp1).
    CHECK(wire.exchange(cpu, req) == wire.expect(ok(Payload{"02 00 02 01 08 00 31 00 32 00 33 00 34 00 02 01 04 00 30 00 31 00",
                                                            "0002" "02" "01" "0008" "0031003200330034"
                                                            "02" "01" "0004" "00300031"})));
}

TEST_CASE("§2.8 141A example 1: bit array Lbl[2], writing 0 then 1", "[labels][spec]") {
    auto wire = GENERATE(values<Wire>(kAll));
    auto cpu = cpu_with_labels(kBitLbl);
    REQUIRE(wire.exchange(cpu, random_label_write_req({{"Lbl[2]", 2, word(1)}})) == wire.expect(ok()));
    const Payload req{"1A 14 00 00 01 00 00 00 06 00 4C 00 62 00 6C 00 5B 00 32 00 5D 00 00 00 02 00 02 00",
                      "141A0000000100000006004C0062006C005B0032005D000000020002"};
    CHECK(wire.data(array_write_req({{"Lbl[2]", 0, 2, word(2)}})) == wire.data(req));
    CHECK(wire.exchange(cpu, req) == wire.expect(ok()));
    CHECK(wire.exchange(cpu, array_read_req({{"Lbl[0]", 0, 6}})) ==
          wire.expect(ok(word(1) + byte(1) + byte(0) + word(6) + word(0b001000))));
}

TEST_CASE("§2.8 141A example 2: word array Lbl[2], 5 words (the bytes, not the prose)", "[labels][spec]") {
    auto wire = GENERATE(values<Wire>(kAll));
    auto cpu = cpu_with_labels(kWordLbl);
    const Payload req{"1A 14 00 00 01 00 00 00 06 00 4C 00 62 00 6C 00 5B 00 32 00 5D 00 01 00 0A 00 44 00 61 00 74 "
                      "00 61 00 31 00",
                      "141A" "0000" "0001" "0000" "0006" "004C0062006C005B0032005D" "01" "00" "000A"
                      "0044" "0061" "0074" "0061" "0031"};
    CHECK(wire.exchange(cpu, req) == wire.expect(ok()));
    CHECK(wire.exchange(cpu, random_label_read_req({"Lbl[2]", "Lbl[6]"})) ==
          wire.expect(ok(word(2) + byte(2) + byte(0) + word(2) + word(0x44) + byte(2) + byte(0) + word(2) + word(0x31))));
}

TEST_CASE("§2.8 141A example 3: Typ1.led[5] and Typ1.No[7] through %1", "[labels][spec]") {
    auto wire = GENERATE(values<Wire>(kAll));
    auto cpu = cpu_with_labels(kTyp1);
    const Payload req{"1A 14 00 00 02 00 01 00 04 00 54 00 79 00 70 00 31 00 09 00 25 00 31 00 2E 00 6C 00 65 00 64 "
                      "00 5B 00 35 00 5D 00 01 00 08 00 34 12 78 56 BC 9A F0 DE 08 00 25 00 31 00 2E 00 4E 00 6F 00 "
                      "5B 00 37 00 5D 00 01 00 04 00 34 12 78 56",
                      "141A00000002000100040054007900700031000900250031002E006C00650064005B0035005D01000008123456789A"
                      "BCDEF0000800250031002E004E006F005B0037005D0100000412345678"};
    CHECK(wire.data(array_write_req({{"%1.led[5]", 1, 8, words({0x1234, 0x5678, 0x9ABC, 0xDEF0})},
                                     {"%1.No[7]", 1, 4, words({0x1234, 0x5678})}},
                                    {"Typ1"})) == wire.data(req));
    CHECK(wire.exchange(cpu, req) == wire.expect(ok()));
    CHECK(wire.exchange(cpu, array_read_req({{"Typ1.led[5]", 1, 8}, {"Typ1.No[7]", 1, 4}})) ==
          wire.expect(ok(word(2) + byte(2) + byte(1) + word(8) + words({0x1234, 0x5678, 0x9ABC, 0xDEF0}) + byte(2) +
                         byte(1) + word(4) + words({0x1234, 0x5678}))));
}

TEST_CASE("§2.9 041C example: LabelB, LabelW, Sw.led (spare answered 00)", "[labels][spec]") {
    auto wire = GENERATE(values<Wire>(kAll));
    auto cpu = cpu_with_labels(kRandom);
    cpu.memory().set_bit(*devicemodel::find_by_symbol("M"), 100, true);
    cpu.memory().set_value(*devicemodel::find_by_symbol("D"), 9000, 0x44);
    REQUIRE(wire.exchange(cpu, random_label_write_req({{"Sw.led", 2, word(0x31)}})) == wire.expect(ok()));
    const Payload req{"1C 04 00 00 03 00 00 00 06 00 4C 00 61 00 62 00 65 00 6C 00 42 00 06 00 4C 00 61 00 62 00 65 00 "
                      "6C 00 57 00 06 00 53 00 77 00 2E 00 6C 00 65 00 64 00",
                      "041C" "0000" "0003" "0000" "0006" "004C006100620065006C0042" "0006" "004C006100620065006C0057"
                      "0006" "00530077002E006C00650064"};
    CHECK(wire.data(random_label_read_req({"LabelB", "LabelW", "Sw.led"})) == wire.data(req));
    CHECK(wire.exchange(cpu, req) ==
          wire.expect(ok(Payload{"03 00 01 00 02 00 01 00 02 00 02 00 44 00 02 00 02 00 31 00",
                                 "0003" "01" "00" "0002" "0001" "02" "00" "0002" "0044" "02" "00" "0002" "0031"})));
}

TEST_CASE("§2.10 141B example: LabelB=ON, LabelW=0031H, Sw.led=0001H, and D9000 and M100 agree", "[labels][spec]") {
    auto wire = GENERATE(values<Wire>(kAll));
    auto cpu = cpu_with_labels(kRandom);
    const Payload req{"1B 14 00 00 03 00 00 00 06 00 4C 00 61 00 62 00 65 00 6C 00 42 00 02 00 01 00 06 00 4C 00 61 00 "
                      "62 00 65 00 6C 00 57 00 02 00 31 00 06 00 53 00 77 00 2E 00 6C 00 65 00 64 00 02 00 01 00",
                      "141B0000000300000006004C006100620065006C0042000200010006004C006100620065006C005700020031000600"
                      "530077002E006C0065006400020001"};
    CHECK(wire.data(random_label_write_req({{"LabelB", 2, word(1)}, {"LabelW", 2, word(0x31)}, {"Sw.led", 2, word(1)}})) ==
          wire.data(req));
    CHECK(wire.exchange(cpu, req) == wire.expect(ok()));
    CHECK(wire.exchange(cpu, read_words_req(Form::IQR, "D9000", 1)) == wire.expect(ok(words({0x31}))));
    CHECK(wire.exchange(cpu, read_bits_req(Form::IQR, "M100", 1)) == wire.expect(ok(bits({1}))));
    // And the other way: 1401 to D9000, the label reads it.
    CHECK(wire.exchange(cpu, write_words_req(Form::Q, "D9000", {0xBEEF})) == wire.expect(ok()));
    CHECK(wire.exchange(cpu, random_label_read_req({"LabelW"})) ==
          wire.expect(ok(word(1) + byte(2) + byte(0) + word(2) + word(0xBEEF))));
}

TEST_CASE("§2.9 the data type IDs: 10 is 0A, TIME 7FFFFFFF is one 32-bit value", "[labels][spec]") {
    auto wire = GENERATE(values<Wire>(kAll));
    auto cpu = cpu_with_labels(R"J({"labels": [{"name": "U", "type": "String [Unicode](3)"},
                                               {"name": "Tm", "type": "Time"}]})J");
    REQUIRE(wire.exchange(cpu, random_label_write_req({{"U", 8, words({0x41, 0x41, 0x41, 0})}, {"Tm", 4, dword(0x7FFFFFFF)}})) ==
            wire.expect(ok()));
    CHECK(wire.exchange(cpu, random_label_read_req({"U", "Tm"})) ==
          wire.expect(ok(Payload{"02 00 0A 00 08 00 41 00 41 00 41 00 00 00 08 00 04 00 FF FF FF 7F",
                                 "0002" "0A" "00" "0008" "0041004100410000" "08" "00" "0004" "7FFFFFFF"})));
}

// ---------------------------------------------------------------------------
// Every data type through both command pairs, assigned to D (checked by 0401)
// and in the label area.

namespace {

struct TypeCase {
    std::string type;
    std::uint8_t id;
    std::uint16_t length;                 // bytes of one value
    Payload value;                        // one value as the wire carries it
    std::vector<std::uint16_t> device;    // the same value as D words
};

std::vector<TypeCase> type_cases() {
    return {
        {"Word [Signed]", 4, 2, word(0x8001), {0x8001}},
        {"INT", 4, 2, word(0x7FFF), {0x7FFF}},
        {"Word [Unsigned]/Bit String [16-bit]", 2, 2, word(0xFFFF), {0xFFFF}},
        {"Double Word [Signed]", 5, 4, dword(0x80000001), {0x0001, 0x8000}},
        {"DWORD", 3, 4, dword(0x12345678), {0x5678, 0x1234}},
        {"FLOAT [Single Precision]", 6, 4, dword(0x3FC00000), {0x0000, 0x3FC0}},   // 1.5
        {"LREAL", 7, 8, qword(0x3FF8000000000000ull), {0, 0, 0, 0x3FF8}},           // 1.5
        {"Time", 8, 4, dword(0x7FFFFFFF), {0xFFFF, 0x7FFF}},
        {"String(5)", 9, 6, words({0x4241, 0x4443, 0x0045}), {0x4241, 0x4443, 0x0045}},   // "ABCDE" + NUL
        {"STRING[4]", 9, 6, words({0x4241, 0x4443, 0x0000}), {0x4241, 0x4443, 0x0000}},   // "ABCD" + NUL + pad
        {"String [Unicode](3)", 10, 8, words({0x0041, 0x3042, 0x0043, 0}), {0x0041, 0x3042, 0x0043, 0}},
    };
}

}  // namespace

TEST_CASE("round trip: every basic type × 141B/041C and 141A/041A, on D and in the label area", "[labels]") {
    auto wire = GENERATE(values<Wire>(kAll));
    for (const auto& t : type_cases()) {
        CAPTURE(t.type);
        const auto config = "{\"labels\": [{\"name\": \"OnD\", \"type\": \"" + t.type + "\", \"device\": \"D500\"}, "
                            "{\"name\": \"InArea\", \"type\": \"" + t.type + "\"}, "
                            "{\"name\": \"Arr\", \"type\": \"" + t.type + "\", \"dims\": [3], \"device\": \"D600\"}]}";
        auto cpu = cpu_with_labels(config);
        for (const std::string name : {"OnD", "InArea"}) {
            CAPTURE(name);
            CHECK(wire.exchange(cpu, random_label_write_req({{name, t.length, t.value}})) == wire.expect(ok()));
            CHECK(wire.exchange(cpu, random_label_read_req({name})) ==
                  wire.expect(ok(word(1) + byte(t.id) + byte(0) + word(t.length) + t.value)));
            CHECK(wire.exchange(cpu, array_read_req({{name, 1, t.length}})) ==
                  wire.expect(ok(word(1) + byte(t.id) + byte(1) + word(t.length) + t.value)));
        }
        CHECK(read_d(cpu, 500, t.device.size()) == t.device);
        // 141A to elements 1..2 of Arr; 0401 sees them right after element 0.
        const auto n = static_cast<std::uint32_t>(t.device.size());
        CHECK(wire.exchange(cpu, array_write_req({{"Arr[1]", 1, static_cast<std::uint16_t>(2 * t.length), t.value + t.value}})) ==
              wire.expect(ok()));
        CHECK(wire.exchange(cpu, array_read_req({{"Arr[0]", 1, static_cast<std::uint16_t>(3 * t.length)}})) ==
              wire.expect(ok(word(1) + byte(t.id) + byte(1) + word(static_cast<std::uint16_t>(3 * t.length)) +
                             words(std::vector<std::uint16_t>(n, 0)) + t.value + t.value)));
        std::vector<std::uint16_t> expected(n, 0);
        expected.insert(expected.end(), t.device.begin(), t.device.end());
        expected.insert(expected.end(), t.device.begin(), t.device.end());
        CHECK(read_d(cpu, 600, 3 * n) == expected);
        // 1401 to D600 (element 0), then 041C reads Arr[0].
        CHECK(wire.exchange(cpu, write_words_req(Form::Q, "D600", t.device)) == wire.expect(ok()));
        CHECK(wire.exchange(cpu, random_label_read_req({"Arr[0]"})) ==
              wire.expect(ok(word(1) + byte(t.id) + byte(0) + word(t.length) + t.value)));
    }
}

TEST_CASE("names: nested structures, arrays of structures, 2-D/3-D, k/h indexes, timers, %n.%m", "[labels]") {
    auto wire = GENERATE(values<Wire>(kAll));
    auto cpu = cpu_with_labels(R"J({
        "structures": [
            {"name": "Valve", "members": [{"name": "Open", "type": "Bit"}, {"name": "Pos", "type": "INT"}]},
            {"name": "TankT", "members": [{"name": "Level", "type": "REAL"}, {"name": "V", "type": "Valve", "dims": [2]},
                                          {"name": "Flags", "type": "Bit(0..19)"}, {"name": "Delay", "type": "Timer"}]},
            {"name": "Step", "members": [{"name": "Speed", "type": "INT"}, {"name": "Name", "type": "String(6)"}]}],
        "labels": [
            {"name": "Tank1", "type": "TankT"},
            {"name": "Recipe", "type": "Step(0..4)", "device": "D2000"},
            {"name": "A", "type": "Word [Signed](0..1,0..19)"},
            {"name": "Cube", "type": "DINT", "dims": [2, 3, 4], "device": "ZR100"},
            {"name": "T1", "type": "Timer", "device": "T5"},
            {"name": "LT1", "type": "Long Timer", "device": "LT2"}]})J");
    auto check_word = [&](const std::string& name, std::uint16_t value) {
        CAPTURE(name);
        CHECK(wire.exchange(cpu, random_label_write_req({{name, 2, word(value)}})) == wire.expect(ok()));
        CHECK(wire.exchange(cpu, random_label_read_req({name})) ==
              wire.expect(ok(word(1) + byte(4) + byte(0) + word(2) + word(value))));
    };
    check_word("Tank1.V[1].Pos", 77);
    check_word("Recipe[3].Speed", 1500);
    check_word("A[1,2]", 0x1234);
    CHECK(wire.exchange(cpu, random_label_read_req({"A[k1,h2]"})) ==
          wire.expect(ok(word(1) + byte(4) + byte(0) + word(2) + word(0x1234))));
    // Recipe[3] on D2000: Step is Speed (1 word) + Name (4 words), so D2015.
    CHECK(read_d(cpu, 2015, 1) == std::vector<std::uint16_t>{1500});
    // A[1,2] is element 1×20+2 = 22 of the label-area array: A[0,0] + 22 in 041A.
    CHECK(wire.exchange(cpu, array_read_req({{"A[1,1]", 1, 4}})) ==
          wire.expect(ok(word(1) + byte(4) + byte(1) + word(4) + words({0, 0x1234}))));
    // Cube[1,2,3] = element 1×12 + 2×4 + 3 = 23 on ZR100 + 46.
    CHECK(wire.exchange(cpu, random_label_write_req({{"Cube[1,2,3]", 4, dword(0x00020001)}})) == wire.expect(ok()));
    CHECK(wire.exchange(cpu, read_words_req(Form::IQR, "ZR146", 2)) == wire.expect(ok(words({1, 2}))));
    // Bits: a lone bit member and a packed bit array member.
    CHECK(wire.exchange(cpu, random_label_write_req({{"Tank1.V[0].Open", 2, word(1)}, {"Tank1.Flags[17]", 2, word(1)}})) ==
          wire.expect(ok()));
    CHECK(wire.exchange(cpu, array_read_req({{"Tank1.Flags[16]", 0, 4}})) ==
          wire.expect(ok(word(1) + byte(1) + byte(0) + word(4) + word(0b0010))));
    // %1.%2.member: both prefixes registered.
    CHECK(wire.exchange(cpu, random_label_read_req({"%1.%2.Open", "%1.%2.Pos"}, {"Tank1", "V[0]"})) ==
          wire.expect(ok(word(2) + byte(1) + byte(0) + word(2) + word(1) + byte(4) + byte(0) + word(2) + word(0))));
    // Timers: T1 is T5 (TS5/TC5/TN5), LT1 is LT2; Tank1.Delay lives in the label area.
    cpu.memory().set_value(*devicemodel::find_by_symbol("TN"), 5, 321);
    cpu.memory().set_bit(*devicemodel::find_by_symbol("TS"), 5, true);
    cpu.memory().set_value(*devicemodel::find_by_symbol("LTN"), 2, 0x00012345);
    CHECK(wire.exchange(cpu, random_label_read_req({"T1.N", "T1.S", "T1.C", "LT1.N"})) ==
          wire.expect(ok(word(4) + byte(2) + byte(0) + word(2) + word(321) + byte(1) + byte(0) + word(2) + word(1) +
                         byte(1) + byte(0) + word(2) + word(0) + byte(3) + byte(0) + word(4) + dword(0x00012345))));
    CHECK(wire.exchange(cpu, random_label_write_req({{"T1.N", 2, word(9)}, {"Tank1.Delay.C", 2, word(1)}})) ==
          wire.expect(ok()));
    CHECK(cpu.memory().value(*devicemodel::find_by_symbol("TN"), 5) == 9);
    CHECK(wire.exchange(cpu, random_label_read_req({"Tank1.Delay.C", "Tank1.Delay.S"})) ==
          wire.expect(ok(word(2) + byte(1) + byte(0) + word(2) + word(1) + byte(1) + byte(0) + word(2) + word(0))));
}

// ---------------------------------------------------------------------------
// The error table (docs/labels.md): each request is refused with its end code
// and changes nothing.

TEST_CASE("errors: end code per case, memory unchanged", "[labels][errors]") {
    auto wire = GENERATE(values<Wire>(kAll));
    auto cpu = cpu_with_labels(R"J({
        "structures": [{"name": "S", "members": [{"name": "m", "type": "INT", "dims": [4]}, {"name": "b", "type": "Bit"}]}],
        "labels": [{"name": "LabelW", "type": "Word [Signed]", "device": "D9000"},
                   {"name": "DDD", "type": "Word [Signed]", "dims": [20]},
                   {"name": "Hidden", "type": "Bit", "external": false},
                   {"name": "Bits2", "type": "Bit(0..1,0..7)"},
                   {"name": "Tm", "type": "Timer"},
                   {"name": "Str", "type": "String(4)"},
                   {"name": "St", "type": "S"}]})J");
    // Something in memory so that "unchanged" means something.
    REQUIRE(wire.exchange(cpu, random_label_write_req({{"LabelW", 2, word(7)}, {"DDD[3]", 2, word(8)}})) ==
            wire.expect(ok()));
    const auto before = cpu.memory();
    struct Case {
        const char* what;
        Payload request;
        std::uint16_t code;
    };
    const std::vector<Case> cases = {
        {"no such label", random_label_read_req({"Nope"}), 0x40C0},
        {"no such member", random_label_read_req({"St.x"}), 0x40C0},
        {"external access off", random_label_read_req({"Hidden"}), 0x40C0},
        {"external access off (write)", random_label_write_req({{"Hidden", 2, word(1)}}), 0x40C0},
        {"bit of a label AAA.3", random_label_read_req({"LabelW.3"}), 0x40C0},
        {"digit specification K4AAA", random_label_read_req({"K4LabelW"}), 0x40C0},
        {"variable index BBB[XXX]", random_label_read_req({"DDD[XXX]"}), 0x40C0},
        {"index past the array", random_label_read_req({"DDD[20]"}), 0x40C0},
        {"two indexes on a 1-D array", random_label_read_req({"DDD[1,2]"}), 0x40C0},
        {"array without an index", random_label_read_req({"DDD"}), 0x40C0},
        {"index on a scalar", random_label_read_req({"LabelW[0]"}), 0x40C0},
        {"structure, not its member", random_label_read_req({"St"}), 0x40C0},
        {"timer, not its member", random_label_read_req({"Tm"}), 0x40C0},
        {"timer member that does not exist", random_label_read_req({"Tm.X"}), 0x40C0},
        {"%1 not registered", random_label_read_req({"%1.b"}), 0x40C0},
        {"abbreviated array %1[2]", random_label_read_req({"%1[2]"}, {"DDD"}), 0x40C0},
        {"abbreviation that is not a whole unit", random_label_read_req({"%1W"}, {"Label"}), 0x40C0},
        {"141B: second entry unknown, first not written", random_label_write_req({{"LabelW", 2, word(99)}, {"Nope", 2, word(1)}}), 0x40C0},
        {"141B: length of a word is 2", random_label_write_req({{"LabelW", 4, dword(1)}}), 0xC05C},
        {"141B: string length is chars + N", random_label_write_req({{"Str", 4, words({0x4241, 0})}}), 0xC05C},
        {"141B: second entry's length wrong, first not written",
         random_label_write_req({{"DDD[0]", 2, word(5)}, {"LabelW", 1, byte(1) + byte(0)}}), 0xC05C},
        {"141A: unit 0 on a word label", array_write_req({{"DDD[0]", 0, 2, word(1)}}), 0xC05C},
        {"141A: unit 1 on a bit label", array_write_req({{"St.b", 1, 2, word(1)}}), 0xC05C},
        {"141A: unit spec 2", array_write_req({{"DDD[0]", 2, 2, word(1)}}), 0xC05C},
        {"141A: odd byte count for words", array_write_req({{"DDD[0]", 1, 3, words({1, 2})}}), 0xC05C},
        {"141A: past the end of the array", array_write_req({{"DDD[18]", 1, 6, words({1, 2, 3})}}), 0xC05C},
        {"141A: length 0", array_write_req({{"DDD[0]", 1, 0}}), 0xC05C},
        {"141A: timer member", array_write_req({{"Tm.N", 1, 2, word(1)}}), 0xC05C},
        {"041A: timer member", array_read_req({{"Tm.S", 0, 1}}), 0xC05C},
        {"041A: 2-D bit array", array_read_req({{"Bits2[0,0]", 0, 2}}), 0xC05C},
        {"041A: 0 array points", word(0x041A) + word(0) + word(0) + word(0), 0xC05C},
        {"041C: 0 points", word(0x041C) + word(0) + word(0) + word(0), 0xC05C},
        {"141A: data short", array_write_req({{"DDD[0]", 1, 4, word(1)}}), 0xC061},
        {"141B: data left over", random_label_write_req({{"LabelW", 2, words({1, 2})}}), 0xC061},
        {"041C: name shorter than its length", word(0x041C) + word(0) + word(1) + word(0) + word(6) + words({'L', 'a'}),
         0xC061},
        {"141B: request data over 1920 bytes",
         random_label_write_req(std::vector<RandomEntry>(130, RandomEntry{"LabelW", 2, word(1)})), 0xCEE1},
    };
    for (const auto& c : cases) {
        CAPTURE(c.what);
        const auto command = static_cast<std::uint16_t>(std::stoul(c.request.ascii.substr(0, 4), nullptr, 16));
        CHECK(wire.exchange(cpu, c.request) == wire.expect(error(c.code, command, 0x0000)));
        CHECK(cpu.memory() == before);
    }
}

TEST_CASE("errors: a response over 1920 bytes is CEE2", "[labels][errors]") {
    auto wire = GENERATE(values<Wire>(kAll));
    auto cpu = cpu_with_labels(R"J({"labels": [{"name": "Big", "type": "INT", "dims": [1000]}]})J");
    // 960 words = 1920 bytes of data binary (plus the header fields): over in both codecs.
    CHECK(wire.exchange(cpu, array_read_req({{"Big[0]", 1, 1920}})) == wire.expect(error(0xCEE2, 0x041A, 0x0000)));
}

TEST_CASE("§12 families: Q/L, QJ71E71 and FX5 ports refuse the label commands with C059", "[labels][families]") {
    const auto config = R"J({"labels": [{"name": "LabelW", "type": "INT", "device": "D100"}]})J";
    for (const std::string profile : {"Q26UDEHCPU", "L26CPU-BT", "Q06UDVCPU-QJ71E71", "FX5U-32MR"}) {
        CAPTURE(profile);
        auto cpu = cpu_with_labels(config, profile);
        const auto& wire = kBinary3E;
        for (const auto& [req, command] : std::vector<std::pair<Payload, std::uint16_t>>{
                 {random_label_read_req({"LabelW"}), 0x041C},
                 {random_label_write_req({{"LabelW", 2, word(1)}}), 0x141B},
                 {array_read_req({{"LabelW", 1, 2}}), 0x041A},
                 {array_write_req({{"LabelW", 1, 2, word(1)}}), 0x141A}}) {
            CHECK(wire.exchange(cpu, req) == wire.expect(error(0xC059, command, 0x0000)));
        }
        CHECK(cpu.memory().value(*devicemodel::find_by_symbol("D"), 100) == 0);
    }
    auto cpu = cpu_with_labels(config, "R120PCPU");
    CHECK(kBinary3E.exchange(cpu, random_label_write_req({{"LabelW", 2, word(1)}})) == kBinary3E.expect(ok()));
}

TEST_CASE("unknown label subcommand answers C059, not 0000", "[labels][errors]") {
    auto cpu = cpu_with_labels(R"J({"labels": [{"name": "W", "type": "INT"}]})J");
    CHECK(kBinary3E.exchange(cpu, word(0x041C) + word(0x0002) + word(1) + word(0) + label_name("W")) ==
          kBinary3E.expect(error(0xC059, 0x041C, 0x0002)));
}

TEST_CASE("labels survive a snapshot: the label area is saved and restored", "[labels][snapshot]") {
    auto cpu = cpu_with_labels(R"J({"labels": [{"name": "A", "type": "DINT"}, {"name": "S", "type": "String(8)"}]})J");
    REQUIRE(kAscii3E.exchange(cpu, random_label_write_req({{"A", 4, dword(0xCAFEF00D)}})) == kAscii3E.expect(ok()));
    auto bytes = devicemodel::encode_snapshot(cpu.memory(), cpu.profile().name);
    auto fresh = cpu_with_labels(R"J({"labels": [{"name": "A", "type": "DINT"}, {"name": "S", "type": "String(8)"}]})J");
    auto result = devicemodel::restore_snapshot(bytes, fresh.memory(), cpu.profile().name, fresh.runtime().latch(),
                                                devicemodel::RestoreScope::All);
    REQUIRE(result.ok);
    CHECK(result.warnings.empty());
    CHECK(kBinary3E.exchange(fresh, random_label_read_req({"A"})) ==
          kBinary3E.expect(ok(word(1) + byte(5) + byte(0) + word(4) + dword(0xCAFEF00D))));
    // A snapshot without a label area (an older file, or no labels) restores the devices and leaves labels alone.
    auto plain = make_cpu();
    auto old = devicemodel::encode_snapshot(plain.memory(), plain.profile().name);
    auto again = devicemodel::restore_snapshot(old, fresh.memory(), cpu.profile().name, fresh.runtime().latch(),
                                               devicemodel::RestoreScope::All);
    CHECK(again.ok);
    CHECK(fresh.memory().label_word(0) == 0xF00D);
}

TEST_CASE("the outcome names the labels a request carried, for the call monitor and recordings", "[labels]") {
    auto wire = GENERATE(values<Wire>(kAll));
    auto cpu = cpu_with_labels(kRandom);
    CHECK(run(cpu, wire.request(random_label_read_req({"LabelB", "LabelW", "Sw.led"}))).named == "LabelB, LabelW, Sw.led");
    // Refused at the second name (40C0): the names up to the one that failed.
    auto refused = run(cpu, wire.request(random_label_read_req({"LabelB", "Nope", "LabelW"})));
    CHECK(refused.end_code == protocol::EndCode::LabelNotFound);
    CHECK(refused.named == "LabelB, Nope");
    std::vector<std::string> many(10, "LabelW");
    CHECK(run(cpu, wire.request(random_label_read_req(many))).named ==
          "LabelW, LabelW, LabelW, LabelW, LabelW, LabelW, LabelW, LabelW +2 more");
    CHECK(run(cpu, wire.request(word(0x0401) + word(0) + device(Form::Q, "D0") + word(1))).named.empty());
}
