// A multi-CPU system (SLMP Reference Manual, Appendix 3): CPU No.1–4
// are reached through one port with module I/O 03E0–03E3 (03FF = the CPU of
// the port). Each CPU has its own memory; U3E1\G reaches CPU No.2's buffer
// memory from anywhere, but only CPU No.2 writes it (414A for the others); Entry/Execute Monitor, Memory 0613/1613, Self Test 0619
// and Clear Error 1617 cannot reach CPU No.2–4 (C059); a CPU that is not
// configured answers 4B02 (chosen, docs/end-codes.md).
#include "support/device_commands.hpp"

using namespace slmp;
using namespace slmp::test;
using devicemodel::Cpu;

namespace {

struct MultiCpu {
    Cpu one = make_cpu("R08CPU");
    Cpu two = make_cpu("R120PCPU");
    protocol::Engine engine{one, port_of(one)};
    MultiCpu() { engine.add_cpu(2, two, port_of(two)); }
};

}  // namespace

TEST_CASE("CPU No.2 (module I/O 03E1) has its own device memory", "[multi_cpu]") {
    MultiCpu station;
    Connection conn{station.engine};
    auto wire = GENERATE(kBinary3E, kBinary4E, kAscii3E, kAscii4E);
    const auto r1 = cpu_route(1), r2 = cpu_route(2);
    CHECK(conn.exchange(wire, write_words_req(Form::Q, "D0", {0x0002}), r2) == wire.expect(ok(), r2));
    CHECK(conn.exchange(wire, write_words_req(Form::Q, "D0", {0x0001}), r1) == wire.expect(ok(), r1));
    CHECK(station.two.memory().value(spec_of("D"), 0) == 2);
    CHECK(station.one.memory().value(spec_of("D"), 0) == 1);
    // 03FF is the port's CPU, No.1.
    CHECK(conn.exchange(wire, read_words_req(Form::Q, "D0", 1)) == wire.expect(ok(word(1))));
    CHECK(conn.exchange(wire, read_words_req(Form::Q, "D0", 1), r2) == wire.expect(ok(word(2)), r2));
    SECTION("every device command reaches CPU No.2") {
        CHECK(conn.exchange(wire, random_write_words_req(0x0002, {{device(Form::IQR, "D1"), 0x21}}, {}), r2) ==
              wire.expect(ok(), r2));
        CHECK(conn.exchange(wire, random_write_bits_req(0x0001, {{device(Form::Q, "M3"), true}}), r2) ==
              wire.expect(ok(), r2));
        CHECK(conn.exchange(wire, block_write_req(0x0000, {{device(Form::Q, "D2"), {0x22}}}, {}), r2) ==
              wire.expect(ok(), r2));
        CHECK(conn.exchange(wire, random_read_req(0x0000, {device(Form::Q, "D1"), device(Form::Q, "M0")}, {}), r2) ==
              wire.expect(ok(words({0x21, 0x0008})), r2));
        CHECK(conn.exchange(wire, block_read_req(0x0002, {{device(Form::IQR, "D0"), 3}}, {}), r2) ==
              wire.expect(ok(words({2, 0x21, 0x22})), r2));
        CHECK(station.one.memory().value(spec_of("D"), 1) == 0);
        CHECK_FALSE(station.one.memory().bit(spec_of("M"), 3));
    }
    SECTION("errors from CPU No.2 use its profile and echo its route") {
        // R120PCPU refuses a mixed word+bit 1406 with C056 (R08CPU: C05B).
        auto mixed = block_write_req(0x0000, {{device(Form::Q, "D0"), {1}}}, {{device(Form::Q, "M0"), {1}}});
        CHECK(conn.exchange(wire, mixed, r2) == wire.expect(error(0xC056, 0x1406, 0x0000, r2), r2));
        CHECK(conn.exchange(wire, mixed) == wire.expect(error(0xC05B, 0x1406, 0x0000)));
    }
}

TEST_CASE("U3E1¥G reaches CPU No.2's buffer memory, U3E0¥G CPU No.1's", "[multi_cpu][extended]") {
    MultiCpu station;
    Connection conn{station.engine};
    auto wire = GENERATE(kBinary3E, kAscii3E);
    station.one.memory().set_value(spec_of("G"), 7, 0x0001);
    station.two.memory().set_value(spec_of("G"), 7, 0x0002);
    auto g7 = [](std::uint16_t io) { return ext_device(Form::IQR, "G7", cpu_buffer(io)); };
    // From the port's CPU, and from CPU No.2's own route: the U3E number decides.
    for (auto route : {Route{}, cpu_route(2)}) {
        CHECK(conn.exchange(wire, random_read_req(0x0082, {g7(0x3E0), g7(0x3E1)}, {}), route) ==
              wire.expect(ok(words({1, 2})), route));
    }
    // Each CPU writes only its own buffer memory: from CPU No.1's route a write to
    // U3E1 answers 414A and changes nothing; from CPU No.2's own route it is served.
    const auto write_g7 = [&](std::uint16_t io, std::uint16_t value) {
        return word(0x1401) + word(0x0082) + g7(io) + word(1) + word(value);
    };
    CHECK(conn.exchange(wire, write_g7(0x3E1, 0x2222)) == wire.expect(error(0x414A, 0x1401, 0x0082)));
    CHECK(station.two.memory().value(spec_of("G"), 7) == 0x0002);
    const auto r2 = cpu_route(2);
    CHECK(conn.exchange(wire, write_g7(0x3E1, 0x2222), r2) == wire.expect(ok(), r2));
    CHECK(station.two.memory().value(spec_of("G"), 7) == 0x2222);
    CHECK(conn.exchange(wire, write_g7(0x3E0, 0x1111), r2) == wire.expect(error(0x414A, 0x1401, 0x0082, r2), r2));
    CHECK(station.one.memory().value(spec_of("G"), 7) == 0x0001);
    // The same through HG and through the random and block writes.
    auto hg3 = [](std::uint16_t io) { return ext_device(Form::IQR, "HG3", cpu_buffer(io)); };
    CHECK(conn.exchange(wire, word(0x1401) + word(0x0082) + hg3(0x3E1) + word(1) + word(5)) ==
          wire.expect(error(0x414A, 0x1401, 0x0082)));
    CHECK(conn.exchange(wire, random_write_words_req(0x0082, {{g7(0x3E1), 0x3333}}, {})) ==
          wire.expect(error(0x414A, 0x1402, 0x0082)));
    CHECK(conn.exchange(wire, block_write_req(0x0082, {{g7(0x3E1), {0x4444}}}, {})) ==
          wire.expect(error(0x414A, 0x1406, 0x0082)));
    CHECK(station.two.memory().value(spec_of("G"), 7) == 0x2222);
    CHECK(station.two.memory().value(spec_of("HG"), 3) == 0);
    // Own buffer memory through U3E0 from CPU No.1 is written as before.
    CHECK(conn.exchange(wire, write_g7(0x3E0, 0x0101)) == wire.expect(ok()));
    CHECK(station.one.memory().value(spec_of("G"), 7) == 0x0101);
    // Extend Unit with module number 03E1 reaches the same memory (head address 0):
    // read from anywhere, written only from CPU No.2.
    CHECK(conn.exchange(wire, extend_unit_read_req(14, 2, 0x03E1)) == wire.expect(ok(memory_bytes({0x22, 0x22}))));
    CHECK(conn.exchange(wire, extend_unit_write_req(14, 0x03E1, {0x55, 0x55})) ==
          wire.expect(error(0x414A, 0x1601, 0x0000)));
    CHECK(conn.exchange(wire, extend_unit_write_req(14, 0x03E1, {0x55, 0x55}), r2) == wire.expect(ok(), r2));
    CHECK(station.two.memory().value(spec_of("G"), 7) == 0x5555);
    // CPU No.3 is not configured: its buffer memory is not there (4043, as a missing module).
    CHECK(conn.exchange(wire, random_read_req(0x0082, {g7(0x3E2)}, {})) == wire.expect(error(0x4043, 0x0403, 0x0082)));
    CHECK(conn.exchange(wire, extend_unit_read_req(14, 2, 0x03E2)) == wire.expect(error(0x4043, 0x0601, 0x0000)));
}

TEST_CASE("Commands that cannot reach CPU No.2-4 answer C059 (Appendix 3)", "[multi_cpu]") {
    MultiCpu station;
    Connection conn{station.engine};
    auto wire = GENERATE(kBinary3E, kAscii4E);
    const auto r2 = cpu_route(2);
    auto before = snapshot(station.two);
    CHECK(conn.exchange(wire, monitor_entry_req(0x0000, {device(Form::Q, "D0")}, {}), r2) ==
          wire.expect(error(0xC059, 0x0801, 0x0000, r2), r2));
    CHECK(conn.exchange(wire, monitor_execute_req(), r2) == wire.expect(error(0xC059, 0x0802, 0x0000, r2), r2));
    CHECK(conn.exchange(wire, memory_read_req(0, 1), r2) == wire.expect(error(0xC059, 0x0613, 0x0000, r2), r2));
    CHECK(conn.exchange(wire, memory_write_req(0, {1}), r2) == wire.expect(error(0xC059, 0x1613, 0x0000, r2), r2));
    CHECK(conn.exchange(wire, word(0x0619) + word(0) + word(2) + Payload{"41 42", "AB"}, r2) ==
          wire.expect(error(0xC059, 0x0619, 0x0000, r2), r2));
    CHECK((snapshot(station.two) == before));
    // The same commands through 03E0 (CPU No.1 named explicitly) are served.
    const auto r1 = cpu_route(1);
    CHECK(conn.exchange(wire, monitor_entry_req(0x0000, {device(Form::Q, "D0")}, {}), r1) == wire.expect(ok(), r1));
    CHECK(conn.exchange(wire, monitor_execute_req(), r1) == wire.expect(ok(word(0)), r1));
    CHECK(conn.exchange(wire, memory_read_req(0, 1), r1) == wire.expect(ok(word(0)), r1));
}

TEST_CASE("A CPU number that is not configured answers 4B02", "[multi_cpu]") {
    MultiCpu station;
    Connection conn{station.engine};
    auto wire = GENERATE(kBinary3E, kAscii3E);
    for (int number : {3, 4}) {
        const auto r = cpu_route(number);
        INFO("CPU No." << number);
        CHECK(conn.exchange(wire, read_words_req(Form::Q, "D0", 1), r) ==
              wire.expect(error(0x4B02, 0x0401, 0x0000, r), r));
        CHECK(conn.exchange(wire, write_words_req(Form::Q, "D0", {1}), r) ==
              wire.expect(error(0x4B02, 0x1401, 0x0000, r), r));
    }
    CHECK(station.one.memory().value(spec_of("D"), 0) == 0);
    // A single-CPU station: 03E1 is not there either, 03E0 is the CPU itself.
    auto single = make_cpu("R08CPU");
    CHECK(wire.exchange(single, read_words_req(Form::Q, "D0", 1), cpu_route(2)) ==
          wire.expect(error(0x4B02, 0x0401, 0x0000, cpu_route(2)), cpu_route(2)));
    CHECK(wire.exchange(single, read_words_req(Form::Q, "D0", 1), cpu_route(1)) ==
          wire.expect(ok(word(0)), cpu_route(1)));
}
