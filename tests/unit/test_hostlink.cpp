// The Ladder Motion host link, bytes in and bytes out: every worked example
// and consolidated test vector of the Ladder Motion host-link manual, docs/hostlink.md (FCS
// included), the framing rules of §2–§3 and the error rules of §8.
#include <catch2/catch.hpp>

#include <string>

#include "config/config.hpp"
#include "frontends/hostlink/command_table.hpp"
#include "frontends/hostlink/host_link.hpp"

namespace {

using namespace slmp;
using hostlink::Area;

struct Fixture {
    devicemodel::Cpu cpu{config::load_profile("R08CPU").cpu};
    hostlink::HostLink link{cpu, hostlink::Options{}};
    hostlink::LinkState state;

    std::string ask(const std::string& record) { return link.answer(record, state); }
    const devicemodel::DeviceSpec& spec(const char* symbol) { return *devicemodel::find_by_symbol(symbol); }
    std::uint32_t value(const char* symbol, std::uint32_t n) { return cpu.memory().value(spec(symbol), n); }
    void set(const char* symbol, std::uint32_t n, std::uint32_t v) { cpu.memory().set_value(spec(symbol), n, v); }
};

std::span<const std::uint8_t> bytes(const std::string& s) {
    return {reinterpret_cast<const std::uint8_t*>(s.data()), s.size()};
}

}  // namespace

TEST_CASE("host link FCS and CSM: the spec's algorithm checks", "[hostlink]") {
    CHECK(hostlink::fcs("@00MM") == "40");
    CHECK(hostlink::csm("ABC") == "3A");   // §2.2 / §9
    CHECK(hostlink::close_record("@00IC") == "@00IC4A*\r");
}

TEST_CASE("host link R& worked examples (§6.7, vectors 1-3)", "[hostlink]") {
    Fixture f;
    // Version: the manual's 02.31; execution status: running (RUN).
    CHECK(f.ask("@00R&000900023F*\r") == "@00R&00023134*\r");
    CHECK(f.ask("@00R&0003000136*\r") == "@00R&000135*\r");
    // Cycle time 0x1234 x 200 ns depends on the scan: check the frame shape and FCS.
    auto cycle = f.ask("@00R&0006000230*\r");
    REQUIRE(cycle.size() == std::string("@00R&00123430*\r").size());
    CHECK(cycle.substr(0, 7) == "@00R&00");
    CHECK(cycle.substr(11, 2) == hostlink::fcs(cycle.substr(0, 11)));
    CHECK(f.ask(hostlink::close_record("@00R&00040001")) == hostlink::close_record("@00R&0003"));
    CHECK(f.ask(hostlink::close_record("@00R&00010001")) == hostlink::close_record("@00R&0001"));
    // Reserved item, unknown item, wrong byte count: 01 (inferred).
    CHECK(f.ask(hostlink::close_record("@00R&00020001")) == hostlink::close_record("@00R&01"));
    CHECK(f.ask(hostlink::close_record("@00R&000A0002")) == hostlink::close_record("@00R&01"));
    CHECK(f.ask(hostlink::close_record("@00R&00090001")) == hostlink::close_record("@00R&01"));
}

TEST_CASE("host link consolidated vectors 4-22 (§9)", "[hostlink]") {
    Fixture f;
    CHECK(f.ask("@00MM40*\r") == "@00MM001140*\r");   // 4

    f.set("D", 0, 0x1234);
    f.set("D", 1, 0xABCD);
    CHECK(f.ask("@00RD0000000254*\r") == "@00RD001234ABCD56*\r");   // 5

    // 6: the spec prints the answer "@00WD0052*\r", but XOR("@00WD00") is 0x53
    // (its WE answer, vector 21, is the one with FCS 52): the spec's slip.
    CHECK(f.ask("@00WD0100ABCD123452*\r") == "@00WD0053*\r");
    CHECK(f.value("D", 100) == 0xABCD);
    CHECK(f.value("D", 101) == 0x1234);

    f.cpu.memory().write_words(f.spec("M"), 16, std::array<std::uint16_t, 1>{0x00A5});   // CIO channel 1 = M16..M31
    CHECK(f.ask("@00RR0001000140*\r") == "@00RR0000A534*\r");   // 7

    CHECK(f.ask("@00Rr00105000357*\r") == "@00Rr0010150*\r");   // 8: 1.05-1.07 of 0x00A5 = 1,0,1

    f.cpu.memory().write_words(f.spec("M"), 16, std::array<std::uint16_t, 1>{0});
    CHECK(f.ask("@00Wr001051151*\r") == "@00Wr0065*\r");   // 9
    CHECK(f.value("M", 16 + 5) == 1);
    CHECK(f.value("M", 16 + 6) == 1);
    CHECK(f.value("M", 16 + 7) == 0);

    f.set("R", 0, 0x5678);   // VR0 low word
    f.set("R", 1, 0x1234);   // VR0 high word
    CHECK(f.ask("@00RV0000000145*\r") == "@00RV00123456784C*\r");   // 10

    // 11: the spec prints "@00WV000041*\r" — one "00" more than §6.4's cmd +
    // code, which the FCS cannot show ("00" XORs to zero). §6.4 wins.
    f.set("R", 0, 0);
    f.set("R", 1, 0);
    CHECK(f.ask("@00WV00001234567849*\r") == "@00WV0041*\r");
    CHECK(f.value("R", 0) == 0x5678);
    CHECK(f.value("R", 1) == 0x1234);

    f.cpu.memory().set_bit(f.spec("TS"), 1, true);
    f.cpu.memory().set_bit(f.spec("TS"), 3, true);
    CHECK(f.ask("@00RG0000000451*\r") == "@00RG00010155*\r");   // 12

    // 13: the spec prints "@00WG000050*\r"; as 11, the response is cmd + code.
    CHECK(f.ask("@00WG0002163*\r") == "@00WG0050*\r");
    CHECK(f.cpu.memory().bit(f.spec("TS"), 2));

    CHECK(f.ask("@00RH000000015B*\r") == "@00RH0000005A*\r");   // 14
    CHECK(f.ask("@00TSHELLO05*\r") == "@00TSHELLO05*\r");       // 15
    CHECK(f.ask("@00SC0252*\r") == "@00SC0151*\r");             // 16
    CHECK(f.ask("@00XZ42*\r").empty());                         // 17
    CHECK(f.ask("@00ZZ40*\r") == "@00IC4A*\r");                 // 18

    f.set("D", 100, 0x1234);
    f.cpu.memory().write_words(f.spec("M"), 16, std::array<std::uint16_t, 1>{0x0020});   // CIO 1.05 on
    CHECK(f.ask("@00QQMRDM  0100CH,CIO 00010511*\r") == "@00QQMR005F*\r");   // 19
    CHECK(f.ask("@00QQIR5B*\r") == "@00QQIR001234,142*\r");                 // 20

    CHECK(f.ask("@00WE0000ABCD56*\r") == "@00WE0052*\r");   // 21
    CHECK(f.ask("@00WEFFFF52*\r") == "@00WE0052*\r");
    CHECK(f.ask(hostlink::close_record("@00WE000012345678")) == "@00WE0052*\r");
    CHECK(f.ask("@00RE0000000255*\r") == "@00RE00123456785F*\r");   // 22
}

TEST_CASE("host link word and bit commands in every area", "[hostlink]") {
    Fixture f;
    struct Case {
        const char* write;
        const char* read;
        const char* symbol;
        std::uint32_t number;
    };
    // Word writes then reads; the default map puts each area on its device.
    for (auto c : {Case{"WR", "RR", "M", 16 * 3}, Case{"WH", "RH", "L", 16 * 3}, Case{"WL", "RL", "B", 16 * 3},
                   Case{"WJ", "RJ", "M", 4096 + 16 * 3}, Case{"WD", "RD", "D", 3}, Case{"WC", "RC", "TN", 3},
                   Case{"Wc", "Rc", "W", 3}}) {
        INFO(c.write);
        auto cmd = std::string("@00") + c.write + "0003BEEF0102";
        CHECK(f.ask(hostlink::close_record(cmd)) == hostlink::close_record(std::string("@00") + c.write + "00"));
        CHECK(f.ask(hostlink::close_record(std::string("@00") + c.read + "00030002")) ==
              hostlink::close_record(std::string("@00") + c.read + "00BEEF0102"));
        std::uint16_t word = 0;
        f.cpu.memory().read_words(f.spec(c.symbol), c.number, std::span<std::uint16_t>(&word, 1));
        CHECK(word == 0xBEEF);
    }
    // Bit forms: bit 15 of channel 2 then bit 0 of channel 3 (runs across channels).
    for (auto [w, r, area] : {std::tuple{"Wr", "Rr", "RR"}, std::tuple{"Wh", "Rh", "RH"}, std::tuple{"Wl", "Rl", "RL"},
                              std::tuple{"Wj", "Rj", "RJ"}}) {
        INFO(w);
        CHECK(f.ask(hostlink::close_record(std::string("@00") + w + "0021511")) ==
              hostlink::close_record(std::string("@00") + w + "00"));
        CHECK(f.ask(hostlink::close_record(std::string("@00") + r + "002140003")) ==
              hostlink::close_record(std::string("@00") + r + "00011"));
        CHECK(f.ask(hostlink::close_record(std::string("@00") + area + "00020002")) ==
              hostlink::close_record(std::string("@00") + area + "008000BEEF"));
    }
    // RI/WI, the list's spelling of Rl/Wl, answer under their own name.
    CHECK(f.ask(hostlink::close_record("@00RI002150001")) == hostlink::close_record("@00RI001"));
}

TEST_CASE("host link errors: bad input gets 01 and changes nothing", "[hostlink]") {
    Fixture f;
    auto err = [](const char* cmd) { return hostlink::close_record(std::string("@00") + cmd + "01"); };
    CHECK(f.ask("@00RD0000000255*\r") == err("RD"));              // bad FCS
    CHECK(f.ask("@00RD0000000254*\r") != err("RD"));              // the right one
    CHECK(f.ask("@00MM4a*\r") == err("MM"));                      // wrong FCS even in lower case
    CHECK(f.ask(hostlink::close_record("@00RD66550002")) == err("RD"));   // past DM6655
    CHECK(f.ask(hostlink::close_record("@00RD66550001")) != err("RD"));
    CHECK(f.ask(hostlink::close_record("@00RD00000031")) == err("RD"));   // 31 words do not fit 132 bytes
    CHECK(f.ask(hostlink::close_record("@00RD00000030")).size() == 131);
    CHECK(f.ask(hostlink::close_record("@00RV00000016")) == err("RV"));
    CHECK(f.ask(hostlink::close_record("@00RD0A000001")) == err("RD"));   // non-decimal
    CHECK(f.ask(hostlink::close_record("@00RD00000000")) == err("RD"));   // zero count
    CHECK(f.ask(hostlink::close_record("@00RD0000001")) == err("RD"));    // short field
    CHECK(f.ask(hostlink::close_record("@00Rr000160001")) == err("Rr"));  // bit 16
    CHECK(f.ask(hostlink::close_record("@00WD0000123")) == err("WD"));    // partial word
    CHECK(f.ask(hostlink::close_record("@00WD0000")) == err("WD"));       // no data
    CHECK(f.ask(hostlink::close_record("@00WD00001234XYZ1")) == err("WD"));
    CHECK(f.value("D", 0) == 0);   // the first word of the refused write was not stored
    CHECK(f.ask(hostlink::close_record("@00WD66551234ABCD")) == err("WD"));
    CHECK(f.value("D", 6655) == 0);
    CHECK(f.ask(hostlink::close_record("@00Wr00000102")) == err("Wr"));
    CHECK(f.value("M", 0) == 0);
    CHECK(f.ask(hostlink::close_record("@00WG05111")) != err("WG"));
    CHECK(f.ask(hostlink::close_record("@00WG051111")) == err("WG"));   // past T/C 511
    CHECK(f.ask(hostlink::close_record("@00MMX")) == err("MM"));
    CHECK(f.ask(hostlink::close_record("@00QQIR")) == err("QQIR"));     // no list registered
    CHECK(f.ask(hostlink::close_record("@00QQMRDM  9999CH")) == err("QQMR"));
    CHECK(f.ask(hostlink::close_record("@00QQXX")) == "@00IC4A*\r");
    // Every refused OMRON command: 01, no data.
    for (const auto& row : hostlink::command_table())
        if (row.compat == hostlink::Compat::Refused)
            CHECK(f.ask(hostlink::close_record(std::string("@00") + std::string(row.code) + "0000")) ==
                  err(std::string(row.code).c_str()));
    // Silence: `**`, another station, no `*`.
    CHECK(f.ask(hostlink::close_record("@00**")).empty());
    CHECK(f.ask(hostlink::close_record("@01MM")).empty());
    CHECK(f.ask("@00MM40\r").empty());
    // Over 132 bytes: 01.
    CHECK(f.ask(hostlink::close_record("@00TS" + std::string(124, 'A'))) == err("TS"));
    CHECK(f.ask(hostlink::close_record("@00TS" + std::string(123, 'A'))).size() == 132);
}

TEST_CASE("host link: the refused code and FCS error code are options", "[hostlink]") {
    devicemodel::Cpu cpu{config::load_profile("R08CPU").cpu};
    hostlink::Options options;
    options.refused_code = "15";
    options.fcs_error_code = "13";
    hostlink::HostLink link(cpu, options);
    hostlink::LinkState state;
    CHECK(link.answer("@00SC0252*\r", state) == "@00SC1554*\r");   // vector 16's alternative
    CHECK(link.answer("@00MM41*\r", state) == hostlink::close_record("@00MM13"));
}

TEST_CASE("host link QQ lists are per connection and `**` clears them", "[hostlink]") {
    Fixture f;
    hostlink::LinkState other;
    f.set("D", 5, 0x0F0F);
    CHECK(f.ask(hostlink::close_record("@00QQMRDM  0005CH,DM  000500,DM  000504,TIM 000103")) ==
          hostlink::close_record("@00QQMR00"));
    f.cpu.memory().set_bit(f.spec("TS"), 1, true);
    CHECK(f.ask(hostlink::close_record("@00QQIR")) == hostlink::close_record("@00QQIR000F0F,1,0,1"));
    CHECK(f.link.answer(hostlink::close_record("@00QQIR"), other) == hostlink::close_record("@00QQIR01"));
    CHECK(f.ask(hostlink::close_record("@00**")).empty());
    CHECK(f.ask(hostlink::close_record("@00QQIR")) == hostlink::close_record("@00QQIR01"));
}

TEST_CASE("host link stream framing: bare, STX/ETX, split, coalesced, garbage", "[hostlink]") {
    Fixture f;
    std::string two = "@00MM40*\r@00ZZ40*\r";
    auto first = f.link.handle(bytes(two), f.state);
    CHECK(first.kind == hostlink::Cut::Kind::Record);
    CHECK(first.consumed == 9);
    CHECK(first.response == "@00MM001140*\r");
    auto second = f.link.handle(bytes(two.substr(9)), f.state);
    CHECK(second.response == "@00IC4A*\r");

    std::string wrapped = std::string(1, hostlink::kStx) + "@00MM40*\r" + std::string(1, hostlink::kEtx);
    auto w = f.link.handle(bytes(wrapped), f.state);
    CHECK(w.consumed == wrapped.size());
    CHECK(w.response == std::string(1, hostlink::kStx) + "@00MM001140*\r" + std::string(1, hostlink::kEtx));
    // STX record whose ETX has not arrived yet: wait for it.
    CHECK(f.link.handle(bytes(wrapped.substr(0, wrapped.size() - 1)), f.state).kind == hostlink::Cut::Kind::NeedMore);

    CHECK(f.link.handle(bytes("@00MM4"), f.state).kind == hostlink::Cut::Kind::NeedMore);
    auto garbage = f.link.handle(bytes("xyz\r\n@00MM40*\r"), f.state);
    CHECK(garbage.kind == hostlink::Cut::Kind::Garbage);
    CHECK(garbage.consumed == 5);
    auto endless = std::string(1, '@') + std::string(2000, 'A');
    auto dropped = f.link.handle(bytes(endless), f.state);
    CHECK(dropped.kind == hostlink::Cut::Kind::Garbage);
    CHECK(dropped.consumed == endless.size());
}

TEST_CASE("host link memory map check names the key and the fix", "[hostlink]") {
    devicemodel::Cpu cpu{config::load_profile("R08CPU").cpu};
    hostlink::MemoryMap map;
    CHECK(map.check(cpu.memory()).empty());
    map.bind(Area::Dm, {*devicemodel::parse_address("D0"), 20000});
    auto message = map.check(cpu.memory());
    CHECK_THAT(message, Catch::Contains("areas/DM") && Catch::Contains("device_sizes"));
    hostlink::MemoryMap flags;
    flags.bind(Area::TcUp, {*devicemodel::parse_address("D0"), 16});
    CHECK_THAT(flags.check(cpu.memory()), Catch::Contains("areas/TC_UP") && Catch::Contains("bit device"));
}
