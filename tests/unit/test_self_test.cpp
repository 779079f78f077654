// Self Test (loopback) 0619 — SLMP Reference Manual §5.9. The manual gives the
// request and response data for "ABCDE"; whole frames are built around them.
#include "support/fixtures.hpp"

using namespace slmp;
using namespace slmp::test;

namespace {

Payload loopback(std::uint16_t count, const std::string& data) {
    return word(0x0619) + word(0x0000) + word(count) + Payload{hex(text(data)), data};
}

}  // namespace

TEST_CASE("0619 with ABCDE: the manual example", "[self_test][spec]") {
    auto cpu = make_cpu("R08CPU");
    SECTION("request data as printed") {
        CHECK(hex(text("061900000005ABCDE")) == "30 36 31 39 30 30 30 30 30 30 30 35 41 42 43 44 45");
        auto wire = GENERATE(kBinary3E, kBinary4E, kAscii3E, kAscii4E);
        const Payload request{"19 06 00 00 05 00 41 42 43 44 45", "061900000005ABCDE"};
        const Payload response{"05 00 41 42 43 44 45", "0005ABCDE"};
        CHECK(wire.exchange(cpu, request) == wire.expect(ok(response)));
    }
    SECTION("whole frames, 3E (derived)") {
        auto out = run(cpu, bytes("50 00 00 FF FF 03 00 0D 00 10 00 19 06 00 00 05 00 41 42 43 44 45"));
        CHECK(hex(out.response) == "D0 00 00 FF FF 03 00 09 00 00 00 05 00 41 42 43 44 45");
        auto asc = run(cpu, text("500000FF03FF000015" "0010" "061900000005ABCDE"));
        CHECK(str(asc.response) == "D00000FF03FF00000D" "0000" "0005ABCDE");
    }
}

TEST_CASE("0619 data counts", "[self_test]") {
    auto cpu = make_cpu("R08CPU");
    auto wire = GENERATE(kBinary3E, kBinary4E, kAscii3E, kAscii4E);
    SECTION("1 byte") {
        CHECK(wire.exchange(cpu, loopback(1, "0")) == wire.expect(ok(word(1) + Payload{"30", "0"})));
    }
    SECTION("960 bytes (the maximum)") {
        std::string data(960, 'F');
        CHECK(wire.exchange(cpu, loopback(960, data)) == wire.expect(ok(word(960) + Payload{hex(text(data)), data})));
    }
    SECTION("0 bytes -> C05C (chosen; the manual names no code)") {
        CHECK(wire.exchange(cpu, loopback(0, "")) == wire.expect(error(0xC05C, 0x0619, 0x0000)));
    }
    SECTION("961 bytes -> C05C (chosen)") {
        CHECK(wire.exchange(cpu, loopback(961, std::string(961, 'A'))) == wire.expect(error(0xC05C, 0x0619, 0x0000)));
    }
    SECTION("count 5, 4 bytes of data -> C061") {
        CHECK(wire.exchange(cpu, loopback(5, "ABCD")) == wire.expect(error(0xC061, 0x0619, 0x0000)));
    }
    SECTION("count 5, 6 bytes of data -> C061") {
        CHECK(wire.exchange(cpu, loopback(5, "ABCDEF")) == wire.expect(error(0xC061, 0x0619, 0x0000)));
    }
    SECTION("characters outside 0-9/A-F are echoed (the lenient choice)") {
        CHECK(wire.exchange(cpu, loopback(3, "a z")) == wire.expect(ok(word(3) + Payload{"61 20 7A", "a z"})));
    }
    SECTION("ASCII: a non-hex count -> C050") {
        if (wire.ascii()) CHECK(wire.exchange(cpu, {"", "06190000000GABCDE"}) == wire.expect(error(0xC050, 0x0619, 0x0000)));
    }
}

TEST_CASE("0619 per profile", "[self_test]") {
    SECTION("QnU and L built-in ports -> C059") {
        auto name = GENERATE(as<std::string>{}, "Q26UDEHCPU", "L26CPU-BT");
        auto cpu = make_cpu(name);
        auto wire = GENERATE(kBinary3E, kAscii3E);
        CHECK(wire.exchange(cpu, loopback(5, "ABCDE")) == wire.expect(error(0xC059, 0x0619, 0x0000)));
    }
    SECTION("QJ71E71, FX5U, R120PCPU answer") {
        auto name = GENERATE(as<std::string>{}, "Q06UDVCPU-QJ71E71", "FX5U-32MR", "R120PCPU");
        auto cpu = make_cpu(name);
        auto wire = GENERATE(kBinary3E, kAscii3E);
        CHECK(wire.exchange(cpu, loopback(5, "ABCDE")) == wire.expect(ok(word(5) + Payload{"41 42 43 44 45", "ABCDE"})));
    }
}
