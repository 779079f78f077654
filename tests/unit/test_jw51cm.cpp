// The Sharp JW-51CM computer link, bytes in and bytes out: every consolidated
// test vector of the JW-51CM manual, docs/jw51cm.md that the front end covers (1–18, 27–29)
// byte-exact with the 40-byte header, the COM-driven framing of §3.2, the
// write-permission mode, the run/stop owner and the RSLT codes of §10.
#include <catch2/catch.hpp>

#include <chrono>
#include <vector>

#include "config/config.hpp"
#include "frontends/jw51cm/command_table.hpp"
#include "frontends/jw51cm/computer_link.hpp"
#include "support/jw51cm_frames.hpp"

namespace {

using namespace slmp;
using Bytes = std::vector<std::uint8_t>;

using test::jw51cm::request;
using test::jw51cm::response;

// 1997-12-17 21:12:37 UTC, the manual's clock examples.
std::chrono::system_clock::time_point manual_time() {
    using namespace std::chrono;
    return sys_days(year(1997) / 12 / 17) + hours(21) + minutes(12) + seconds(37);
}

struct Fixture {
    devicemodel::Cpu cpu{config::load_profile("R08CPU").cpu};
    jw51cm::Options options = [] {
        jw51cm::Options o;
        o.timer_attributes = {{0, 0x08}, {1, 0x0A}};
        return o;
    }();
    std::chrono::system_clock::time_point now = manual_time();
    jw51cm::ComputerLink link{cpu, options, [this] { return now; }};

    Bytes ask(const Bytes& after_id) {
        auto frame = request(after_id);
        auto result = link.handle_stream(frame);
        REQUIRE(result.kind == jw51cm::ComputerLink::Result::Kind::Respond);
        CHECK(result.consumed == frame.size());
        return result.response;
    }
    const devicemodel::DeviceSpec& spec(const char* symbol) { return *devicemodel::find_by_symbol(symbol); }
};

}  // namespace

TEST_CASE("JW-51CM vectors 1-2: write-permission mode", "[jw51cm]") {
    Fixture f;
    CHECK(f.ask({0xE9}) == response({0xE9, 0x00, 0x00}));   // 0 at power-on
    CHECK(f.ask({0xF9, 0x02}) == response({0xF9, 0x00, 0x02}));
    CHECK(f.ask({0xE9}) == response({0xE9, 0x00, 0x02}));
    CHECK(f.ask({0xF9, 0x03}) == response({0xF9, 0x01}));
}

TEST_CASE("JW-51CM vectors 3, 27: relay 04033 monitor and set (full frames)", "[jw51cm]") {
    Fixture f;
    f.cpu.memory().set_bit(f.spec("M"), 04033, true);   // relay 04033 = M2075
    auto frame = request({0x20, 0x00, 0x03, 0x01, 0x03});
    REQUIRE(frame.size() == 47);
    auto answer = f.link.handle_stream(frame).response;
    CHECK(answer.size() == 49);
    CHECK(answer == response({0x20, 0x00, 0x00, 0x03, 0x01, 0x03, 0x01}));
    // 30 while write mode 0: RSLT 10, nothing changes; then mode 1 and reset it.
    CHECK(f.ask({0x30, 0x00, 0x03, 0x01, 0x03, 0x00}) == response({0x30, 0x10}));
    CHECK(f.cpu.memory().bit(f.spec("M"), 04033));
    f.ask({0xF9, 0x01});
    CHECK(f.ask({0x30, 0x00, 0x03, 0x01, 0x03, 0x00}) == response({0x30, 0x00, 0x00, 0x03, 0x01, 0x03}));
    CHECK_FALSE(f.cpu.memory().bit(f.spec("M"), 04033));
    CHECK(f.ask({0x30, 0x00, 0x03, 0x01, 0x03, 0x01}) == response({0x30, 0x00, 0x00, 0x03, 0x01, 0x03}));   // 27
    CHECK(f.cpu.memory().bit(f.spec("M"), 04033));
    CHECK(f.ask({0x20, 0x00, 0x03, 0x01, 0x08}) == response({0x20, 0x01}));   // BLOC 8
    CHECK(f.ask({0x20, 0x08, 0x03, 0x01, 0x03}) == response({0x20, 0x01}));   // DSEG 8
    CHECK(f.ask({0x20, 0x00, 0x00, 0x20, 0x00}) == response({0x20, 0x01}));   // past file 0 (0x2000)
}

TEST_CASE("JW-51CM vectors 4-5: T/C set and current values with attributes", "[jw51cm]") {
    Fixture f;
    f.ask({0xF9, 0x01});
    CHECK(f.ask({0x32, 0x02, 0x00, 0x01}) == response({0x32, 0x00, 0x02, 0x00}));   // 4
    CHECK(f.cpu.memory().bit(f.spec("TS"), 2));
    f.cpu.memory().set_value(f.spec("TN"), 0, 0x9234);
    f.cpu.memory().set_value(f.spec("TN"), 1, 0xD678);
    CHECK(f.ask({0x23, 0x00, 0x00, 0x02, 0x00}) ==
          response({0x23, 0x00, 0x00, 0x00, 0x02, 0x00, 0x34, 0x92, 0x78, 0xD6, 0x08, 0x0A}));   // 5
    CHECK(f.ask({0x23, 0x00, 0x00, 0x01, 0x01}) == response({0x23, 0x01}));   // 257 T/Cs
    CHECK(f.ask({0x23, 0xFF, 0x03, 0x02, 0x00}) == response({0x23, 0x01}));   // past 1777
    // Error 13: T/C set/reset while the PLC is stopped.
    f.ask({0xF8, 0x01});
    CHECK(f.ask({0x32, 0x03, 0x00, 0x01}) == response({0x32, 0x13}));
    CHECK_FALSE(f.cpu.memory().bit(f.spec("TS"), 3));
}

TEST_CASE("JW-51CM vectors 6-8, 28-29: registers read, write, fill", "[jw51cm]") {
    Fixture f;
    // Registers 09000-09003 = D0, D1 low byte first.
    f.cpu.memory().set_value(f.spec("D"), 0, 0x4F00);
    f.cpu.memory().set_value(f.spec("D"), 1, 0x0132);
    CHECK(f.ask({0x24, 0x00, 0x00, 0x08, 0x04, 0x00}) ==
          response({0x24, 0x00, 0x00, 0x00, 0x08, 0x04, 0x00, 0x00, 0x4F, 0x32, 0x01}));   // 6
    CHECK(f.ask({0x24, 0x00, 0x02, 0x08, 0x02, 0x00}) ==
          response({0x24, 0x00, 0x00, 0x02, 0x08, 0x02, 0x00, 0x32, 0x01}));   // 7, the sample program
    // 29: mode 0 refuses a fill with RSLT 10 and no text; nothing changes.
    CHECK(f.ask({0xF9, 0x00}) == response({0xF9, 0x00, 0x00}));
    CHECK(f.ask({0x35, 0x00, 0x00, 0x08, 0x01, 0x00, 0xFF}) == response({0x35, 0x10}));
    CHECK(f.cpu.memory().value(f.spec("D"), 0) == 0x4F00);
    f.ask({0xF9, 0x01});
    CHECK(f.ask({0x35, 0x00, 0x00, 0x0A, 0x04, 0x00, 0x4F}) == response({0x35, 0x00, 0x00, 0x00, 0x0A, 0x04, 0x00}));   // 8
    CHECK(f.cpu.memory().value(f.spec("D"), 256) == 0x4F4F);   // 19000 = byte 0o5000 = D256
    CHECK(f.cpu.memory().value(f.spec("D"), 257) == 0x4F4F);
    CHECK(f.ask({0x34, 0x00, 0x00, 0x08, 0x02, 0x00, 0x12, 0x34}) == response({0x34, 0x00, 0x00, 0x00, 0x08, 0x02, 0x00}));   // 28
    CHECK(f.cpu.memory().value(f.spec("D"), 0) == 0x3412);
    // Files 1-7 on ZR; a relay byte read as a register.
    CHECK(f.ask({0x34, 0x01, 0x00, 0x30, 0x01, 0x00, 0xAB}) == response({0x34, 0x00, 0x01, 0x00, 0x30, 0x01, 0x00}));
    CHECK(f.cpu.memory().value(f.spec("ZR"), 0x3000 / 2) == 0x00AB);
    f.cpu.memory().set_bit(f.spec("M"), 8 * 3 + 1, true);
    CHECK(f.ask({0x24, 0x00, 0x03, 0x00, 0x01, 0x00}) == response({0x24, 0x00, 0x00, 0x03, 0x00, 0x01, 0x00, 0x02}));
    // Out of range and bad lengths: 01, nothing written.
    CHECK(f.ask({0x24, 0x00, 0xFF, 0x1F, 0x02, 0x00}) == response({0x24, 0x01}));   // runs past file 0
    CHECK(f.ask({0x24, 0x00, 0x00, 0x08, 0x00, 0x00}) == response({0x24, 0x01}));   // L = 0
    CHECK(f.ask({0x24, 0x00, 0x00, 0x08, 0x01, 0x04}) == response({0x24, 0x01}));   // L = 1025
    CHECK(f.ask({0x35, 0x00, 0xFF, 0x1F, 0x02, 0x00, 0x11}) == response({0x35, 0x01}));
    CHECK(f.ask({0x24, 0x08, 0x00, 0x00, 0x01, 0x00}) == response({0x24, 0x01}));   // DSEG 8
    CHECK(f.ask({0x24, 0x01, 0x00, 0x40, 0x01, 0x00}) == response({0x24, 0x01}));   // past file 1's 16 KB
}

TEST_CASE("JW-51CM vectors 9-12: system memory and program need mode 2 and STOP", "[jw51cm]") {
    Fixture f;
    Bytes write_system{0x54, 0x08, 0x84, 0x00, 0x04, 0x00, 0x81, 0x00, 0x00, 0x04};
    Bytes write_program{0x14, 0x08, 0x00, 0x00, 0x03, 0x00, 0x00, 0x80, 0x00, 0x91, 0x08, 0xB8};
    f.ask({0xF9, 0x01});
    CHECK(f.ask(write_system) == response({0x54, 0x10}));    // mode 1: 10
    f.ask({0xF9, 0x02});
    CHECK(f.ask(write_system) == response({0x54, 0x06}));    // running: 06
    CHECK(f.ask(write_program) == response({0x14, 0x06}));
    CHECK(f.ask({0xF8, 0x01}) == response({0xF8, 0x00, 0x01}));   // 18
    CHECK(f.ask(write_system) == response({0x54, 0x00, 0x08, 0x84, 0x00, 0x04, 0x00}));   // 10
    CHECK(f.ask({0x44, 0x08, 0x84, 0x00, 0x04, 0x00}) ==
          response({0x44, 0x00, 0x08, 0x84, 0x00, 0x04, 0x00, 0x81, 0x00, 0x00, 0x04}));
    f.link.system_memory[0x84] = 0x80;
    f.link.system_memory[0x85] = 0x01;
    f.link.system_memory[0x86] = 0x08;
    f.link.system_memory[0x87] = 0x00;
    CHECK(f.ask({0x44, 0x08, 0x84, 0x00, 0x04, 0x00}) ==
          response({0x44, 0x00, 0x08, 0x84, 0x00, 0x04, 0x00, 0x80, 0x01, 0x08, 0x00}));   // 9
    CHECK(f.ask(write_program) == response({0x14, 0x00, 0x08, 0x00, 0x00, 0x03, 0x00}));   // 11
    CHECK(f.ask({0x04, 0x08, 0x00, 0x00, 0x03, 0x00}) ==
          response({0x04, 0x00, 0x08, 0x00, 0x00, 0x03, 0x00, 0x00, 0x80, 0x00, 0x91, 0x08, 0xB8}));   // 12
    CHECK(f.ask({0x44, 0x07, 0x84, 0x00, 0x04, 0x00}) == response({0x44, 0x01}));   // SEG must be 08
    CHECK(f.ask({0x44, 0x08, 0x7F, 0x04, 0x02, 0x00}) == response({0x44, 0x01}));   // past #2177
    CHECK(f.ask({0x04, 0x0A, 0x00, 0x00, 0x01, 0x00}) == response({0x04, 0x01}));   // PSEG 0A
    CHECK(f.ask({0x04, 0x09, 0x00, 0x00, 0x01, 0x02}) == response({0x04, 0x01}));   // 513 words
}

TEST_CASE("JW-51CM vectors 13-16: the clock", "[jw51cm]") {
    Fixture f;
    CHECK(f.ask({0xA2}) == response({0xA2, 0x00, 0x97, 0x12, 0x17, 0x03}));   // 13
    CHECK(f.ask({0xA3}) == response({0xA3, 0x00, 0x21, 0x12, 0x37}));         // 15
    CHECK(f.ask({0xB2, 0x98, 0x01, 0x23, 0x05}) == response({0xB2, 0x10}));   // mode 0
    f.ask({0xF9, 0x01});
    CHECK(f.ask({0xB2, 0x98, 0x01, 0x23, 0x05}) == response({0xB2, 0x00}));   // 14
    CHECK(f.ask({0xB3, 0x18, 0x10, 0x20, 0x00}) == response({0xB3, 0x00}));   // 16
    CHECK(f.ask({0xA2}) == response({0xA2, 0x00, 0x98, 0x01, 0x23, 0x05}));
    CHECK(f.ask({0xA3}) == response({0xA3, 0x00, 0x18, 0x10, 0x20}));
    f.now += std::chrono::seconds(65);   // the clock runs on
    CHECK(f.ask({0xA3}) == response({0xA3, 0x00, 0x18, 0x11, 0x25}));
    CHECK(f.ask({0xB2, 0x98, 0x02, 0x30, 0x05}) == response({0xB2, 0x01}));   // 30 February
    CHECK(f.ask({0xB3, 0x24, 0x00, 0x00, 0x00}) == response({0xB3, 0x01}));
    CHECK(f.ask({0xB3, 0x1A, 0x00, 0x00, 0x00}) == response({0xB3, 0x01}));   // not BCD
}

TEST_CASE("JW-51CM vectors 17-18: run/stop with the stop owner", "[jw51cm]") {
    Fixture f;
    auto& runtime = f.cpu.runtime();
    CHECK(f.ask({0xE8}) == response({0xE8, 0x00, 0x00}));   // 17
    CHECK(f.ask({0xF8, 0x01}) == response({0xF8, 0x00, 0x01}));   // 18
    CHECK(runtime.state() == devicemodel::RunState::Stop);
    CHECK(f.ask({0xE8}) == response({0xE8, 0x00, 0x02}));   // stopped by this unit
    CHECK(f.ask({0xF8, 0x00}) == response({0xF8, 0x00, 0x00}));
    CHECK(runtime.state() == devicemodel::RunState::Run);
    // A stop by someone else (an SLMP client) reads 01 and F8 00 does not release it.
    runtime.remote_stop(f.cpu.memory(), 7);
    CHECK(f.ask({0xE8}) == response({0xE8, 0x00, 0x01}));
    CHECK(f.ask({0xF8, 0x00}) == response({0xF8, 0x00, 0x00}));
    CHECK(runtime.state() == devicemodel::RunState::Stop);
    CHECK(f.ask({0xF8, 0x02}) == response({0xF8, 0x01}));
}

TEST_CASE("JW-51CM framing: split, coalesced, E8's optional byte, bad ID, 2-tier header, UDP", "[jw51cm]") {
    Fixture f;
    using Kind = jw51cm::ComputerLink::Result::Kind;
    auto read = request({0x24, 0x00, 0x00, 0x08, 0x02, 0x00});
    // Not whole: wait.
    CHECK(f.link.handle_stream(std::span(read).first(47)).kind == Kind::NeedMore);
    CHECK(f.link.handle_stream(std::span(read).first(10)).kind == Kind::NeedMore);
    // Two requests in one buffer: the first is cut at its COM's length.
    auto two = read;
    auto mode = request({0xE9});
    two.insert(two.end(), mode.begin(), mode.end());
    auto first = f.link.handle_stream(two);
    CHECK(first.consumed == read.size());
    CHECK(f.link.handle_stream(std::span(two).subspan(first.consumed)).response == response({0xE9, 0x00, 0x00}));
    // A write's length comes from its L field.
    auto write = request({0x34, 0x00, 0x00, 0x08, 0x03, 0x00, 1, 2});
    CHECK(f.link.handle_stream(write).kind == Kind::NeedMore);
    // E8 with a MODE byte in the same segment takes it; followed by another request it does not.
    auto e8 = request({0xE8, 0x00});
    CHECK(f.link.handle_stream(e8).consumed == 44);
    auto e8_then = request({0xE8});
    e8_then.insert(e8_then.end(), mode.begin(), mode.end());
    CHECK(f.link.handle_stream(e8_then).consumed == 43);
    // A wrong ID or an unknown COM: RSLT 01 (a 44-byte answer) and the buffer is dropped.
    auto bad = request({0x99});
    auto refused = f.link.handle_stream(bad);
    CHECK(refused.response == response({0x99, 0x01}));
    CHECK(refused.response.size() == 44);
    auto wrong_id = request({0xE9});
    wrong_id[40] = 0x46;
    CHECK(f.link.handle_stream(wrong_id).response == response({0xE9, 0x01}));
    // A 2-tier (non-zero) header is not relayed: 01, the header echoed.
    auto relayed = request({0xE9});
    relayed[5] = 0x60;
    auto answer = f.link.handle_stream(relayed).response;
    REQUIRE(answer.size() == 44);
    CHECK(answer[5] == 0x60);
    CHECK(answer[43] == 0x01);
    // UDP: the datagram must be exactly one request.
    CHECK(f.link.handle_datagram(read).response == response({0x24, 0x00, 0x00, 0x00, 0x08, 0x02, 0x00, 0x00, 0x00}));
    auto longer = read;
    longer.push_back(0);
    CHECK(f.link.handle_datagram(longer).response == response({0x24, 0x01}));
    CHECK(f.link.handle_datagram(std::span(read).first(45)).response == response({0x24, 0x01}));
    CHECK(f.link.handle_datagram(e8).response == response({0xE8, 0x00, 0x00}));
    CHECK(f.link.handle_datagram(std::span(read).first(20)).kind == Kind::Drop);
}

TEST_CASE("JW-51CM memory map check names the fix", "[jw51cm]") {
    devicemodel::Cpu cpu{config::load_profile("R08CPU").cpu};
    CHECK(jw51cm::MemoryMap().check(cpu.memory()).empty());
    CHECK_THAT(jw51cm::MemoryMap(65536).check(cpu.memory()), Catch::Contains("file_bytes") && Catch::Contains("ZR"));
}
