// Buffer memory by address (SLMP Reference Manual §5.4–§5.5): Memory Read/Write
// 0613/1613 on the own station's buffer memory and Extend Unit Read/Write
// 0601/1601 on a module's, with the manuals' examples byte for byte, the limits,
// the module numbers real CPUs refuse (real-CPU measurements), and proof that
// 0613 and U3E0\G, 0601 and U\G are one store each.
#include "support/device_commands.hpp"

using namespace slmp;
using namespace slmp::test;
using devicemodel::Cpu;

namespace {

// The manual's Q62DA at I/O 30H–4FH: module No. 0003, head address 1008H.
Cpu with_q62da(const std::string& profile = "R08CPU") {
    auto cpu = make_cpu(profile);
    cpu.add_module(3, "Q62DA", 4096, 0x1008);
    return cpu;
}
devicemodel::DeviceMemory& q62da(Cpu& cpu) {
    return cpu.module(3)->memory;
}

// 0613 example: 78H = 0500H, 79H = 09C1H, ..., 81H = 00C8H (words 3-9 not shown: chosen).
const std::vector<std::uint16_t> k0613 = {0x0500, 0x09C1, 0x0003, 0x0004, 0x0005,
                                          0x0006, 0x0007, 0x0008, 0x0009, 0x00C8};

}  // namespace

TEST_CASE("§3 0613: read 78H-81H (10 words) as printed", "[buffer][spec]") {
    auto cpu = make_cpu("R08CPU");
    cpu.memory().write_words(spec_of("G"), 0x78, k0613);  // iQ-R: the CPU buffer memory (U3E0\G)
    auto wire = GENERATE(kBinary3E, kBinary4E, kAscii3E, kAscii4E);
    const Payload req{"13 06 00 00 78 00 00 00 0A 00",
                      "06130000"
                      "00000078"
                      "000A"};
    CHECK(wire.data(memory_read_req(0x78, 10)) == wire.data(req));
    // The manual prints the response's first words as "00 05" "C1 09" (binary) / "0500" "09C1".
    CHECK(wire.exchange(cpu, req) == wire.expect(ok(words(k0613))));
}

TEST_CASE("§3 1613: write 2680H-2683H as printed (data 2 and 3 chosen), then 0613 and U3E0¥G", "[buffer][spec]") {
    auto cpu = make_cpu("R08CPU");
    auto wire = GENERATE(kBinary3E, kBinary4E, kAscii3E, kAscii4E);
    const Payload req{"13 16 00 00 80 26 00 00 04 00 00 20 34 12 78 56 00 00",
                      "16130000"
                      "00002680"
                      "0004"
                      "2000"
                      "1234"
                      "5678"
                      "0000"};
    CHECK(wire.data(memory_write_req(0x2680, {0x2000, 0x1234, 0x5678, 0x0000})) == wire.data(req));
    cpu.memory().set_value(spec_of("G"), 0x2683, 0xFFFF);
    CHECK(wire.exchange(cpu, req) == wire.expect(ok()));
    CHECK(wire.exchange(cpu, memory_read_req(0x267F, 6)) == wire.expect(ok(words({0, 0x2000, 0x1234, 0x5678, 0, 0}))));
    CHECK(wire.exchange(cpu, word(0x0401) + word(0x0082) + ext_device(Form::IQR, "G9856", cpu_buffer()) + word(4)) ==
          wire.expect(ok(words({0x2000, 0x1234, 0x5678, 0}))));
    // And the other way round: U3E0\G written, 0613 reads it.
    CHECK(wire.exchange(cpu, word(0x1401) + word(0x0082) + ext_device(Form::IQR, "G10", cpu_buffer()) + word(1) +
                                 word(0xA5A5)) == wire.expect(ok()));
    CHECK(wire.exchange(cpu, memory_read_req(10, 1)) == wire.expect(ok(word(0xA5A5))));
}

TEST_CASE("0613/1613 word counts 1..480 and the end of the buffer", "[buffer][limits]") {
    auto wire = GENERATE(kBinary3E, kAscii3E);
    SECTION("R08CPU: the CPU buffer memory, 524288 words, out of range 4031") {
        auto cpu = make_cpu("R08CPU");
        CHECK(wire.exchange(cpu, memory_read_req(0, 479)) ==
              wire.expect(ok(words(std::vector<std::uint16_t>(479, 0)))));
        CHECK(wire.exchange(cpu, memory_read_req(0, 480)) ==
              wire.expect(ok(words(std::vector<std::uint16_t>(480, 0)))));
        CHECK(wire.exchange(cpu, memory_read_req(0, 481)) == wire.expect(error(0xC051, 0x0613, 0x0000)));
        CHECK(wire.exchange(cpu, memory_read_req(0, 0)) == wire.expect(error(0xC051, 0x0613, 0x0000)));
        CHECK(wire.exchange(cpu, memory_read_req(524287, 1)) == wire.expect(ok(word(0))));
        CHECK(wire.exchange(cpu, memory_read_req(524287, 2)) == wire.expect(error(0x4031, 0x0613, 0x0000)));
        auto before = snapshot(cpu);
        CHECK(wire.exchange(cpu, memory_write_req(0, std::vector<std::uint16_t>(481, 1))) ==
              wire.expect(error(0xC051, 0x1613, 0x0000)));
        CHECK(wire.exchange(cpu, memory_write_req(524287, {1, 2})) == wire.expect(error(0x4031, 0x1613, 0x0000)));
        // Fewer data words than the count: C061.
        CHECK(wire.exchange(cpu, word(0x1613) + word(0) + dword(0) + word(2) + word(1)) ==
              wire.expect(error(0xC061, 0x1613, 0x0000)));
        CHECK((snapshot(cpu) == before));
        CHECK(wire.exchange(cpu, memory_write_req(0, std::vector<std::uint16_t>(480, 0x0101))) == wire.expect(ok()));
        CHECK(cpu.memory().value(spec_of("G"), 479) == 0x0101);
        CHECK(cpu.memory().value(spec_of("G"), 480) == 0);
    }
    SECTION("Q06UDVCPU via QJ71E71-100: the module's own 24576-word buffer, out of range C056") {
        auto cpu = make_cpu("Q06UDVCPU-QJ71E71");
        CHECK(wire.exchange(cpu, memory_write_req(0x5FFF, {0x1234})) == wire.expect(ok()));
        CHECK(wire.exchange(cpu, memory_read_req(0x5FFF, 1)) == wire.expect(ok(word(0x1234))));
        CHECK(wire.exchange(cpu, memory_read_req(0x5FFF, 2)) == wire.expect(error(0xC056, 0x0613, 0x0000)));
        CHECK(wire.exchange(cpu, memory_read_req(0x6000, 1)) == wire.expect(error(0xC056, 0x0613, 0x0000)));
        CHECK(cpu.station_buffer().value(spec_of("G"), 0x5FFF) == 0x1234);
    }
    SECTION("QnU, L and FX5U built-in ports refuse 0613 (C059)") {
        for (const char* name : {"Q26UDEHCPU", "L26CPU-BT", "FX5U-32MR"}) {
            INFO(name);
            auto cpu = make_cpu(name);
            CHECK(wire.exchange(cpu, memory_read_req(0, 1)) == wire.expect(error(0xC059, 0x0613, 0x0000)));
        }
    }
}

TEST_CASE("§4 0601: read Q62DA buffer memory 1H-2H as printed", "[buffer][spec]") {
    auto cpu = with_q62da();
    q62da(cpu).write_words(spec_of("G"), 1, std::vector<std::uint16_t>{0x0001, 0x0012});
    auto wire = GENERATE(kBinary3E, kBinary4E, kAscii3E, kAscii4E);
    const Payload req{"01 06 00 00 0A 10 00 00 04 00 03 00",
                      "06010000"
                      "0000100A"
                      "0004"
                      "0003"};
    CHECK(wire.data(extend_unit_read_req(0x100A, 4, 3)) == wire.data(req));
    // Low byte first in both codes: "0100" "1200" / 01 00 12 00.
    CHECK(wire.exchange(cpu, req) == wire.expect(ok(Payload{"01 00 12 00", "01001200"})));
}

TEST_CASE("§4 1601: write 03E8H to Q62DA buffer memory 18H as printed, U3¥G24 reads it", "[buffer][spec]") {
    auto cpu = with_q62da();
    auto wire = GENERATE(kBinary3E, kBinary4E, kAscii3E, kAscii4E);
    // Address (18H × 2) + 1008H = 1038H; data "E803" = 03E8H, low byte first.
    const Payload req{"01 16 00 00 38 10 00 00 02 00 03 00 E8 03",
                      "16010000"
                      "00001038"
                      "0002"
                      "0003"
                      "E803"};
    CHECK(wire.data(extend_unit_write_req(0x1038, 3, {0xE8, 0x03})) == wire.data(req));
    CHECK(wire.exchange(cpu, req) == wire.expect(ok()));
    CHECK(q62da(cpu).value(spec_of("G"), 0x18) == 0x03E8);
    CHECK(wire.exchange(cpu, word(0x0401) + word(0x0080) + ext_device(Form::Q, "G24", module_access(3)) + word(1)) ==
          wire.expect(ok(word(0x03E8))));
    // And back: U3\G written through 1401/0080, 0601 reads the bytes.
    CHECK(wire.exchange(cpu, word(0x1401) + word(0x0080) + ext_device(Form::Q, "G2", module_access(3)) + word(1) +
                                 word(0xC109)) == wire.expect(ok()));
    CHECK(wire.exchange(cpu, extend_unit_read_req(0x100C, 2, 3)) == wire.expect(ok(memory_bytes({0x09, 0xC1}))));
}

TEST_CASE("0601/1601 byte addressing: odd start addresses split words", "[buffer]") {
    auto cpu = with_q62da();
    auto wire = GENERATE(kBinary3E, kAscii3E);
    q62da(cpu).write_words(spec_of("G"), 0, std::vector<std::uint16_t>{0x2211, 0x4433, 0x6655});
    // 1009H is the high byte of word 0.
    CHECK(wire.exchange(cpu, extend_unit_read_req(0x1009, 4, 3)) ==
          wire.expect(ok(memory_bytes({0x22, 0x33, 0x44, 0x55}))));
    CHECK(wire.exchange(cpu, extend_unit_write_req(0x1009, 3, {0xAA, 0xBB})) == wire.expect(ok()));
    CHECK(q62da(cpu).value(spec_of("G"), 0) == 0xAA11);
    CHECK(q62da(cpu).value(spec_of("G"), 1) == 0x44BB);
}

TEST_CASE("0601/1601 limits and module numbers", "[buffer][limits]") {
    auto cpu = with_q62da();
    auto wire = GENERATE(kBinary3E, kAscii3E);
    auto before = snapshot(cpu);
    SECTION("byte count 2..1920") {
        CHECK(wire.exchange(cpu, extend_unit_read_req(0x1008, 1920, 3)) ==
              wire.expect(ok(memory_bytes(std::vector<std::uint8_t>(1920, 0)))));
        CHECK(wire.exchange(cpu, extend_unit_read_req(0x1008, 1921, 3)) == wire.expect(error(0xC051, 0x0601, 0x0000)));
        CHECK(wire.exchange(cpu, extend_unit_read_req(0x1008, 2, 3)) == wire.expect(ok(memory_bytes({0, 0}))));
        CHECK(wire.exchange(cpu, extend_unit_read_req(0x1008, 1, 3)) == wire.expect(error(0xC051, 0x0601, 0x0000)));
        CHECK(wire.exchange(cpu, extend_unit_write_req(0x1008, 3, std::vector<std::uint8_t>(1921, 1))) ==
              wire.expect(error(0xC051, 0x1601, 0x0000)));
    }
    SECTION("module 0000 -> 4043, 03FF -> 4080 (real-CPU measurements), absent -> 4043") {
        CHECK(wire.exchange(cpu, extend_unit_read_req(0x1008, 2, 0x0000)) ==
              wire.expect(error(0x4043, 0x0601, 0x0000)));
        CHECK(wire.exchange(cpu, extend_unit_read_req(0x1008, 2, 0x03FF)) ==
              wire.expect(error(0x4080, 0x0601, 0x0000)));
        CHECK(wire.exchange(cpu, extend_unit_read_req(0x1008, 2, 0x0004)) ==
              wire.expect(error(0x4043, 0x0601, 0x0000)));
        CHECK(wire.exchange(cpu, extend_unit_write_req(0x1008, 0x0000, {1, 2})) ==
              wire.expect(error(0x4043, 0x1601, 0x0000)));
        CHECK(wire.exchange(cpu, extend_unit_write_req(0x1008, 0x03FF, {1, 2})) ==
              wire.expect(error(0x4080, 0x1601, 0x0000)));
    }
    SECTION("below the head address or past the buffer -> out of range") {
        CHECK(wire.exchange(cpu, extend_unit_read_req(0x1006, 2, 3)) == wire.expect(error(0x4031, 0x0601, 0x0000)));
        // 4096 words = 8192 bytes from 1008H: the last byte is 3007H.
        CHECK(wire.exchange(cpu, extend_unit_read_req(0x3006, 2, 3)) == wire.expect(ok(memory_bytes({0, 0}))));
        CHECK(wire.exchange(cpu, extend_unit_read_req(0x3007, 2, 3)) == wire.expect(error(0x4031, 0x0601, 0x0000)));
        CHECK(wire.exchange(cpu, extend_unit_write_req(0x3006, 3, {1, 2, 3, 4})) ==
              wire.expect(error(0x4031, 0x1601, 0x0000)));
    }
    SECTION("short write data -> C061") {
        CHECK(wire.exchange(cpu, word(0x1601) + word(0) + dword(0x1008) + word(4) + word(3) + byte(1)) ==
              wire.expect(error(0xC061, 0x1601, 0x0000)));
    }
    CHECK((snapshot(cpu) == before));
    CHECK(q62da(cpu).value(spec_of("G"), 0) == 0);
}

TEST_CASE("0601 with module number 03E0 reaches the CPU buffer memory (hardware-behaviour §7)", "[buffer]") {   // signposts: allow (the name ctest lists)
    auto cpu = make_cpu("R08CPU");
    auto wire = GENERATE(kBinary3E, kAscii3E);
    cpu.memory().set_value(spec_of("G"), 5, 0xBEEF);
    // The CPU buffer memory has no head-address table entry: byte address = word × 2 (chosen).
    CHECK(wire.exchange(cpu, extend_unit_read_req(10, 2, 0x03E0)) == wire.expect(ok(memory_bytes({0xEF, 0xBE}))));
    CHECK(wire.exchange(cpu, extend_unit_write_req(12, 0x03E0, {0x34, 0x12})) == wire.expect(ok()));
    CHECK(wire.exchange(cpu, memory_read_req(6, 1)) == wire.expect(ok(word(0x1234))));
}
