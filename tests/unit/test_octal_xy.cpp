// FX5 (iQ-F) numbers X and Y in octal: X0-X7, X10 ... (issue 14). The number a
// device address holds is the bit index, so X10 is bit 8; ASCII frames carry
// the octal digits, binary frames the bit index (what npm mcprotocol's
// "octalInputOutput" sends). iQ-R/Q/L keep hexadecimal.
#include "support/fixtures.hpp"

using namespace slmp;
using namespace slmp::test;
using devicemodel::Numbering;
using devicemodel::Radix;

namespace {

const Numbering kOctal{Radix::Oct};

}  // namespace

TEST_CASE("address text: X/Y in octal under an octal numbering", "[devices][octal]") {
    CHECK(devicemodel::parse_address("X7", kOctal)->number == 7);
    CHECK(devicemodel::parse_address("X10", kOctal)->number == 8);
    CHECK(devicemodel::parse_address("Y1777", kOctal)->number == 1023);
    CHECK(devicemodel::parse_address("DX10", kOctal)->number == 8);
    // Other devices keep the table's radix: D decimal, B hexadecimal.
    CHECK(devicemodel::parse_address("D10", kOctal)->number == 10);
    CHECK(devicemodel::parse_address("B10", kOctal)->number == 16);
    // Hexadecimal by default (iQ-R, Q, L).
    CHECK(devicemodel::parse_address("X10")->number == 16);
    CHECK(devicemodel::parse_address("X8")->number == 8);

    std::string error;
    CHECK_FALSE(devicemodel::parse_address("X8", kOctal, &error));
    CHECK(error == "bad device number '8' in address 'X8' (X is numbered in octal on this CPU: X7 is followed by X10)");
    CHECK_FALSE(devicemodel::parse_address("Y1F", kOctal, &error));

    const auto& x = *devicemodel::find_by_symbol("X");
    CHECK(devicemodel::format_address({&x, 8}, kOctal) == "X10");
    CHECK(devicemodel::format_address({&x, 7}, kOctal) == "X7");
    CHECK(devicemodel::format_address({&x, 8}) == "X8");
    CHECK(devicemodel::format_address({&x, 31}) == "X1F");
}

TEST_CASE("profiles: FX5 numbers X/Y in octal, the others in hexadecimal", "[profiles][octal]") {
    for (auto name : config::builtin_profile_names()) {
        INFO(name);
        auto cpu = make_cpu(name);
        auto expected = cpu.profile().family == devicemodel::Family::IQF ? Radix::Oct : Radix::Hex;
        CHECK(cpu.profile().numbering.xy == expected);
    }
}

TEST_CASE("SLMP on an FX5U: X7 then X10 are adjacent, X8 is refused", "[octal][spec]") {
    auto cpu = make_cpu("FX5U-32MR");
    const auto& x = *devicemodel::find_by_symbol("X");
    auto& memory = cpu.memory();

    SECTION("1401 bit write of 2 points from X7 sets bits 7 and 8") {
        // Binary: number 7 (the bit index), code 9C; ASCII: "X*000007".
        const Payload write{"01 14 01 00 07 00 00 9C 02 00 11", "14010001X*0000070002" "11"};
        auto wire = GENERATE(kBinary3E, kAscii3E);
        INFO(wire.name());
        CHECK(wire.exchange(cpu, write) == wire.expect(ok()));
        CHECK(memory.bit(x, 7));
        CHECK(memory.bit(x, 8));
        CHECK_FALSE(memory.bit(x, 9));
        CHECK_FALSE(memory.bit(x, 16));
    }
    SECTION("0401 bit read of X10 reads bit 8") {
        memory.set_bit(x, 8, true);
        const Payload read{"01 04 01 00 08 00 00 9C 02 00", "04010001X*0000100002"};
        auto wire = GENERATE(kBinary3E, kAscii3E);
        INFO(wire.name());
        CHECK(wire.exchange(cpu, read) == wire.expect(ok(bits({1, 0}))));
    }
    SECTION("ASCII X*000008 is not an octal number: C050, memory unchanged") {
        auto before = memory.bit(x, 8);
        CHECK(kAscii3E.exchange(cpu, Payload{"", "14010001X*0000080001" "1"}) ==
              kAscii3E.expect(error(0xC050, 0x1401, 0x0001)));
        CHECK(memory.bit(x, 8) == before);
        CHECK_FALSE(memory.bit(x, 10));
    }
    SECTION("0403 random read names Y20 (bit 16) in octal in ASCII") {
        const std::uint16_t value = 0xA5A5;
        memory.write_words(*devicemodel::find_by_symbol("Y"), 16, std::span(&value, 1));
        // Random read of one word device: Y20 (octal) = bit 16; 16 bits from there.
        CHECK(kAscii3E.exchange(cpu, Payload{"", "04030000" "0100" "Y*000020"}) == kAscii3E.expect(ok(words({0xA5A5}))));
        CHECK(kBinary3E.exchange(cpu, Payload{"03 04 00 00 01 00 10 00 00 9D", ""}) ==
              kBinary3E.expect(ok(words({0xA5A5}))));
    }
}

TEST_CASE("SLMP on an R08CPU: X10 is hexadecimal (bit 16), X8 is served", "[octal]") {
    auto cpu = make_cpu("R08CPU");
    const auto& x = *devicemodel::find_by_symbol("X");
    CHECK(kAscii3E.exchange(cpu, Payload{"", "14010001X*0000100001" "1"}) == kAscii3E.expect(ok()));
    CHECK(kAscii3E.exchange(cpu, Payload{"", "14010001X*0000080001" "1"}) == kAscii3E.expect(ok()));
    CHECK(cpu.memory().bit(x, 16));
    CHECK(cpu.memory().bit(x, 8));
}
