// The extended device specification (subcommands 008x, SLMP Reference Manual
// Appendix 1): the worked examples J1, U1, U3E0, JZ, DZ, @D0 and @D0Z2 byte
// for byte (binary and ASCII, 3E and 4E), then what each form reaches —
// a network's link devices, a module's buffer memory, the CPU buffer memory —
// index registers Z/LZ, indirect "@", and the errors.
//
// "(inferred)" in the spec, and how the implementation resolves it:
//  - every ASCII form of JZ/DZ/@ beyond the printed characters: the field
//    widths of §7.1; "@" is accepted as "@0" and as "0@";
//  - @D0's meaning: D0 (low) and D1 (high) hold the number of the device of
//    the same kind that is meant (ADRSET's real encoding is CPU-internal);
//  - @D0Z2: the modification applies first (D0+Z2 = D4), then the indirection.
#include "support/device_commands.hpp"

using namespace slmp;
using namespace slmp::test;
using devicemodel::Cpu;

namespace {

devicemodel::DeviceMemory& net(Cpu& cpu, std::uint16_t n) {
    return *cpu.network(n);
}
devicemodel::DeviceMemory& module_memory(Cpu& cpu) {
    return cpu.module(3)->memory;
}

// A 0401 word read of one point around an extended device field.
Payload read1(std::uint16_t sub, const Payload& dev) {
    return word(0x0401) + word(sub) + dev + word(1);
}

}  // namespace

TEST_CASE("§7.2 Example J1: W100 of network 1 (J1¥W100), 0080", "[extended][spec]") {
    auto cpu = make_station();
    net(cpu, 1).set_value(spec_of("W"), 0x100, 0x0123);
    cpu.memory().set_value(spec_of("W"), 0x100, 0x0999);  // the CPU's own W100 is another device
    auto wire = GENERATE(kBinary3E, kBinary4E, kAscii3E, kAscii4E);
    const Payload j1{"00 00 00 01 00 B4 00 00 01 00 F9",
                     "00"
                     "J001"
                     "000"
                     "W*"
                     "000100"
                     "000"};
    CHECK(wire.data(ext_device(Form::Q, "W100", link_direct(1))) == wire.data(j1));
    CHECK(wire.exchange(cpu, read1(0x0080, j1)) == wire.expect(ok(word(0x0123))));
    SECTION("write through J1\\W100 reaches the network, not the CPU's W") {
        CHECK(wire.exchange(cpu, word(0x1401) + word(0x0080) + j1 + word(1) + word(0xBEEF)) == wire.expect(ok()));
        CHECK(net(cpu, 1).value(spec_of("W"), 0x100) == 0xBEEF);
        CHECK(net(cpu, 2).value(spec_of("W"), 0x100) == 0);
        CHECK(cpu.memory().value(spec_of("W"), 0x100) == 0x0999);
    }
    SECTION("iQ-R form 0082 (derived): 10-digit ASCII number, hex for W") {
        auto j1_iqr = ext_device(Form::IQR, "W100", link_direct(1));
        CHECK(j1_iqr.ascii == "00J0010000W***00000001000000");
        CHECK(j1_iqr.binary == "00 00 00 01 00 00 B4 00 00 00 01 00 F9");
        CHECK(wire.exchange(cpu, read1(0x0082, j1_iqr)) == wire.expect(ok(word(0x0123))));
    }
}

TEST_CASE("§7.3 Example U1: buffer memory 1 of the module at start I/O 0030 (U3¥G1), 0080", "[extended][spec]") {
    auto cpu = make_station();
    module_memory(cpu).set_value(spec_of("G"), 1, 0x03E8);
    auto wire = GENERATE(kBinary3E, kBinary4E, kAscii3E, kAscii4E);
    const Payload u1{"00 00 01 00 00 AB 00 00 03 00 F8",
                     "00"
                     "U003"
                     "000"
                     "G*"
                     "000001"
                     "000"};
    CHECK(wire.data(ext_device(Form::Q, "G1", module_access(3))) == wire.data(u1));
    CHECK(wire.exchange(cpu, read1(0x0080, u1)) == wire.expect(ok(word(0x03E8))));
    SECTION("the module's last word, one past it") {
        module_memory(cpu).set_value(spec_of("G"), 4095, 0x4095);
        CHECK(wire.exchange(cpu, read1(0x0082, ext_device(Form::IQR, "G4095", module_access(3)))) ==
              wire.expect(ok(word(0x4095))));
        CHECK(wire.exchange(cpu, read1(0x0082, ext_device(Form::IQR, "G4096", module_access(3)))) ==
              wire.expect(error(0x4031, 0x0401, 0x0082)));
        CHECK(wire.exchange(cpu, word(0x0401) + word(0x0082) + ext_device(Form::IQR, "G4095", module_access(3)) +
                                     word(2)) == wire.expect(error(0x4031, 0x0401, 0x0082)));
    }
}

TEST_CASE("§7.4 Example U3E0: CPU buffer memory 1 of CPU No.1 (U3E0¥G1), 0082", "[extended][spec]") {
    auto cpu = make_station();
    cpu.memory().set_value(spec_of("G"), 1, 0x5A5A);
    auto wire = GENERATE(kBinary3E, kBinary4E, kAscii3E, kAscii4E);
    const Payload u3e0{"00 00 01 00 00 00 AB 00 00 00 E0 03 FA",
                       "00"
                       "U3E0"
                       "0000"
                       "G***"
                       "0000000001"
                       "0000"};
    CHECK(wire.data(ext_device(Form::IQR, "G1", cpu_buffer())) == wire.data(u3e0));
    CHECK(wire.exchange(cpu, read1(0x0082, u3e0)) == wire.expect(ok(word(0x5A5A))));
    SECTION("HG, the fixed-cycle area, and the ends of both") {
        cpu.memory().set_value(spec_of("HG"), 20, 0x0020);
        CHECK(wire.exchange(cpu, read1(0x0082, ext_device(Form::IQR, "HG20", cpu_buffer()))) ==
              wire.expect(ok(word(0x0020))));
        CHECK(wire.exchange(cpu, read1(0x0082, ext_device(Form::IQR, "HG6143", cpu_buffer()))) ==
              wire.expect(ok(word(0))));
        CHECK(wire.exchange(cpu, read1(0x0082, ext_device(Form::IQR, "HG6144", cpu_buffer()))) ==
              wire.expect(error(0x4031, 0x0401, 0x0082)));
        CHECK(wire.exchange(cpu, read1(0x0082, ext_device(Form::IQR, "G524287", cpu_buffer()))) ==
              wire.expect(ok(word(0))));
        CHECK(wire.exchange(cpu, read1(0x0082, ext_device(Form::IQR, "G524288", cpu_buffer()))) ==
              wire.expect(error(0x4031, 0x0401, 0x0082)));
    }
}

TEST_CASE("U3E□ beyond CPU No.4 and U□ moved onto U3E0 by Z answer alike in binary and ASCII", "[extended]") {
    auto cpu = make_station();
    cpu.memory().set_value(spec_of("G"), 1, 0x5A5A);
    auto wire = GENERATE(kBinary3E, kBinary4E, kAscii3E, kAscii4E);
    // ASCII has no F8/FA byte: "U3E4" is a module number there and a CPU number
    // in binary; either way nothing answers at 3E4 (4043, as a missing module).
    CHECK(wire.exchange(cpu, read1(0x0082, ext_device(Form::IQR, "G1", cpu_buffer(0x3E4)))) ==
          wire.expect(error(0x4043, 0x0401, 0x0082)));
    // U3DF with Z0 = 1 lands on U3E0: the CPU buffer memory, in both codecs.
    cpu.memory().set_value(spec_of("Z"), 0, 1);
    auto moved = cpu_buffer(0x3DF);
    moved.target_index = z(0);
    CHECK(wire.exchange(cpu, read1(0x0082, ext_device(Form::IQR, "G1", moved))) == wire.expect(ok(word(0x5A5A))));
    auto module_moved = module_access(0x3DF);
    module_moved.target_index = z(0);
    CHECK(wire.exchange(cpu, read1(0x0082, ext_device(Form::IQR, "G1", module_moved))) ==
          wire.expect(ok(word(0x5A5A))));
}

TEST_CASE("§7.5 Example JZ: W100 of network 1+Z0 (J1Z0¥W100), in 0403/0080", "[extended][spec]") {
    auto cpu = make_station();
    net(cpu, 1).set_value(spec_of("W"), 0x100, 0x0001);
    net(cpu, 2).set_value(spec_of("W"), 0x100, 0x0002);
    auto wire = GENERATE(kBinary3E, kBinary4E, kAscii3E, kAscii4E);
    const Payload jz{"00 00 00 01 00 B4 00 40 01 00 F9",
                     "00"
                     "J001"
                     "Z00"
                     "W*"
                     "000100"
                     "000"};
    Extension ext = link_direct(1);
    ext.target_index = z(0);
    CHECK(wire.data(ext_device(Form::Q, "W100", ext)) == wire.data(jz));
    const auto rr = random_read_req(0x0080, {jz}, {});
    CHECK(wire.exchange(cpu, rr) == wire.expect(ok(word(0x0001))));
    cpu.memory().set_value(spec_of("Z"), 0, 1);
    CHECK(wire.exchange(cpu, rr) == wire.expect(ok(word(0x0002))));
    // Network 1 + 5 = 6 is not there: 4043 (chosen, as for a missing module).
    cpu.memory().set_value(spec_of("Z"), 0, 5);
    CHECK(wire.exchange(cpu, rr) == wire.expect(error(0x4043, 0x0403, 0x0080)));
}

TEST_CASE("§7.6 Example DZ: D100+Z4 (D100Z4), in 0403/0080", "[extended][spec]") {
    auto cpu = make_station();
    for (std::uint32_t n = 90; n < 120; ++n) cpu.memory().set_value(spec_of("D"), n, n);
    auto wire = GENERATE(kBinary3E, kBinary4E, kAscii3E, kAscii4E);
    // Binary confirmed byte for byte by the English iQ-R manual.
    const Payload dz{"04 40 64 00 00 A8 00 00 00 00 00",
                     "00"
                     "0000"
                     "000"
                     "D*"
                     "000100"
                     "Z04"};
    Extension ext;
    ext.device_index = z(4);
    CHECK(wire.data(ext_device(Form::Q, "D100", ext)) == wire.data(dz));
    cpu.memory().set_value(spec_of("Z"), 4, 4);
    CHECK(wire.exchange(cpu, random_read_req(0x0080, {dz}, {})) == wire.expect(ok(word(104))));
    cpu.memory().set_value(spec_of("Z"), 4, 0xFFF6);  // Z is signed: -10
    CHECK(wire.exchange(cpu, random_read_req(0x0080, {dz}, {})) == wire.expect(ok(word(90))));
    SECTION("the same through 1402/0080 and 0801+0802") {
        cpu.memory().set_value(spec_of("Z"), 4, 4);
        CHECK(wire.exchange(cpu, random_write_words_req(0x0080, {{dz, 0x0BAD}}, {})) == wire.expect(ok()));
        CHECK(cpu.memory().value(spec_of("D"), 104) == 0x0BAD);
        CHECK(cpu.memory().value(spec_of("D"), 100) == 100);
        auto engine = engine_for(cpu);
        Connection conn{engine};
        CHECK(conn.exchange(wire, monitor_entry_req(0x0080, {dz}, {})) == wire.expect(ok()));
        CHECK(conn.exchange(wire, monitor_execute_req()) == wire.expect(ok(word(0x0BAD))));
    }
    SECTION("iQ-R form: \"Z 04\" and LZ (\"LZ01\", 32-bit signed)") {
        auto dz_iqr = ext_device(Form::IQR, "D100", ext);
        CHECK(dz_iqr.ascii == "0000000000D***0000000100Z 04");
        CHECK(dz_iqr.binary == "04 40 64 00 00 00 A8 00 00 00 00 00 00");
        CHECK(wire.exchange(cpu, random_read_req(0x0082, {dz_iqr}, {})) == wire.expect(ok(word(90))));
        Extension lz1;
        lz1.device_index = lz(1);
        cpu.memory().set_value(spec_of("LZ"), 1, 0xFFFFFFF6);  // -10
        auto d100lz1 = ext_device(Form::IQR, "D100", lz1);
        CHECK(d100lz1.ascii == "0000000000D***0000000100LZ01");
        CHECK(wire.exchange(cpu, random_read_req(0x0082, {d100lz1}, {})) == wire.expect(ok(word(90))));
        cpu.memory().set_value(spec_of("LZ"), 1, 20000);  // D20100 is past D10239
        CHECK(wire.exchange(cpu, random_read_req(0x0082, {d100lz1}, {})) == wire.expect(error(0x4031, 0x0403, 0x0082)));
    }
}

TEST_CASE("§7.7 Examples @D0 and @D0Z2: indirect specification, in 0403/0080", "[extended][spec]") {
    auto cpu = make_station();
    cpu.memory().set_value(spec_of("D"), 100, 0x0100);
    cpu.memory().set_value(spec_of("D"), 0, 100);  // D1:D0 = 100: "@D0" is D100
    cpu.memory().set_value(spec_of("D"), 4, 100);  // D5:D4 = 100
    cpu.memory().set_value(spec_of("Z"), 2, 4);
    auto wire = GENERATE(kBinary3E, kBinary4E, kAscii3E, kAscii4E);
    // Binary inferred (matches the English manual); the ASCII "@0" placement is inferred.
    const Payload at_d0{"00 08 00 00 00 A8 00 00 00 00 00",
                        "@0"
                        "0000"
                        "000"
                        "D*"
                        "000000"
                        "000"};
    const Payload at_d0z2{"02 48 00 00 00 A8 00 00 00 00 00",
                          "@0"
                          "0000"
                          "000"
                          "D*"
                          "000000"
                          "Z02"};
    Extension at;
    at.indirect = true;
    CHECK(wire.data(ext_device(Form::Q, "D0", at)) == wire.data(at_d0));
    at.device_index = z(2);
    CHECK(wire.data(ext_device(Form::Q, "D0", at)) == wire.data(at_d0z2));
    CHECK(wire.exchange(cpu, random_read_req(0x0080, {at_d0, at_d0z2}, {})) ==
          wire.expect(ok(words({0x0100, 0x0100}))));
    SECTION("\"0@\" is accepted as well in ASCII") {
        if (!wire.ascii()) return;
        const Payload other{"",
                            "0@"
                            "0000"
                            "000"
                            "D*"
                            "000000"
                            "000"};
        CHECK(wire.exchange(cpu, random_read_req(0x0080, {other}, {})) == wire.expect(ok(word(0x0100))));
    }
    SECTION("write through @D0 (1402/0080)") {
        CHECK(wire.exchange(cpu, random_write_words_req(0x0080, {{at_d0, 0x7777}}, {})) == wire.expect(ok()));
        CHECK(cpu.memory().value(spec_of("D"), 100) == 0x7777);
        CHECK(cpu.memory().value(spec_of("D"), 0) == 100);
    }
    SECTION("an address past the end -> 4031; indirect through a bit device -> C05C") {
        cpu.memory().set_value(spec_of("D"), 1, 1);  // D1:D0 = 65636
        CHECK(wire.exchange(cpu, random_read_req(0x0080, {at_d0}, {})) == wire.expect(error(0x4031, 0x0403, 0x0080)));
        Extension at_m;
        at_m.indirect = true;
        CHECK(wire.exchange(cpu, random_read_req(0x0080, {ext_device(Form::Q, "M0", at_m)}, {})) ==
              wire.expect(error(0xC05C, 0x0403, 0x0080)));
        // The pointer pair itself must exist: @D10239 needs D10240.
        CHECK(wire.exchange(cpu, random_read_req(0x0080, {ext_device(Form::Q, "D10239", at)}, {})) ==
              wire.expect(error(0x4031, 0x0403, 0x0080)));
    }
}

TEST_CASE("Extended forms in every device command reach the same memory", "[extended]") {
    auto cpu = make_station();
    auto wire = GENERATE(kBinary3E, kAscii3E);
    const auto u3g = [](const char* g) { return ext_device(Form::IQR, g, module_access(3)); };
    const auto cpu_g = [](const char* g) { return ext_device(Form::IQR, g, cpu_buffer()); };
    const auto j1 = [](Form f, const char* d) { return ext_device(f, d, link_direct(1)); };
    SECTION("1402/0082 into U3\\G, 0406/0082 and 0403/0082 back") {
        CHECK(wire.exchange(cpu, random_write_words_req(0x0082, {{u3g("G10"), 0x1010}}, {{u3g("G20"), 0x20212022}})) ==
              wire.expect(ok()));
        CHECK(module_memory(cpu).value(spec_of("G"), 21) == 0x2021);
        CHECK(wire.exchange(cpu, block_read_req(0x0082, {{u3g("G10"), 1}, {u3g("G20"), 2}}, {})) ==
              wire.expect(ok(words({0x1010, 0x2022, 0x2021}))));
        CHECK(wire.exchange(cpu, random_read_req(0x0082, {u3g("G10")}, {u3g("G20")})) ==
              wire.expect(ok(word(0x1010) + dword(0x20212022))));
    }
    SECTION("1406/0082 into U3E0\\G; 0401/0082 and 0801/0082 back") {
        CHECK(wire.exchange(cpu, block_write_req(0x0082, {{cpu_g("G100"), {1, 2, 3}}}, {})) == wire.expect(ok()));
        CHECK(cpu.memory().value(spec_of("G"), 102) == 3);
        CHECK(wire.exchange(cpu, word(0x0401) + word(0x0082) + cpu_g("G100") + word(3)) ==
              wire.expect(ok(words({1, 2, 3}))));
        auto engine = engine_for(cpu);
        Connection conn{engine};
        CHECK(conn.exchange(wire, monitor_entry_req(0x0082, {cpu_g("G101")}, {})) == wire.expect(ok()));
        CHECK(conn.exchange(wire, monitor_execute_req()) == wire.expect(ok(word(2))));
    }
    SECTION("link bits: 1402/0081 and 1401/0081 into J1\\B, J1\\X; read in bits and words") {
        CHECK(wire.exchange(cpu, random_write_bits_req(0x0081, {{j1(Form::Q, "B1F"), true},
                                                                {j1(Form::Q, "X0"), true}})) == wire.expect(ok()));
        CHECK(net(cpu, 1).bit(spec_of("B"), 0x1F));
        CHECK_FALSE(cpu.memory().bit(spec_of("B"), 0x1F));
        CHECK(wire.exchange(cpu, word(0x1401) + word(0x0083) + j1(Form::IQR, "SB10") + word(3) + bits({1, 0, 1})) ==
              wire.expect(ok()));
        CHECK(wire.exchange(cpu, word(0x0401) + word(0x0081) + j1(Form::Q, "SB10") + word(4)) ==
              wire.expect(ok(bits({1, 0, 1, 0}))));
        CHECK(wire.exchange(cpu, block_read_req(0x0080, {}, {{j1(Form::Q, "B10"), 1}})) ==
              wire.expect(ok(word(0x8000))));
    }
}

TEST_CASE("Extended-form errors", "[extended][errors]") {
    auto cpu = make_station();
    auto wire = GENERATE(kBinary3E, kAscii3E);
    auto before = snapshot(cpu);
    SECTION("a network, module or CPU that is not there -> 4043 (chosen)") {
        CHECK(wire.exchange(cpu, read1(0x0080, ext_device(Form::Q, "W0", link_direct(9)))) ==
              wire.expect(error(0x4043, 0x0401, 0x0080)));
        CHECK(wire.exchange(cpu, read1(0x0080, ext_device(Form::Q, "G0", module_access(4)))) ==
              wire.expect(error(0x4043, 0x0401, 0x0080)));
        CHECK(wire.exchange(cpu, read1(0x0082, ext_device(Form::IQR, "G0", cpu_buffer(0x3E1)))) ==
              wire.expect(error(0x4043, 0x0401, 0x0082)));
    }
    SECTION("a device the extension does not have -> C05B") {
        CHECK(wire.exchange(cpu, read1(0x0080, ext_device(Form::Q, "D0", link_direct(1)))) ==
              wire.expect(error(0xC05B, 0x0401, 0x0080)));
        CHECK(wire.exchange(cpu, read1(0x0080, ext_device(Form::Q, "D0", module_access(3)))) ==
              wire.expect(error(0xC05B, 0x0401, 0x0080)));
        CHECK(wire.exchange(cpu, read1(0x0082, ext_device(Form::IQR, "W0", cpu_buffer()))) ==
              wire.expect(error(0xC05B, 0x0401, 0x0082)));
    }
    SECTION("G and HG named without an extension -> C05B (real-CPU measurements)") {
        CHECK(wire.exchange(cpu, read1(0x0082, ext_device(Form::IQR, "G0"))) ==
              wire.expect(error(0xC05B, 0x0401, 0x0082)));
        CHECK(wire.exchange(cpu, read_words_req(Form::IQR, "G0", 1)) == wire.expect(error(0xC05B, 0x0401, 0x0002)));
        CHECK(wire.exchange(cpu, read_words_req(Form::IQR, "HG0", 1)) == wire.expect(error(0xC05B, 0x0401, 0x0002)));
        CHECK(wire.exchange(cpu, random_read_req(0x0000, {device(Form::Q, "G0")}, {})) ==
              wire.expect(error(0xC05B, 0x0403, 0x0000)));
    }
    SECTION("rejected extended writes change nothing") {
        CHECK(wire.exchange(cpu, random_write_words_req(0x0082,
                                                        {{ext_device(Form::IQR, "G0", module_access(3)), 1},
                                                         {ext_device(Form::IQR, "G4096", module_access(3)), 1}},
                                                        {})) == wire.expect(error(0x4031, 0x1402, 0x0082)));
        CHECK(wire.exchange(cpu, block_write_req(0x0080,
                                                 {{ext_device(Form::Q, "W0", link_direct(1)), {1}},
                                                  {ext_device(Form::Q, "W0", link_direct(7)), {1}}},
                                                 {})) == wire.expect(error(0x4043, 0x1406, 0x0080)));
        CHECK((snapshot(cpu) == before));
        CHECK(net(cpu, 1).value(spec_of("W"), 0) == 0);
        CHECK(module_memory(cpu).value(spec_of("G"), 0) == 0);
    }
    SECTION("a plain-device field where 008x expects the extended one -> C061 / rejected") {
        // 0401/0080 with the 4-byte plain Q form: the extended reader runs short.
        CHECK(wire.exchange(cpu, word(0x0401) + word(0x0080) + device(Form::Q, "D0") + word(1)) ==
              wire.expect(error(0xC061, 0x0401, 0x0080)));
    }
}
