// Remote Control 1001/1002/1003/1005/1006 and Clear Error 1617, byte-exact in
// binary and ASCII, 3E and 4E: SLMP Reference Manual ch. 5 (framed
// examples), §5.2–§5.6 (request data), §5.8 (the state rules), §8.
// End codes where the manuals are silent are the choices in docs/cpu-runtime.md.
#include "support/fixtures.hpp"

using namespace slmp;
using namespace slmp::test;
using devicemodel::RunSwitch;

namespace {

Payload byte(std::uint8_t v) { return {hexn(v, 2), hexn(v, 2)}; }

Payload run_req(std::uint16_t mode, std::uint8_t clear, std::uint8_t fixed = 0) {
    return word(0x1001) + word(0x0000) + word(mode) + byte(clear) + byte(fixed);
}
Payload stop_req(std::uint16_t fixed = 1) { return word(0x1002) + word(0x0000) + word(fixed); }
Payload pause_req(std::uint16_t mode) { return word(0x1003) + word(0x0000) + word(mode); }
Payload latch_clear_req(std::uint16_t fixed = 1) { return word(0x1005) + word(0x0000) + word(fixed); }
Payload reset_req(std::uint16_t fixed = 1) { return word(0x1006) + word(0x0000) + word(fixed); }
Payload clear_error_req() { return word(0x1617) + word(0x0000); }

// One client: its own Session, so ownership rules can be exercised.
struct Client {
    std::uint64_t id;
    protocol::Session session{};
    Client(std::uint64_t i) : id(i) { session.id = i; }
    Outcome send(devicemodel::Cpu& cpu, const Wire& w, const Payload& p) {
        return engine_for(cpu).process(w.request(p), DataCodePolicy::Auto, session);
    }
    std::string exchange(devicemodel::Cpu& cpu, const Wire& w, const Payload& p) { return w.show(send(cpu, w, p)); }
};

std::string sd203(devicemodel::Cpu& cpu, const Wire& w) {
    Client reader(99);
    return reader.exchange(cpu, w, read_words_req(Form::Q, "SD203", 1));
}

devicemodel::Cpu cpu_with(devicemodel::RuntimeConfig config, const std::string& profile = "R08CPU") {
    auto cpu = make_cpu(profile);
    cpu.runtime().configure(std::move(config), cpu.memory());
    return cpu;
}

}  // namespace

TEST_CASE("1001 Remote RUN: the framed examples of §1.6", "[remote][spec]") {
    auto cpu = make_cpu();
    auto bin = run(cpu, bytes("50 00 00 FF FF 03 00 0A 00 10 00 01 10 00 00 01 00 02 00"));
    CHECK(hex(bin.response) == "D0 00 00 FF FF 03 00 02 00 00 00");
    auto asc = run(cpu, text("500000FF03FF000014" "0010" "1001000000010200"));
    CHECK(str(asc.response) == "D00000FF03FF000004" "0000");
}

TEST_CASE("remote control request data as the manual prints it (§5.2-§5.6)", "[remote][spec]") {
    CHECK(run_req(0x0001, 0x02).ascii == "1001000000010200");
    CHECK(run_req(0x0001, 0x02).binary == "01 10 00 00 01 00 02 00");
    CHECK(stop_req().ascii == "100200000001");
    CHECK(stop_req().binary == "02 10 00 00 01 00");
    CHECK(pause_req(0x0001).ascii == "100300000001");
    CHECK(pause_req(0x0001).binary == "03 10 00 00 01 00");
    CHECK(latch_clear_req().binary == "05 10 00 00 01 00");
    CHECK(reset_req().ascii == "100600000001");
    CHECK(clear_error_req().binary == "17 16 00 00");
}

TEST_CASE("STOP, PAUSE, RUN over every wire, with SD203 following", "[remote]") {
    auto wire = GENERATE(kBinary3E, kBinary4E, kAscii3E, kAscii4E);
    auto cpu = make_cpu();
    Client a(1);
    CHECK(sd203(cpu, wire) == wire.expect(ok(words({0x0000}))));
    CHECK(a.exchange(cpu, wire, stop_req()) == wire.expect(ok()));
    CHECK(sd203(cpu, wire) == wire.expect(ok(words({0x0022}))));
    CHECK(a.exchange(cpu, wire, run_req(0x0001, 0x00)) == wire.expect(ok()));
    CHECK(sd203(cpu, wire) == wire.expect(ok(words({0x0000}))));
    CHECK(a.exchange(cpu, wire, pause_req(0x0001)) == wire.expect(ok()));
    CHECK(sd203(cpu, wire) == wire.expect(ok(words({0x0023}))));
    CHECK(a.exchange(cpu, wire, run_req(0x0003, 0x00)) == wire.expect(ok()));
    CHECK(sd203(cpu, wire) == wire.expect(ok(words({0x0000}))));
}

TEST_CASE("ownership: mode 0001 from another client is refused with 4015, 0003 forces", "[remote]") {
    auto wire = GENERATE(kBinary3E, kAscii3E);
    auto cpu = make_cpu();
    Client a(1), b(2);
    REQUIRE(a.exchange(cpu, wire, stop_req()) == wire.expect(ok()));
    CHECK(b.exchange(cpu, wire, run_req(0x0001, 0x00)) == wire.expect(error(0x4015, 0x1001, 0x0000)));
    CHECK(b.exchange(cpu, wire, pause_req(0x0001)) == wire.expect(error(0x4015, 0x1003, 0x0000)));
    CHECK(b.exchange(cpu, wire, latch_clear_req()) == wire.expect(error(0x4015, 0x1005, 0x0000)));
    CHECK(sd203(cpu, wire) == wire.expect(ok(words({0x0022}))));   // refused: nothing changed
    CHECK(b.exchange(cpu, wire, pause_req(0x0003)) == wire.expect(ok()));
    CHECK(sd203(cpu, wire) == wire.expect(ok(words({0x0023}))));
    CHECK(a.exchange(cpu, wire, run_req(0x0001, 0x00)) == wire.expect(error(0x4015, 0x1001, 0x0000)));
    CHECK(a.exchange(cpu, wire, run_req(0x0003, 0x00)) == wire.expect(ok()));
}

TEST_CASE("switch at STOP: RUN and PAUSE complete normally and change nothing", "[remote]") {
    auto wire = GENERATE(kBinary3E, kAscii4E);
    devicemodel::RuntimeConfig c;
    c.run_switch = RunSwitch::Stop;
    auto cpu = cpu_with(c);
    Client a(1);
    CHECK(sd203(cpu, wire) == wire.expect(ok(words({0x0002}))));
    CHECK(a.exchange(cpu, wire, run_req(0x0001, 0x02)) == wire.expect(ok()));
    CHECK(a.exchange(cpu, wire, pause_req(0x0001)) == wire.expect(ok()));
    CHECK(sd203(cpu, wire) == wire.expect(ok(words({0x0002}))));
}

TEST_CASE("1005 Remote Latch Clear: 4013 unless in STOP", "[remote]") {
    auto wire = GENERATE(kBinary3E, kAscii3E);
    devicemodel::RuntimeConfig c;
    c.latch.push_back({devicemodel::Area::D, 0, 10});
    auto cpu = cpu_with(c);
    Client a(1);
    REQUIRE(a.exchange(cpu, wire, write_words_req(Form::Q, "D5", {0x1234})) == wire.expect(ok()));
    CHECK(a.exchange(cpu, wire, latch_clear_req()) == wire.expect(error(0x4013, 0x1005, 0x0000)));
    CHECK(a.exchange(cpu, wire, read_words_req(Form::Q, "D5", 1)) == wire.expect(ok(words({0x1234}))));
    REQUIRE(a.exchange(cpu, wire, stop_req()) == wire.expect(ok()));
    CHECK(a.exchange(cpu, wire, latch_clear_req()) == wire.expect(ok()));
    CHECK(a.exchange(cpu, wire, read_words_req(Form::Q, "D5", 1)) == wire.expect(ok(words({0x0000}))));
}

TEST_CASE("1006 Remote RESET", "[remote]") {
    auto wire = GENERATE(kBinary3E, kBinary4E, kAscii3E, kAscii4E);
    SECTION("disabled by default: 4014") {
        auto cpu = make_cpu();
        Client a(1);
        a.exchange(cpu, wire, stop_req());
        CHECK(a.exchange(cpu, wire, reset_req()) == wire.expect(error(0x4014, 0x1006, 0x0000)));
    }
    devicemodel::RuntimeConfig c;
    c.remote_reset_enabled = true;
    c.latch.push_back({devicemodel::Area::D, 100, 1});
    auto cpu = cpu_with(c);
    Client a(1);
    SECTION("enabled but in RUN: 4013") {
        CHECK(a.exchange(cpu, wire, reset_req()) == wire.expect(error(0x4013, 0x1006, 0x0000)));
    }
    SECTION("enabled, in STOP: no response; the CPU restarts from the switch with latched devices kept") {
        a.exchange(cpu, wire, write_words_req(Form::Q, "D99", {0x1111, 0x2222}));
        a.exchange(cpu, wire, stop_req());
        auto out = a.send(cpu, wire, reset_req());
        CHECK(out.action == Outcome::Action::Restart);
        CHECK(out.response.empty());
        CHECK(sd203(cpu, wire) == wire.expect(ok(words({0x0000}))));
        CHECK(a.exchange(cpu, wire, read_words_req(Form::Q, "D99", 2)) == wire.expect(ok(words({0x0000, 0x2222}))));
    }
    SECTION("a wrong fixed value: C05C, nothing happens") {
        a.exchange(cpu, wire, stop_req());
        CHECK(a.exchange(cpu, wire, reset_req(0x0000)) == wire.expect(error(0xC05C, 0x1006, 0x0000)));
    }
}

TEST_CASE("malformed remote requests change nothing", "[remote][errors]") {
    auto wire = GENERATE(kBinary3E, kAscii3E);
    auto cpu = make_cpu();
    Client a(1);
    CHECK(a.exchange(cpu, wire, run_req(0x0002, 0x00)) == wire.expect(error(0xC05C, 0x1001, 0x0000)));
    CHECK(a.exchange(cpu, wire, run_req(0x0001, 0x03)) == wire.expect(error(0xC05C, 0x1001, 0x0000)));
    CHECK(a.exchange(cpu, wire, run_req(0x0001, 0x00, 0x01)) == wire.expect(error(0xC05C, 0x1001, 0x0000)));
    CHECK(a.exchange(cpu, wire, pause_req(0x0000)) == wire.expect(error(0xC05C, 0x1003, 0x0000)));
    CHECK(a.exchange(cpu, wire, stop_req(0x0002)) == wire.expect(error(0xC05C, 0x1002, 0x0000)));
    CHECK(a.exchange(cpu, wire, word(0x1002) + word(0x0000)) == wire.expect(error(0xC061, 0x1002, 0x0000)));
    CHECK(a.exchange(cpu, wire, stop_req() + word(0)) == wire.expect(error(0xC061, 0x1002, 0x0000)));
    CHECK(a.exchange(cpu, wire, word(0x1001) + word(0x0000) + word(1)) == wire.expect(error(0xC061, 0x1001, 0x0000)));
    CHECK(a.exchange(cpu, wire, word(0x1002) + word(0x0001) + word(1)) == wire.expect(error(0xC059, 0x1002, 0x0001)));
    CHECK(sd203(cpu, wire) == wire.expect(ok(words({0x0000}))));
}

TEST_CASE("1617 Clear Error on the iQ-F port clears the CPU's error", "[remote][error_clear]") {
    auto wire = GENERATE(kBinary3E, kAscii3E);   // the FX5 port serves 3E only
    auto cpu = make_cpu("FX5U-32MR");
    Client a(1);
    SECTION("a continuation error: SD0 and SM0 cleared") {
        cpu.runtime().raise_error(cpu.memory(), {0x1900, false});
        CHECK(a.exchange(cpu, wire, read_words_req(Form::Q, "SD0", 1)) == wire.expect(ok(words({0x1900}))));
        CHECK(a.exchange(cpu, wire, clear_error_req()) == wire.expect(ok()));
        CHECK(a.exchange(cpu, wire, read_words_req(Form::Q, "SD0", 1)) == wire.expect(ok(words({0x0000}))));
    }
    SECTION("no error: normal completion") { CHECK(a.exchange(cpu, wire, clear_error_req()) == wire.expect(ok())); }
    SECTION("a stop error needs a reset: C05F, the error stays") {
        cpu.runtime().raise_error(cpu.memory(), {0x3300, true});
        CHECK(a.exchange(cpu, wire, clear_error_req()) == wire.expect(error(0xC05F, 0x1617, 0x0000)));
        CHECK(sd203(cpu, wire) == wire.expect(ok(words({0x0042}))));
        CHECK(a.exchange(cpu, wire, run_req(0x0003, 0x00)) == wire.expect(error(0xC05F, 0x1001, 0x0000)));
    }
    SECTION("trailing data: C061") {
        CHECK(a.exchange(cpu, wire, clear_error_req() + word(0)) == wire.expect(error(0xC061, 0x1617, 0x0000)));
    }
}

// The Chinese manual's access table marks Clear Error × for the iQ-R, Q and L
// CPUs' built-in ports; through an Ethernet module it clears the module's
// own error, and the CPU's stays.
TEST_CASE("1617 Clear Error: a CPU's built-in port refuses it, a module port leaves the CPU's error", "[remote][error_clear]") {
    auto wire = GENERATE(kBinary3E, kAscii3E);   // the Q and L built-in ports serve 3E only
    SECTION("iQ-R, QnU and L built-in ports: C059, SD0 unchanged") {
        auto profile = GENERATE(as<std::string>{}, "R08CPU", "Q26UDEHCPU", "L26CPU-BT");
        auto cpu = make_cpu(profile);
        Client a(1);
        cpu.runtime().raise_error(cpu.memory(), {0x1900, false});
        CHECK(a.exchange(cpu, wire, clear_error_req()) == wire.expect(error(0xC059, 0x1617, 0x0000)));
        CHECK(a.exchange(cpu, wire, read_words_req(Form::Q, "SD0", 1)) == wire.expect(ok(words({0x1900}))));
    }
    SECTION("RJ71EN71 and QJ71E71 module ports: 0000, the CPU's SD0 stays") {
        auto profile = GENERATE(as<std::string>{}, "RJ71EN71", "Q06UDVCPU-QJ71E71");
        auto cpu = make_cpu(profile);
        Client a(1);
        cpu.runtime().raise_error(cpu.memory(), {0x1900, false});
        CHECK(a.exchange(cpu, wire, clear_error_req()) == wire.expect(ok()));
        CHECK(a.exchange(cpu, wire, read_words_req(Form::Q, "SD0", 1)) == wire.expect(ok(words({0x1900}))));
    }
}

// SM50 Error reset: the CPU's own way, from the program or a client's write.
TEST_CASE("SM50 error reset clears a continuation error at END", "[remote][error_clear]") {
    auto wire = GENERATE(kBinary3E, kAscii3E);
    const devicemodel::CalendarTime calendar{};
    auto at = [](int ms) { return devicemodel::Runtime::TimePoint{} + std::chrono::milliseconds(ms); };
    SECTION("iQ-R: OFF->ON clears SM0/SM1/SD0, and the CPU turns SM50 off") {
        auto cpu = make_cpu("R08CPU");
        Client a(1);
        cpu.runtime().raise_error(cpu.memory(), {0x1900, false});
        CHECK(a.exchange(cpu, wire, write_bits_req(Form::Q, "SM50", {1})) == wire.expect(ok()));
        cpu.runtime().scan(cpu.memory(), at(10), calendar);
        CHECK(a.exchange(cpu, wire, read_words_req(Form::Q, "SD0", 1)) == wire.expect(ok(words({0x0000}))));
        CHECK(a.exchange(cpu, wire, read_bits_req(Form::Q, "SM0", 2)) == wire.expect(ok(bits({0, 0}))));
        CHECK(a.exchange(cpu, wire, read_bits_req(Form::Q, "SM50", 1)) == wire.expect(ok(bits({0}))));
    }
    SECTION("QnU: SM50 stays ON; a later error needs SM50 OFF then ON again") {
        auto cpu = make_cpu("Q26UDEHCPU");
        Client a(1);
        cpu.runtime().raise_error(cpu.memory(), {0x1900, false});
        CHECK(a.exchange(cpu, wire, write_bits_req(Form::Q, "SM50", {1})) == wire.expect(ok()));
        cpu.runtime().scan(cpu.memory(), at(10), calendar);
        CHECK(a.exchange(cpu, wire, read_words_req(Form::Q, "SD0", 1)) == wire.expect(ok(words({0x0000}))));
        CHECK(a.exchange(cpu, wire, read_bits_req(Form::Q, "SM50", 1)) == wire.expect(ok(bits({1}))));
        cpu.runtime().raise_error(cpu.memory(), {0x1900, false});
        cpu.runtime().scan(cpu.memory(), at(20), calendar);
        CHECK(a.exchange(cpu, wire, read_words_req(Form::Q, "SD0", 1)) == wire.expect(ok(words({0x1900}))));
        CHECK(a.exchange(cpu, wire, write_bits_req(Form::Q, "SM50", {0})) == wire.expect(ok()));
        cpu.runtime().scan(cpu.memory(), at(30), calendar);
        CHECK(a.exchange(cpu, wire, write_bits_req(Form::Q, "SM50", {1})) == wire.expect(ok()));
        cpu.runtime().scan(cpu.memory(), at(40), calendar);
        CHECK(a.exchange(cpu, wire, read_words_req(Form::Q, "SD0", 1)) == wire.expect(ok(words({0x0000}))));
    }
    SECTION("a stop error stays: it needs a reset") {
        auto cpu = make_cpu("R08CPU");
        Client a(1);
        cpu.runtime().raise_error(cpu.memory(), {0x3300, true});
        CHECK(a.exchange(cpu, wire, write_bits_req(Form::Q, "SM50", {1})) == wire.expect(ok()));
        cpu.runtime().scan(cpu.memory(), at(10), calendar);
        CHECK(a.exchange(cpu, wire, read_words_req(Form::Q, "SD0", 1)) == wire.expect(ok(words({0x3300}))));
        CHECK(sd203(cpu, wire) == wire.expect(ok(words({0x0042}))));
    }
}
