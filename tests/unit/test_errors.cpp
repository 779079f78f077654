// Error responses on an R08CPU, byte-exact: end code + 9 bytes of error
// information (route, command, subcommand), length 0B00 / "0016". Check order
// of protocol/commands/device_batch.cpp's header comment. After every rejected
// write, memory must be unchanged.
#include "support/fixtures.hpp"

using namespace slmp;
using namespace slmp::test;

namespace {

// Sends a request that must be rejected with `code`, and proves nothing changed.
void expect_rejected(devicemodel::Cpu& cpu, const Wire& wire, const Payload& request, std::uint16_t code,
                     std::uint16_t command, std::uint16_t subcommand, Route route = {}) {
    auto before = snapshot(cpu);
    CHECK(wire.exchange(cpu, request, route) == wire.expect(error(code, command, subcommand, route), route));
    CHECK((snapshot(cpu) == before));
}

// A few non-zero values where rejected writes aim, so "unchanged" means something.
void seed(devicemodel::Cpu& cpu) {
    auto& m = cpu.memory();
    for (const char* a : {"D100", "D10239", "M100", "S0", "S100", "Z19", "LZ0", "LZ1", "LCN0", "LTN0", "W1FFF"}) {
        auto address = *devicemodel::parse_address(a);
        m.set_value(*address.spec, address.number, 0x5A5A);
    }
}

}  // namespace

TEST_CASE("error frames: the shapes of spec §3.4 D and hardware-behaviour §1", "[errors][spec]") {   // signposts: allow (the name ctest lists)
    auto cpu = make_cpu("R08CPU");
    SECTION("3E binary and ASCII, unsupported subcommand 0401/0004 -> C059") {
        auto out = run(cpu, bytes("50 00 00 FF FF 03 00 0C 00 10 00 01 04 04 00 64 00 00 A8 03 00"));
        CHECK(hex(out.response) == "D0 00 00 FF FF 03 00 0B 00 59 C0 00 FF FF 03 00 01 04 04 00");
        CHECK(out.end_code == protocol::EndCode::UnsupportedCommand);
        CHECK(out.command == 0x0401);
        CHECK(out.subcommand == 0x0004);
        CHECK_FALSE(out.note.empty());
        auto asc = run(cpu, text("500000FF03FF000018001004010004D*0001000003"));
        CHECK(str(asc.response) == "D00000FF03FF000016C05900FF03FF0004010004");
    }
    SECTION("4E binary, serial 0001, 0401/0002 D10240 -> 4031 (real-CPU measurements)") {
        auto out = run(cpu, bytes("54 00 01 00 00 00 00 FF FF 03 00 0E 00 10 00 01 04 02 00 00 28 00 00 A8 00 01 00"));
        CHECK(hex(out.response) == "D4 00 01 00 00 00 00 FF FF 03 00 0B 00 31 40 00 FF FF 03 00 01 04 02 00");
        auto asc = run(cpu, text("54000001000000FF03FF00001C001004010002D***000102400001"));
        CHECK(str(asc.response) == "D4000001000000FF03FF000016403100FF03FF0004010002");
    }
    SECTION("the error information echoes the request route (network 01, station 02)") {
        // The probe report's request went to network 01 station 02; a built-in
        // port cannot route, so the code is 4A01 (chosen), the shape is the same.
        auto out = run(cpu, bytes("54 00 01 00 00 00 01 02 FF 03 00 0E 00 10 00 01 04 02 00 00 28 00 00 A8 00 01 00"));
        CHECK(hex(out.response) == "D4 00 01 00 00 00 01 02 FF 03 00 0B 00 01 4A 01 02 FF 03 00 01 04 02 00");
    }
}

TEST_CASE("unsupported commands and subcommands -> C059", "[errors]") {
    auto cpu = make_cpu("R08CPU");
    auto wire = GENERATE(kBinary3E, kBinary4E, kAscii3E, kAscii4E);
    SECTION("unknown command 9999") {
        CHECK(wire.exchange(cpu, word(0x9999) + word(0x0000)) == wire.expect(error(0xC059, 0x9999, 0x0000)));
    }
    SECTION("command 0000") {
        CHECK(wire.exchange(cpu, word(0x0000) + word(0x0000)) == wire.expect(error(0xC059, 0x0000, 0x0000)));
    }
    SECTION("0401 with subcommands 0004, 0005, 0010, 0084, FFFF") {
        for (std::uint16_t sub : {0x0004, 0x0005, 0x0010, 0x0084, 0xFFFF})
            CHECK(wire.exchange(cpu, word(0x0401) + word(sub) + device(Form::Q, "D0") + word(1)) ==
                  wire.expect(error(0xC059, 0x0401, sub)));
    }
    SECTION("1401 with subcommand 0007: memory unchanged") {
        expect_rejected(cpu, wire, word(0x1401) + word(0x0007) + device(Form::IQR, "M0") + word(1) + bits({1}), 0xC059,
                        0x1401, 0x0007);
    }
}

TEST_CASE("route checks (engine.cpp check_route, codes chosen)", "[errors]") {   // signposts: allow (the name ctest lists)
    auto cpu = make_cpu("R08CPU");
    seed(cpu);
    auto wire = GENERATE(kBinary3E, kBinary4E, kAscii3E, kAscii4E);
    const auto read = read_words_req(Form::Q, "D100", 1);
    SECTION("own station 00/FF/03FF/00 and CPU No.1 03E0 are served") {
        CHECK(wire.exchange(cpu, read) == wire.expect(ok(words({0x5A5A}))));
        Route cpu1{0x00, 0xFF, 0x03E0, 0x00};
        CHECK(wire.exchange(cpu, read, cpu1) == wire.expect(ok(words({0x5A5A})), cpu1));
    }
    SECTION("network 01 -> 4A01") {
        CHECK(wire.exchange(cpu, read, {0x01, 0xFF, 0x03FF, 0x00}) ==
              wire.expect(error(0x4A01, 0x0401, 0x0000, {0x01, 0xFF, 0x03FF, 0x00}), {0x01, 0xFF, 0x03FF, 0x00}));
    }
    SECTION("station 01 -> 4A02") {
        Route r{0x00, 0x01, 0x03FF, 0x00};
        CHECK(wire.exchange(cpu, read, r) == wire.expect(error(0x4A02, 0x0401, 0x0000, r), r));
    }
    SECTION("multidrop 01 -> 4A02") {
        Route r{0x00, 0xFF, 0x03FF, 0x01};
        CHECK(wire.exchange(cpu, read, r) == wire.expect(error(0x4A02, 0x0401, 0x0000, r), r));
    }
    SECTION("module I/O 03E1 and 0000 -> 4B02") {
        for (std::uint16_t io : {0x03E1, 0x0000, 0x03D0}) {
            Route r{0x00, 0xFF, io, 0x00};
            CHECK(wire.exchange(cpu, read, r) == wire.expect(error(0x4B02, 0x0401, 0x0000, r), r));
        }
    }
    SECTION("a write to another station changes nothing") {
        expect_rejected(cpu, wire, write_words_req(Form::Q, "D100", {1}), 0x4A01, 0x1401, 0x0000, {0x01, 0x02, 0x03FF, 0x00});
    }
}

TEST_CASE("device checks in order (device_batch.cpp)", "[errors]") {
    auto cpu = make_cpu("R08CPU");
    seed(cpu);
    auto wire = GENERATE(kBinary3E, kBinary4E, kAscii3E, kAscii4E);

    SECTION("2. unknown device code -> C05B") {
        const Payload q_bad{"01 04 00 00 64 00 00 01 01 00", "04010000Q*0001000001"};
        CHECK(wire.exchange(cpu, q_bad) == wire.expect(error(0xC05B, 0x0401, 0x0000)));
        const Payload iqr_bad{"01 04 02 00 64 00 00 00 FF 00 01 00", "04010002QQ**000001000001"};
        CHECK(wire.exchange(cpu, iqr_bad) == wire.expect(error(0xC05B, 0x0401, 0x0002)));
        // An iQ-R-only device in the Q form is unknown there.
        const Payload ltn_q{"01 04 00 00 00 00 00 52 04 00", "04010000LT0000000004"};
        CHECK(wire.exchange(cpu, ltn_q) == wire.expect(error(0xC05B, 0x0401, 0x0000)));
        expect_rejected(cpu, wire, {"01 14 00 00 64 00 00 01 01 00 01 00", "14010000Q*00010000010001"}, 0xC05B, 0x1401,
                        0x0000);
    }
    SECTION("2. G and HG named as plain devices -> C05B (real-CPU measurements)") {
        const Payload g_q{"01 04 00 00 0A 00 00 AB 01 00", "04010000G*0000100001"};
        CHECK(wire.exchange(cpu, g_q) == wire.expect(error(0xC05B, 0x0401, 0x0000)));
        const Payload hg_iqr{"01 04 02 00 14 00 00 00 2E 00 01 00", "04010002HG**000000200001"};
        CHECK(wire.exchange(cpu, hg_iqr) == wire.expect(error(0xC05B, 0x0401, 0x0002)));
        expect_rejected(cpu, wire, {"01 14 00 00 0A 00 00 AB 01 00 01 00", "14010000G*00001000010001"}, 0xC05B, 0x1401,
                        0x0000);
    }
    SECTION("2 before 5: unknown device with 0 points -> C05B") {
        CHECK(wire.exchange(cpu, {"01 04 00 00 64 00 00 01 00 00", "04010000Q*0001000000"}) ==
              wire.expect(error(0xC05B, 0x0401, 0x0000)));
    }
    SECTION("3. direct LTS/LTC/LSTS/LSTC read -> 4030") {
        for (const char* a : {"LTS0", "LTC0", "LSTS0", "LSTC0"}) {
            INFO(a);
            CHECK(wire.exchange(cpu, read_bits_req(Form::IQR, a, 1)) == wire.expect(error(0x4030, 0x0401, 0x0003)));
            CHECK(wire.exchange(cpu, read_words_req(Form::IQR, a, 1)) == wire.expect(error(0x4030, 0x0401, 0x0002)));
        }
    }
    SECTION("3. LTN/LSTN and their contacts/coils written -> 4030") {
        for (const char* a : {"LTN0", "LSTN0"})
            expect_rejected(cpu, wire, write_words_req(Form::IQR, a, {1, 2, 3, 4}), 0x4030, 0x1401, 0x0002);
        for (const char* a : {"LTS0", "LTC0", "LSTS0", "LSTC0"})
            expect_rejected(cpu, wire, write_bits_req(Form::IQR, a, {1}), 0x4030, 0x1401, 0x0003);
    }
    SECTION("3. write to S -> 4030 (bit and word units, both forms)") {
        expect_rejected(cpu, wire, write_bits_req(Form::Q, "S0", {1}), 0x4030, 0x1401, 0x0001);
        expect_rejected(cpu, wire, write_bits_req(Form::IQR, "S100", {0, 1}), 0x4030, 0x1401, 0x0003);
        expect_rejected(cpu, wire, write_words_req(Form::Q, "S0", {0xFFFF}), 0x4030, 0x1401, 0x0000);
        expect_rejected(cpu, wire, write_words_req(Form::IQR, "S0", {0}), 0x4030, 0x1401, 0x0002);
    }
    SECTION("4. bit units on a word device -> C05C") {
        CHECK(wire.exchange(cpu, read_words_req(Form::Q, "D100", 1)) == wire.expect(ok(words({0x5A5A}))));
        const Payload bit_read_d{"01 04 01 00 64 00 00 A8 01 00", "04010001D*0001000001"};
        CHECK(wire.exchange(cpu, bit_read_d) == wire.expect(error(0xC05C, 0x0401, 0x0001)));
        const Payload bit_write_d{"01 14 01 00 64 00 00 A8 01 00 10", "14010001D*00010000011"};
        expect_rejected(cpu, wire, bit_write_d, 0xC05C, 0x1401, 0x0001);
        const Payload bit_read_tn{"01 04 03 00 00 00 00 00 C2 00 01 00", "04010003TN**000000000001"};
        CHECK(wire.exchange(cpu, bit_read_tn) == wire.expect(error(0xC05C, 0x0401, 0x0003)));
        const Payload bit_read_ltn{"01 04 03 00 00 00 00 00 52 00 04 00", "04010003LTN*000000000004"};
        CHECK(wire.exchange(cpu, bit_read_ltn) == wire.expect(error(0xC05C, 0x0401, 0x0003)));
    }
    SECTION("5. 0 points -> C051 (words) / C052 (bits)") {
        CHECK(wire.exchange(cpu, read_words_req(Form::Q, "D0", 0)) == wire.expect(error(0xC051, 0x0401, 0x0000)));
        CHECK(wire.exchange(cpu, read_bits_req(Form::IQR, "M0", 0)) == wire.expect(error(0xC052, 0x0401, 0x0003)));
        expect_rejected(cpu, wire, write_words_req(Form::Q, "D100", {}), 0xC051, 0x1401, 0x0000);
        expect_rejected(cpu, wire, write_bits_req(Form::Q, "M100", {}), 0xC052, 0x1401, 0x0001);
    }
    SECTION("5. long devices in whole units -> C051") {
        for (std::uint16_t n : {1, 2, 3, 5, 6, 7}) {
            INFO("LTN0 x" << n);
            CHECK(wire.exchange(cpu, read_words_req(Form::IQR, "LTN0", n)) == wire.expect(error(0xC051, 0x0401, 0x0002)));
            CHECK(wire.exchange(cpu, read_words_req(Form::IQR, "LSTN0", n)) == wire.expect(error(0xC051, 0x0401, 0x0002)));
        }
        CHECK(wire.exchange(cpu, read_words_req(Form::IQR, "LTN0", 4)) == wire.expect(ok(words({0x5A5A, 0, 0, 0}))));
        expect_rejected(cpu, wire, write_words_req(Form::IQR, "LZ0", {1}), 0xC051, 0x1401, 0x0002);
        expect_rejected(cpu, wire, write_words_req(Form::IQR, "LZ0", {1, 2, 3}), 0xC051, 0x1401, 0x0002);
        expect_rejected(cpu, wire, write_words_req(Form::IQR, "LCN0", {1}), 0xC051, 0x1401, 0x0002);
        expect_rejected(cpu, wire, write_words_req(Form::IQR, "LCN0", {1, 2, 3}), 0xC051, 0x1401, 0x0002);
        CHECK(wire.exchange(cpu, read_words_req(Form::IQR, "LCN0", 1)) == wire.expect(error(0xC051, 0x0401, 0x0002)));
    }
    SECTION("5 before 6: over-limit points past the end -> C051, not 4031") {
        CHECK(wire.exchange(cpu, read_words_req(Form::Q, "D10239", 961)) == wire.expect(error(0xC051, 0x0401, 0x0000)));
    }
    SECTION("6. small areas: Z (20), LZ (2)") {
        CHECK(wire.exchange(cpu, read_words_req(Form::Q, "Z19", 1)) == wire.expect(ok(words({0x5A5A}))));
        CHECK(wire.exchange(cpu, read_words_req(Form::Q, "Z19", 2)) == wire.expect(error(0x4031, 0x0401, 0x0000)));
        CHECK(wire.exchange(cpu, read_words_req(Form::IQR, "Z20", 1)) == wire.expect(error(0x4031, 0x0401, 0x0002)));
        expect_rejected(cpu, wire, write_words_req(Form::Q, "Z19", {1, 2}), 0x4031, 0x1401, 0x0000);
        CHECK(wire.exchange(cpu, read_words_req(Form::IQR, "LZ1", 2)) == wire.expect(ok(words({0x5A5A, 0}))));
        CHECK(wire.exchange(cpu, read_words_req(Form::IQR, "LZ2", 2)) == wire.expect(error(0x4031, 0x0401, 0x0002)));
        CHECK(wire.exchange(cpu, read_words_req(Form::IQR, "LZ1", 4)) == wire.expect(error(0x4031, 0x0401, 0x0002)));
        expect_rejected(cpu, wire, write_words_req(Form::IQR, "LZ2", {1, 2}), 0x4031, 0x1401, 0x0002);
        expect_rejected(cpu, wire, write_words_req(Form::IQR, "LZ0", {1, 2, 3, 4, 5, 6}), 0x4031, 0x1401, 0x0002);
    }
    SECTION("6. a span past 32 bits of device number does not wrap") {
        CHECK(wire.exchange(cpu, read_words_req(Form::IQR, "WFFFFFFFF", 2)) ==
              wire.expect(error(0x4031, 0x0401, 0x0002)));
        CHECK(wire.exchange(cpu, read_bits_req(Form::IQR, "BFFFFFFFF", 2)) ==
              wire.expect(error(0x4031, 0x0401, 0x0003)));
    }
}

TEST_CASE("request data length mismatch -> C061", "[errors]") {
    auto cpu = make_cpu("R08CPU");
    seed(cpu);
    auto wire = GENERATE(kBinary3E, kBinary4E, kAscii3E, kAscii4E);
    SECTION("read: points field cut short") {
        CHECK(wire.exchange(cpu, {"01 04 00 00 64 00 00 A8 03", "04010000D*000100000"}) ==
              wire.expect(error(0xC061, 0x0401, 0x0000)));
    }
    SECTION("read: device field missing") {
        CHECK(wire.exchange(cpu, {"01 04 00 00", "04010000"}) == wire.expect(error(0xC061, 0x0401, 0x0000)));
    }
    SECTION("read: one byte/character after the points") {
        CHECK(wire.exchange(cpu, read_words_req(Form::Q, "D100", 1) + Payload{"00", "0"}) ==
              wire.expect(error(0xC061, 0x0401, 0x0000)));
    }
    SECTION("write: fewer data than points") {
        expect_rejected(cpu, wire, word(0x1401) + word(0) + device(Form::Q, "D100") + word(3) + words({1, 2}), 0xC061,
                        0x1401, 0x0000);
        expect_rejected(cpu, wire, word(0x1401) + word(1) + device(Form::Q, "M100") + word(3) + bits({1, 1}), 0xC061,
                        0x1401, 0x0001);
    }
    SECTION("write: more data than points") {
        expect_rejected(cpu, wire, word(0x1401) + word(0) + device(Form::Q, "D100") + word(1) + words({1, 2}), 0xC061,
                        0x1401, 0x0000);
        expect_rejected(cpu, wire, word(0x1401) + word(3) + device(Form::IQR, "M100") + word(2) + bits({1, 1, 1}),
                        0xC061, 0x1401, 0x0003);
    }
    SECTION("write: half a word of data") {
        expect_rejected(cpu, wire, word(0x1401) + word(0) + device(Form::Q, "D100") + word(1) + Payload{"01", "01"},
                        0xC061, 0x1401, 0x0000);
    }
}

TEST_CASE("bad write data", "[errors]") {
    auto cpu = make_cpu("R08CPU");
    seed(cpu);
    SECTION("binary bit data nibble above 1 -> C05C") {
        auto wire = GENERATE(kBinary3E, kBinary4E);
        expect_rejected(cpu, wire, word(0x1401) + word(1) + device(Form::Q, "M100") + word(2) + Payload{"12", ""},
                        0xC05C, 0x1401, 0x0001);
    }
    SECTION("ASCII bit data other than 0/1 -> C050") {
        auto wire = GENERATE(kAscii3E, kAscii4E);
        expect_rejected(cpu, wire, word(0x1401) + word(1) + device(Form::Q, "M100") + word(2) + Payload{"", "12"},
                        0xC050, 0x1401, 0x0001);
    }
}

TEST_CASE("non-hex ASCII -> C050", "[errors]") {
    auto cpu = make_cpu("R08CPU");
    seed(cpu);
    auto wire = GENERATE(kAscii3E, kAscii4E);
    SECTION("in the points") {
        CHECK(wire.exchange(cpu, {"", "04010000D*00010000G3"}) == wire.expect(error(0xC050, 0x0401, 0x0000)));
    }
    SECTION("in a decimal device number: hex digit A") {
        CHECK(wire.exchange(cpu, {"", "04010000D*00010A0001"}) == wire.expect(error(0xC050, 0x0401, 0x0000)));
    }
    SECTION("in a hex device number") {
        CHECK(wire.exchange(cpu, {"", "04010000X*00001G0001"}) == wire.expect(error(0xC050, 0x0401, 0x0000)));
    }
    SECTION("in word write data: memory unchanged") {
        expect_rejected(cpu, wire, {"", "14010000D*0001000002" "0001" "00X1"}, 0xC050, 0x1401, 0x0000);
    }
    SECTION("in the subcommand: the command is still echoed") {
        CHECK(wire.exchange(cpu, {"", "04010Z00D*0001000001"}) == wire.expect(error(0xC050, 0x0401, 0x0000)));
    }
    SECTION("in the command: nothing readable to echo, command 0000 (chosen)") {
        CHECK(wire.exchange(cpu, {"", "04G10000D*0001000001"}) == wire.expect(error(0xC050, 0x0000, 0x0000)));
    }
    SECTION("in the monitoring timer") {
        Wire bad_timer = wire;
        auto frame = wire.request(read_words_req(Form::Q, "D100", 1));
        frame[wire.header(false, 0).size()] = 'x';
        CHECK(bad_timer.show(run(cpu, frame)) == wire.expect(error(0xC050, 0x0000, 0x0000)));
    }
}
