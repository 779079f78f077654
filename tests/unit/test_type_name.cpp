// Read Type Name 0101 — SLMP Reference Manual §5.6, real-CPU measurements.
// The manual gives the request data and the Q02UCPU response data; whole frames
// are built around them (own station, timer 0010) and the responses derived.
#include "support/fixtures.hpp"

using namespace slmp;
using namespace slmp::test;

namespace {

const Payload kReadTypeName{"01 01 00 00", "01010000"};

// 16 name characters (raw in both codecs) then the model code.
Payload type_name_data(const std::string& name, std::uint16_t code) {
    std::string padded = name;
    padded.resize(16, ' ');
    return Payload{hex(text(padded)), padded} + word(code);
}

}  // namespace

TEST_CASE("0101 on an R08CPU: R08CPU + 10 spaces, code 4801", "[type_name][spec]") {
    auto cpu = make_cpu("R08CPU");
    SECTION("whole frames, 3E binary and ASCII") {
        auto out = run(cpu, bytes("50 00 00 FF FF 03 00 06 00 10 00 01 01 00 00"));
        CHECK(hex(out.response) ==
              "D0 00 00 FF FF 03 00 14 00 00 00 52 30 38 43 50 55 20 20 20 20 20 20 20 20 20 20 01 48");
        auto asc = run(cpu, text("500000FF03FF00000C001001010000"));
        CHECK(str(asc.response) == "D00000FF03FF0000180000R08CPU          4801");
    }
    SECTION("all four frame shapes") {
        auto wire = GENERATE(kBinary3E, kBinary4E, kAscii3E, kAscii4E);
        CHECK(wire.exchange(cpu, kReadTypeName) == wire.expect(ok(type_name_data("R08CPU", 0x4801))));
    }
}

TEST_CASE("0101: the manual's Q02UCPU example", "[type_name][spec]") {
    // A QJ71E71-connected Q CPU answers 0101; rename it to the manual's model.
    auto profile = config::load_profile("Q06UDVCPU-QJ71E71").cpu;
    profile.type_name = "Q02UCPU";
    profile.model_code = 0x0263;
    devicemodel::Cpu cpu(profile);
    auto wire = GENERATE(kBinary3E, kBinary4E, kAscii3E, kAscii4E);
    const Payload spec_response{"51 30 32 55 43 50 55 20 20 20 20 20 20 20 20 20 63 02", "Q02UCPU         0263"};
    CHECK(wire.exchange(cpu, kReadTypeName) == wire.expect(ok(spec_response)));
}

TEST_CASE("0101 per profile (hardware-behaviour §5)", "[type_name]") {   // signposts: allow (the name ctest lists)
    SECTION("R120PCPU -> 4844") {
        auto cpu = make_cpu("R120PCPU");
        auto wire = GENERATE(kBinary3E, kBinary4E, kAscii3E, kAscii4E);
        CHECK(wire.exchange(cpu, kReadTypeName) == wire.expect(ok(type_name_data("R120PCPU", 0x4844))));
    }
    SECTION("Q06UDVCPU through a QJ71E71-100 -> 0368") {
        auto cpu = make_cpu("Q06UDVCPU-QJ71E71");
        auto wire = GENERATE(kBinary3E, kBinary4E, kAscii3E, kAscii4E);
        CHECK(wire.exchange(cpu, kReadTypeName) == wire.expect(ok(type_name_data("Q06UDVCPU", 0x0368))));
    }
    SECTION("FX5U-32MR/DS -> 4A41") {
        auto cpu = make_cpu("FX5U-32MR");
        auto wire = GENERATE(kBinary3E, kAscii3E);
        CHECK(wire.exchange(cpu, kReadTypeName) == wire.expect(ok(type_name_data("FX5U-32MR/DS", 0x4A41))));
    }
    SECTION("QnU and L built-in ports refuse 0101 -> C059") {
        auto name = GENERATE(as<std::string>{}, "Q26UDEHCPU", "L26CPU-BT");
        auto cpu = make_cpu(name);
        auto wire = GENERATE(kBinary3E, kAscii3E);
        CHECK(wire.exchange(cpu, kReadTypeName) == wire.expect(error(0xC059, 0x0101, 0x0000)));
    }
}

TEST_CASE("0101 with data after the subcommand -> C061", "[type_name]") {
    auto cpu = make_cpu("R08CPU");
    auto wire = GENERATE(kBinary3E, kBinary4E, kAscii3E, kAscii4E);
    CHECK(wire.exchange(cpu, kReadTypeName + Payload{"00", "00"}) == wire.expect(error(0xC061, 0x0101, 0x0000)));
    SECTION("unknown subcommand 0001 -> C059") {
        CHECK(wire.exchange(cpu, {"01 01 01 00", "01010001"}) == wire.expect(error(0xC059, 0x0101, 0x0001)));
    }
}
