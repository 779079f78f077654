// Entry Monitor Device 0801 / Execute Monitor 0802 (SLMP Reference Manual
// §5.2): Example EM byte for byte, 0802's answer (equal to Example RR's,
// inferred), the registration's lifetime per connection (Session), limits per
// profile, and the devices 0801 may not name.
#include "support/device_commands.hpp"

using namespace slmp;
using namespace slmp::test;

namespace {

// §6.5 Example EM (JP, ASCII and binary); 0802 then answers kExampleRRAnswer (§6.6, inferred).
const Payload kEMRequest{
    "01 08 00 00 04 03 00 00 00 A8 00 00 00 C2 64 00 00 90 20 00 00 9C DC 05 00 A8 60 01 00 9D 57 04 00 90",
    "08010000"
    "04"
    "03"
    "D*000000"
    "TN000000"
    "M*000100"
    "X*000020"
    "D*001500"
    "Y*000160"
    "M*001111"};

Payload register_d(std::uint32_t n, std::uint16_t sub = 0x0000) {
    auto form = sub & 0x0002 ? Form::IQR : Form::Q;
    return monitor_entry_req(sub, {field(form, sub & 0x0080, "D" + std::to_string(n))}, {});
}

}  // namespace

TEST_CASE("§6.5/§6.6 Example EM then Execute Monitor", "[monitor][spec]") {
    auto cpu = make_cpu("R08CPU");
    load_example_rr(cpu);
    auto engine = engine_for(cpu);
    Connection conn{engine};
    auto wire = GENERATE(kBinary3E, kBinary4E, kAscii3E, kAscii4E);
    CHECK(wire.data(monitor_entry_req(
              0x0000, {device(Form::Q, "D0"), device(Form::Q, "TN0"), device(Form::Q, "M100"), device(Form::Q, "X20")},
              {device(Form::Q, "D1500"), device(Form::Q, "Y160"), device(Form::Q, "M1111")})) == wire.data(kEMRequest));
    // 0802 is "0802" "0000" / 02 08 00 00.
    CHECK(wire.data(monitor_execute_req()) == wire.data(Payload{"02 08 00 00", "08020000"}));
    CHECK(conn.exchange(wire, kEMRequest) == wire.expect(ok()));
    CHECK(conn.exchange(wire, monitor_execute_req()) == wire.expect(ok(kExampleRRAnswer)));
    SECTION("0802 reads the values at the time of 0802, not of 0801") {
        cpu.memory().set_value(spec_of("D"), 0, 0xABCD);
        cpu.memory().set_bit(spec_of("X"), 0x20, false);  // X2F..X20: 4849 -> 4848
        CHECK(conn.exchange(wire, monitor_execute_req()) ==
              wire.expect(ok(Payload{"CD AB 02 12 30 20 48 48 4E 4F 54 4C AF B9 DE C3 B7 BC DD BA",
                                     "ABCD1202203048484C544F4EC3DEB9AFBADDBCB7"})));
    }
    SECTION("iQ-R form 0002 (derived) registers the same list") {
        Connection other{engine};
        auto iqr = monitor_entry_req(
            0x0002,
            {device(Form::IQR, "D0"), device(Form::IQR, "TN0"), device(Form::IQR, "M100"), device(Form::IQR, "X20")},
            {device(Form::IQR, "D1500"), device(Form::IQR, "Y160"), device(Form::IQR, "M1111")});
        CHECK(other.exchange(wire, iqr) == wire.expect(ok()));
        CHECK(other.exchange(wire, monitor_execute_req()) == wire.expect(ok(kExampleRRAnswer)));
    }
}

TEST_CASE("The monitor registration belongs to the connection", "[monitor][session]") {
    auto cpu = make_cpu("R08CPU");
    for (std::uint32_t n = 0; n < 20; ++n) cpu.memory().set_value(spec_of("D"), n, 0x100 + n);
    auto engine = engine_for(cpu);
    Connection a{engine}, b{engine};
    auto wire = GENERATE(kBinary3E, kAscii4E);

    SECTION("0802 without a registration -> C059") {
        CHECK(a.exchange(wire, monitor_execute_req()) == wire.expect(error(0xC059, 0x0802, 0x0000)));
    }
    SECTION("another connection's registration is not this one's") {
        CHECK(a.exchange(wire, register_d(1)) == wire.expect(ok()));
        CHECK(b.exchange(wire, monitor_execute_req()) == wire.expect(error(0xC059, 0x0802, 0x0000)));
        CHECK(b.exchange(wire, register_d(2)) == wire.expect(ok()));
        CHECK(a.exchange(wire, monitor_execute_req()) == wire.expect(ok(word(0x101))));
        CHECK(b.exchange(wire, monitor_execute_req()) == wire.expect(ok(word(0x102))));
    }
    SECTION("a new 0801 replaces the registration") {
        CHECK(a.exchange(wire, register_d(1)) == wire.expect(ok()));
        CHECK(a.exchange(wire, monitor_entry_req(0x0000, {device(Form::Q, "D3"), device(Form::Q, "D4")},
                                                 {device(Form::Q, "D5")})) == wire.expect(ok()));
        CHECK(a.exchange(wire, monitor_execute_req()) == wire.expect(ok(words({0x103, 0x104}) + dword(0x01060105))));
    }
    SECTION("a rejected 0801 keeps the previous registration") {
        CHECK(a.exchange(wire, register_d(7)) == wire.expect(ok()));
        // Over the limit, a device 0801 may not name, out of range, malformed.
        std::vector<Payload> too_many(193, device(Form::Q, "D0"));
        CHECK(a.exchange(wire, monitor_entry_req(0x0000, too_many, {})) == wire.expect(error(0xC054, 0x0801, 0x0000)));
        CHECK(a.exchange(wire, monitor_entry_req(0x0000, {device(Form::Q, "D1"), device(Form::Q, "TS0")}, {})) ==
              wire.expect(error(0x4030, 0x0801, 0x0000)));
        CHECK(a.exchange(wire, monitor_entry_req(0x0000, {device(Form::Q, "D10240")}, {})) ==
              wire.expect(error(0x4031, 0x0801, 0x0000)));
        CHECK(a.exchange(wire, word(0x0801) + word(0) + byte(2) + byte(0) + device(Form::Q, "D1")) ==
              wire.expect(error(0xC061, 0x0801, 0x0000)));
        CHECK(a.exchange(wire, monitor_execute_req()) == wire.expect(ok(word(0x107))));
    }
    SECTION("0802 with a subcommand other than 0000 -> C059, registration kept") {
        CHECK(a.exchange(wire, register_d(9)) == wire.expect(ok()));
        CHECK(a.exchange(wire, word(0x0802) + word(0x0002)) == wire.expect(error(0xC059, 0x0802, 0x0002)));
        CHECK(a.exchange(wire, monitor_execute_req()) == wire.expect(ok(word(0x109))));
    }
    SECTION("0802 with data after the subcommand -> C061") {
        CHECK(a.exchange(wire, register_d(9)) == wire.expect(ok()));
        CHECK(a.exchange(wire, monitor_execute_req() + word(0)) == wire.expect(error(0xC061, 0x0802, 0x0000)));
    }
}

TEST_CASE("Index registers in a registration are applied at every 0802", "[monitor][extended]") {
    auto cpu = make_cpu("R08CPU");
    for (std::uint32_t n = 0; n < 200; ++n) cpu.memory().set_value(spec_of("D"), n, 0x1000 + n);
    auto engine = engine_for(cpu);
    Connection conn{engine};
    auto wire = GENERATE(kBinary3E, kAscii3E);
    auto form = GENERATE(Form::Q, Form::IQR);
    const auto sub = device_sub(form, true);
    Extension d100z4;
    d100z4.device_index = z(4);
    Extension at_d10;
    at_d10.indirect = true;
    cpu.memory().set_value(spec_of("Z"), 4, 0);
    cpu.memory().set_value(spec_of("D"), 10, 150);  // @D10 -> D150
    cpu.memory().set_value(spec_of("D"), 11, 0);
    CHECK(conn.exchange(
              wire, monitor_entry_req(sub, {ext_device(form, "D100", d100z4), ext_device(form, "D10", at_d10)}, {})) ==
          wire.expect(ok()));
    CHECK(conn.exchange(wire, monitor_execute_req()) == wire.expect(ok(words({0x1064, 0x1096}))));
    // Z4 = 5 and D10 = 160 after registration: 0802 reads D105 and D160.
    CHECK(conn.exchange(wire, write_words_req(Form::Q, "Z4", {5})) == wire.expect(ok()));
    CHECK(conn.exchange(wire, write_words_req(Form::Q, "D10", {160})) == wire.expect(ok()));
    CHECK(conn.exchange(wire, monitor_execute_req()) == wire.expect(ok(words({0x1069, 0x10A0}))));
    // Z4 = -100: D0.
    cpu.memory().set_value(spec_of("Z"), 4, 0xFF9C);
    CHECK(conn.exchange(wire, monitor_execute_req()) == wire.expect(ok(words({0x1000, 0x10A0}))));
    // Z4 moves D100 past the end: 0802 answers the out-of-range code, the registration stays.
    cpu.memory().set_value(spec_of("Z"), 4, 10200);
    CHECK(conn.exchange(wire, monitor_execute_req()) == wire.expect(error(0x4031, 0x0802, 0x0000)));
    cpu.memory().set_value(spec_of("Z"), 4, 1);
    CHECK(conn.exchange(wire, monitor_execute_req()) == wire.expect(ok(words({0x1065, 0x10A0}))));
}

TEST_CASE("0801 points: below, at and above per profile", "[monitor][limits][profiles]") {
    struct Case {
        const char* profile;
        bool iqr_form;
        std::uint16_t extended_code;
    };
    auto c = GENERATE(Case{"R08CPU", true, 0}, Case{"R120PCPU", true, 0}, Case{"Q26UDEHCPU", false, 0},
                      Case{"Q06UDVCPU-QJ71E71", false, 0x4080}, Case{"L26CPU-BT", false, 0});
    auto wire = GENERATE(kBinary3E, kAscii3E);
    auto cpu = make_cpu(c.profile);
    for (std::uint32_t n = 0; n < 200; ++n) cpu.memory().set_value(spec_of("D"), n, n);
    auto engine = engine_for(cpu);
    for (auto form : {Form::Q, Form::IQR}) {
        if (form == Form::IQR && !c.iqr_form) continue;
        for (bool extended : {false, true}) {
            const unsigned limit = form == Form::IQR ? 96 : extended ? 96 : 192;  // 0080 counts each point twice
            const auto sub = device_sub(form, extended);
            INFO(c.profile << ", " << wire.name() << ", subcommand " << hexn(sub, 4) << ", limit " << limit);
            for (unsigned n : {limit - 1, limit}) {
                Connection conn{engine};
                std::vector<Payload> list;
                std::vector<std::uint16_t> answer;
                for (unsigned i = 0; i < n; ++i) {
                    list.push_back(field(form, extended, "D" + std::to_string(i)));
                    answer.push_back(static_cast<std::uint16_t>(i));
                }
                CHECK(conn.exchange(wire, monitor_entry_req(sub, list, {})) == wire.expect(ok()));
                CHECK(conn.exchange(wire, monitor_execute_req()) == wire.expect(ok(words(answer))));
            }
            Connection conn{engine};
            std::vector<Payload> over(limit + 1, field(form, extended, "D0"));
            const std::uint16_t code = extended && c.extended_code ? c.extended_code : 0xC054;
            CHECK(conn.exchange(wire, monitor_entry_req(sub, over, {})) == wire.expect(error(code, 0x0801, sub)));
            CHECK(conn.exchange(wire, monitor_execute_req()) == wire.expect(error(0xC059, 0x0802, 0x0000)));
        }
    }
}

TEST_CASE("FX5U does not support 0801/0802 (C059)", "[monitor][profiles]") {
    auto cpu = make_cpu("FX5U-32MR");
    auto wire = GENERATE(kBinary3E, kAscii3E);
    CHECK(wire.exchange(cpu, register_d(0)) == wire.expect(error(0xC059, 0x0801, 0x0000)));
    CHECK(wire.exchange(cpu, monitor_execute_req()) == wire.expect(error(0xC059, 0x0802, 0x0000)));
}

TEST_CASE("0801 refuses the timer/counter contacts, coils and long values with 4030", "[monitor][devices]") {
    auto cpu = make_cpu("R08CPU");
    auto engine = engine_for(cpu);
    auto wire = GENERATE(kBinary3E, kAscii3E);
    // §6.5's list, every one of them; TN, STN and CN are fine.
    for (const char* symbol :
         {"TS", "TC", "LTS", "LTC", "LTN", "STS", "STC", "LSTS", "LSTC", "LSTN", "CS", "CC", "LCS", "LCC", "LCN"}) {
        INFO(symbol);
        Connection conn{engine};
        CHECK(conn.exchange(wire, monitor_entry_req(0x0002, {device(Form::IQR, std::string(symbol) + "0")}, {})) ==
              wire.expect(error(0x4030, 0x0801, 0x0002)));
    }
    Connection conn{engine};
    CHECK(conn.exchange(
              wire,
              monitor_entry_req(0x0002, {device(Form::IQR, "TN0"), device(Form::IQR, "STN0"), device(Form::IQR, "CN0")},
                                {device(Form::IQR, "LZ1")})) == wire.expect(ok()));
}
