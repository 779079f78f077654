// The A-compatible 1E frame (docs/frames.md), byte-exact in binary and ASCII,
// on a Q06UDVCPU through a QJ71E71-100 (a port that serves 1E); an R08CPU's
// built-in port does not know the frame and skips its bytes unanswered.
#include "support/fixtures.hpp"

#include "protocol/command_table.hpp"
#include "protocol/frame_1e.hpp"

using namespace slmp;
using namespace slmp::test;
using protocol::EndCode;

namespace {

constexpr const char* kProfile = "Q06UDVCPU-QJ71E71";

void set(devicemodel::Cpu& cpu, const char* address, std::uint32_t value) {
    auto a = *devicemodel::parse_address(address);
    cpu.memory().set_value(*a.spec, a.number, value);
}

std::uint32_t get(const devicemodel::Cpu& cpu, const char* address) {
    auto a = *devicemodel::parse_address(address);
    return cpu.memory().value(*a.spec, a.number);
}

// A request and its expected answer, in both codecs.
struct Exchange {
    std::string binary_request, binary_response, ascii_request, ascii_response;
};

void check_both(devicemodel::Cpu& cpu, const Exchange& e) {
    CHECK(hex(run(cpu, bytes(e.binary_request)).response) == hex(bytes(e.binary_response)));
    CHECK(str(run(cpu, text(e.ascii_request)).response) == e.ascii_response);
}

}  // namespace

TEST_CASE("1E batch read and write, word and bit units", "[1e][frames]") {
    auto cpu = make_cpu(kProfile);
    SECTION("01 word read D100-D102") {
        set(cpu, "D100", 0x1234);
        set(cpu, "D101", 0x0002);
        set(cpu, "D102", 0x1DEF);
        check_both(cpu, {"01 FF 0A 00 64 00 00 00 20 44 03 00", "81 00 34 12 02 00 EF 1D",
                         "01FF000A4420000000640300", "8100123400021DEF"});
    }
    SECTION("01 word read of a bit device: X20-X3F as two words") {
        set(cpu, "X20", 1);
        set(cpu, "X3F", 1);
        check_both(cpu, {"01 FF 0A 00 20 00 00 00 20 58 02 00", "81 00 01 00 00 80", "01FF000A5820000000200200",
                         "810000018000"});
    }
    SECTION("00 bit read M0-M2: an odd count carries a dummy point") {
        set(cpu, "M0", 1);
        set(cpu, "M2", 1);
        check_both(cpu, {"00 FF 0A 00 00 00 00 00 20 4D 03 00", "80 00 10 10", "00FF000A4D20000000000300", "80001010"});
    }
    SECTION("00 points 00 = 256 points") {
        auto out = run(cpu, bytes("00 FF 0A 00 00 00 00 00 20 4D 00 00"));
        CHECK(out.response.size() == 2 + 128);
    }
    SECTION("03 word write D0-D1") {
        check_both(cpu, {"03 FF 0A 00 00 00 00 00 20 44 02 00 34 12 78 56", "83 00",
                         "03FF000A44200000000002001234ABCD", "8300"});
        CHECK(get(cpu, "D0") == 0x1234);
        CHECK(get(cpu, "D1") == 0xABCD);   // the ASCII write came second
    }
    SECTION("02 bit write Y10-Y12 = 1 1 0, then 0 1 1") {
        CHECK(hex(run(cpu, bytes("02 FF 0A 00 10 00 00 00 20 59 03 00 11 00")).response) == "82 00");
        CHECK((get(cpu, "Y10") == 1 && get(cpu, "Y11") == 1 && get(cpu, "Y12") == 0));
        CHECK(str(run(cpu, text("02FF000A5920000000100300 0110")).response) != "8200");   // a space is no bit
        CHECK(str(run(cpu, text("02FF000A59200000001003000110")).response) == "8200");
        CHECK((get(cpu, "Y10") == 0 && get(cpu, "Y11") == 1 && get(cpu, "Y12") == 1));
    }
}

TEST_CASE("1E test (random write), monitor, loopback, PC type, remote RUN/STOP", "[1e][frames]") {
    auto cpu = make_cpu(kProfile);
    SECTION("05 test word units: D10 = 1111, W5 = 2222") {
        check_both(cpu, {"05 FF 0A 00 02 00 0A 00 00 00 20 44 11 11 05 00 00 00 20 57 22 22", "85 00",
                         "05FF000A0200" "44200000000A1111" "5720000000052222", "8500"});
        CHECK(get(cpu, "D10") == 0x1111);
        CHECK(get(cpu, "W5") == 0x2222);
    }
    SECTION("04 test bit units: M5 on, X1F on, then off in ASCII") {
        CHECK(hex(run(cpu, bytes("04 FF 0A 00 02 00 05 00 00 00 20 4D 01 1F 00 00 00 20 58 01")).response) == "84 00");
        CHECK((get(cpu, "M5") == 1 && get(cpu, "X1F") == 1));
        CHECK(str(run(cpu, text("04FF000A0200" "4D200000000500" "5820000000 1F00")).response) != "8400");
        CHECK(str(run(cpu, text("04FF000A0200" "4D200000000500" "58200000001F00")).response) == "8400");
        CHECK((get(cpu, "M5") == 0 && get(cpu, "X1F") == 0));
    }
    SECTION("07 monitor registration then 09 monitor, per connection") {
        set(cpu, "D100", 0x1234);
        set(cpu, "D200", 0x0042);
        auto engine = engine_for(cpu);
        protocol::Session session;
        auto exchange = [&](const Bytes& request) { return engine.process(request, DataCodePolicy::Auto, session).response; };
        CHECK(hex(exchange(bytes("07 FF 0A 00 02 00 64 00 00 00 20 44 C8 00 00 00 20 44"))) == "87 00");
        CHECK(hex(exchange(bytes("09 FF 0A 00"))) == "89 00 34 12 42 00");
        set(cpu, "D200", 0x0043);
        CHECK(str(exchange(text("09FF000A"))) == "890012340043");
    }
    SECTION("16 loopback echoes count and characters") {
        check_both(cpu, {"16 FF 0A 00 05 41 42 43 44 45", "96 00 05 41 42 43 44 45", "16FF000A05ABCDE", "960005ABCDE"});
    }
    SECTION("15 PC type read answers the profile's byte") {
        check_both(cpu, {"15 FF 0A 00", "95 00 41", "15FF000A", "950041"});
    }
    SECTION("14 remote STOP, 13 remote RUN") {
        check_both(cpu, {"14 FF 0A 00", "94 00", "14FF000A", "9400"});
        CHECK(cpu.runtime().state() == devicemodel::RunState::Stop);
        check_both(cpu, {"13 FF 0A 00", "93 00", "13FF000A", "9300"});
        CHECK(cpu.runtime().state() == devicemodel::RunState::Run);
    }
}

TEST_CASE("1E requests decode into the 3E request shape", "[1e][frames]") {
    auto cpu = make_cpu(kProfile);
    auto engine = engine_for(cpu);
    auto request = engine.decode(bytes("02 FF 0A 00 10 00 00 00 20 59 03 00 11 00"), DataCodePolicy::Auto);
    REQUIRE(request.complete());
    CHECK(request.header.kind == protocol::FrameKind::E1);
    CHECK(request.command == 0x1401);
    CHECK(request.subcommand == 0x0001);
    REQUIRE(request.spec != nullptr);
    CHECK(request.writes_devices());
    REQUIRE(request.operands.devices.size() == 1);
    CHECK(request.operands.devices[0].field.spec->symbol == "Y");
    CHECK(request.operands.devices[0].field.number == 0x10);
    CHECK(request.operands.devices[0].bits == std::vector<std::uint8_t>{1, 1, 0});
    // Every 1E row names a command table row.
    for (const auto& row : protocol::all_commands_1e()) CHECK(protocol::find_command(row.command, row.subcommand) != nullptr);
}

TEST_CASE("1E errors: end code, and the abnormal code after 5B", "[1e][frames][errors]") {
    auto cpu = make_cpu(kProfile);
    SECTION("unknown device code (Z) -> 56, memory unchanged") {
        auto before = snapshot(cpu);
        check_both(cpu, {"03 FF 0A 00 00 00 00 00 20 5A 01 00 01 00", "83 56", "03FF000A5A20000000000100" "0001", "8356"});
        CHECK((snapshot(cpu) == before));
    }
    SECTION("bit units on a word device -> 56") {
        check_both(cpu, {"00 FF 0A 00 00 00 00 00 20 44 01 00", "80 56", "00FF000A4420000000000100", "8056"});
    }
    SECTION("past the device range -> 57") {
        check_both(cpu, {"01 FF 0A 00 FF FF 00 00 20 44 02 00", "81 57", "01FF000A44200000FFFF0200", "8157"});
    }
    SECTION("non-hex ASCII data -> 54") {
        CHECK(str(run(cpu, text("03FF000A44200000000001001G34")).response) == "8354");
    }
    SECTION("PC No. other than FF -> 5B 10") {
        check_both(cpu, {"01 01 0A 00 64 00 00 00 20 44 01 00", "81 5B 10", "0101000A4420000000640100", "815B10"});
    }
    SECTION("loopback count 0 -> 56") {
        check_both(cpu, {"16 FF 0A 00 00", "96 56", "16FF000A00", "9656"});
    }
    CHECK(protocol::end_code_1e(EndCode::Busy).code == 0x5B);
}

TEST_CASE("1E framing: prefixes wait, frames follow each other, other ports skip 1E", "[1e][frames]") {
    auto cpu = make_cpu(kProfile);
    for (auto frame : {bytes("03 FF 0A 00 00 00 00 00 20 44 02 00 34 12 78 56"), text("03FF000A442000000000020012345678"),
                       bytes("16 FF 0A 00 03 41 42 43"), bytes("05 FF 0A 00 01 00 0A 00 00 00 20 44 11 11")}) {
        for (std::size_t n = 0; n < frame.size(); ++n) {
            auto out = run(cpu, std::span(frame).first(n));
            CHECK(out.action == Outcome::Action::NeedMore);
        }
        auto two = frame;
        two.insert(two.end(), frame.begin(), frame.end());
        auto out = run(cpu, two);
        CHECK(out.action == Outcome::Action::Respond);
        CHECK(out.consumed == frame.size());
    }
    SECTION("a 3E frame on the same port is still 3E") {
        auto out = run(cpu, bytes("50 00 00 FF FF 03 00 0C 00 10 00 01 04 00 00 64 00 00 A8 01 00"));
        CHECK(hex(out.response) == "D0 00 00 FF FF 03 00 04 00 00 00 00 00");
    }
    SECTION("the R08CPU's built-in port does not know 1E: skipped, not answered") {
        auto r08 = make_cpu("R08CPU");
        auto out = run(r08, bytes("01 FF 0A 00 64 00 00 00 20 44 03 00"));
        CHECK(out.action == Outcome::Action::Silent);
        CHECK(out.response.empty());
    }
    SECTION("a data code policy hides the other codec's 1E") {
        CHECK(run(cpu, text("01FF000A4420000000640300"), DataCodePolicy::Binary).action == Outcome::Action::Silent);
        CHECK(run(cpu, bytes("01 FF 0A 00 64 00 00 00 20 44 03 00"), DataCodePolicy::Ascii).action ==
              Outcome::Action::Silent);
    }
}
