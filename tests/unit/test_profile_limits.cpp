// What differs between CPUs (real-CPU measurements): point limits and
// their end codes, the out-of-range code at the end of every device, R/ZR
// start-only checks, and how each port refuses frames and subcommands.
// The expected values are written down here from the spec, not read from the
// profiles, so a wrong profile fails these tests.
#include "support/fixtures.hpp"

using namespace slmp;
using namespace slmp::test;

namespace {

struct Expect {
    const char* profile;
    std::uint16_t words_code;      // 0401/1401 > 960 words
    std::uint32_t bits_binary;     // 0401/1401 bit units, binary
    std::uint16_t bits_binary_code;
    std::uint32_t bits_ascii;      // bit units, ASCII
    std::uint16_t bits_ascii_code;
    std::uint16_t out_of_range;
    bool answers_4e;
    bool answers_iqr_form;
};

// FX5U: §3 gives its limits; no report names its out-of-range code, C056 is the profile's choice.
const Expect kExpect[] = {
    {"R08CPU", 0xC051, 7168, 0xC052, 3584, 0xC052, 0x4031, true, true},
    {"R120PCPU", 0xC051, 7168, 0xC052, 3584, 0xC052, 0x4031, true, true},
    {"Q26UDEHCPU", 0xC051, 7168, 0xC052, 3584, 0xC052, 0xC056, false, false},
    {"Q06UDVCPU-QJ71E71", 0xC051, 7168, 0xC052, 3584, 0xC052, 0xC056, true, false},
    {"L26CPU-BT", 0xC051, 7168, 0xC052, 3584, 0xC052, 0xC056, false, false},
    {"FX5U-32MR", 0xC052, 3584, 0xC051, 3584, 0xC051, 0xC056, false, false},
};

std::vector<Wire> wires_for(const Expect& e) {
    if (e.answers_4e) return {kBinary3E, kBinary4E, kAscii3E, kAscii4E};
    return {kBinary3E, kAscii3E};
}

std::string address(const devicemodel::DeviceSpec& spec, std::uint32_t number) {
    return devicemodel::format_address({&spec, number});
}

}  // namespace

TEST_CASE("every profile in the spec is built in", "[profiles]") {
    auto names = config::builtin_profile_names();
    for (const auto& e : kExpect) {
        INFO(e.profile);
        CHECK(std::find(names.begin(), names.end(), e.profile) != names.end());
        CHECK(make_cpu(e.profile).profile().name == e.profile);
    }
}

TEST_CASE("0401/1401 word points per profile", "[profiles][limits]") {
    auto e = GENERATE(from_range(std::begin(kExpect), std::end(kExpect)));
    auto cpu = make_cpu(e.profile);
    auto wire = GENERATE_COPY(from_range(wires_for(e)));
    INFO(e.profile << ", " << wire.name());
    auto& memory = cpu.memory();
    const auto& d = *devicemodel::find_by_symbol("D");
    for (std::uint32_t n = 0; n < 962; ++n) memory.set_value(d, n, n);
    auto values = [](std::uint16_t n) {
        std::vector<std::uint16_t> v(n);
        for (std::uint16_t i = 0; i < n; ++i) v[i] = i;
        return v;
    };
    SECTION("1 word") {
        CHECK(wire.exchange(cpu, read_words_req(Form::Q, "D0", 1)) == wire.expect(ok(words(values(1)))));
    }
    SECTION("959 words") {
        CHECK(wire.exchange(cpu, read_words_req(Form::Q, "D0", 959)) == wire.expect(ok(words(values(959)))));
    }
    SECTION("960 words") {
        CHECK(wire.exchange(cpu, read_words_req(Form::Q, "D0", 960)) == wire.expect(ok(words(values(960)))));
    }
    SECTION("961 words -> C051 (FX5U: C052)") {
        CHECK(wire.exchange(cpu, read_words_req(Form::Q, "D0", 961)) == wire.expect(error(e.words_code, 0x0401, 0x0000)));
    }
    SECTION("65535 words -> C051 (FX5U: C052)") {
        CHECK(wire.exchange(cpu, read_words_req(Form::Q, "D0", 0xFFFF)) ==
              wire.expect(error(e.words_code, 0x0401, 0x0000)));
    }
    SECTION("960 words written") {
        std::vector<std::uint16_t> in(960, 0xBEEF);
        CHECK(wire.exchange(cpu, write_words_req(Form::Q, "D1", in)) == wire.expect(ok()));
        CHECK(memory.value(d, 0) == 0);
        CHECK(memory.value(d, 960) == 0xBEEF);
        CHECK(memory.value(d, 961) == 961);
    }
    SECTION("961 words written -> C051 (FX5U: C052), memory unchanged") {
        auto before = snapshot(cpu);
        CHECK(wire.exchange(cpu, write_words_req(Form::Q, "D0", std::vector<std::uint16_t>(961, 1))) ==
              wire.expect(error(e.words_code, 0x1401, 0x0000)));
        CHECK((snapshot(cpu) == before));
    }
    SECTION("960 words of a bit device (15360 bits)") {
        if (cpu.profile().size(devicemodel::Area::M) >= 15360)
            CHECK(wire.exchange(cpu, read_words_req(Form::Q, "M0", 960)) ==
                  wire.expect(ok(words(std::vector<std::uint16_t>(960, 0)))));
        CHECK(wire.exchange(cpu, read_words_req(Form::Q, "M0", 961)) == wire.expect(error(e.words_code, 0x0401, 0x0000)));
    }
}

TEST_CASE("0401/1401 bit points per profile", "[profiles][limits]") {
    auto e = GENERATE(from_range(std::begin(kExpect), std::end(kExpect)));
    auto cpu = make_cpu(e.profile);
    auto wire = GENERATE_COPY(from_range(wires_for(e)));
    INFO(e.profile << ", " << wire.name());
    const auto limit = wire.ascii() ? e.bits_ascii : e.bits_binary;
    const auto code = wire.ascii() ? e.bits_ascii_code : e.bits_binary_code;
    const auto& m = *devicemodel::find_by_symbol("M");
    cpu.memory().set_bit(m, limit - 1, true);
    SECTION("limit (binary 7168 / ASCII 3584; FX5U 3584)") {
        std::vector<int> expect(limit, 0);
        expect.back() = 1;
        CHECK(wire.exchange(cpu, read_bits_req(Form::Q, "M0", static_cast<std::uint16_t>(limit))) ==
              wire.expect(ok(bits(expect))));
    }
    SECTION("limit - 1") {
        CHECK(wire.exchange(cpu, read_bits_req(Form::Q, "M0", static_cast<std::uint16_t>(limit - 1))) ==
              wire.expect(ok(bits(std::vector<int>(limit - 1, 0)))));
    }
    SECTION("limit + 1 -> C052 (FX5U: C051)") {
        CHECK(wire.exchange(cpu, read_bits_req(Form::Q, "M0", static_cast<std::uint16_t>(limit + 1))) ==
              wire.expect(error(code, 0x0401, 0x0001)));
    }
    SECTION("limit written") {
        CHECK(wire.exchange(cpu, write_bits_req(Form::Q, "M0", std::vector<int>(limit, 1))) == wire.expect(ok()));
        CHECK(cpu.memory().bit(m, 0));
        CHECK(cpu.memory().bit(m, limit - 1));
        CHECK_FALSE(cpu.memory().bit(m, limit));
    }
    SECTION("limit + 1 written -> C052 (FX5U: C051), memory unchanged") {
        auto before = snapshot(cpu);
        CHECK(wire.exchange(cpu, write_bits_req(Form::Q, "M0", std::vector<int>(limit + 1, 1))) ==
              wire.expect(error(code, 0x1401, 0x0001)));
        CHECK((snapshot(cpu) == before));
    }
    SECTION("0 bits -> C052 (FX5U: C051)") {
        CHECK(wire.exchange(cpu, read_bits_req(Form::Q, "M0", 0)) == wire.expect(error(code, 0x0401, 0x0001)));
    }
    SECTION("0 words -> C051 (FX5U: C052)") {
        CHECK(wire.exchange(cpu, read_words_req(Form::Q, "D0", 0)) == wire.expect(error(e.words_code, 0x0401, 0x0000)));
    }
}

TEST_CASE("iQ-R form limits on iQ-R profiles", "[profiles][limits]") {
    auto name = GENERATE(as<std::string>{}, "R08CPU", "R120PCPU");
    auto cpu = make_cpu(name);
    auto wire = GENERATE(kBinary3E, kBinary4E, kAscii3E, kAscii4E);
    const std::uint16_t bit_limit = wire.ascii() ? 3584 : 7168;
    SECTION("960 words ok, 961 words -> C051") {
        CHECK(wire.exchange(cpu, read_words_req(Form::IQR, "D0", 960)) ==
              wire.expect(ok(words(std::vector<std::uint16_t>(960, 0)))));
        CHECK(wire.exchange(cpu, read_words_req(Form::IQR, "D0", 961)) == wire.expect(error(0xC051, 0x0401, 0x0002)));
    }
    SECTION("bit limit ok, limit + 1 -> C052") {
        CHECK(wire.exchange(cpu, read_bits_req(Form::IQR, "M0", bit_limit)) ==
              wire.expect(ok(bits(std::vector<int>(bit_limit, 0)))));
        CHECK(wire.exchange(cpu, read_bits_req(Form::IQR, "M0", bit_limit + 1)) ==
              wire.expect(error(0xC052, 0x0401, 0x0003)));
    }
}

TEST_CASE("out of range at the end of every device", "[profiles][range]") {
    auto e = GENERATE(from_range(std::begin(kExpect), std::end(kExpect)));
    auto cpu = make_cpu(e.profile);
    const auto& profile = cpu.profile();
    devicemodel::NumberingScope numbering(profile.numbering);   // FX5: X/Y addresses and ASCII digits in octal
    auto wire = GENERATE_COPY(from_range(wires_for(e)));
    for (auto form : {Form::Q, Form::IQR}) {
        if (form == Form::IQR && !e.answers_iqr_form) continue;
        const auto sub_words = subcommand(form, false);
        const auto sub_bits = subcommand(form, true);
        for (const auto& spec : devicemodel::all_devices()) {
            using devicemodel::Area;
            if (spec.extension_only || (form == Form::Q && spec.q_code < 0)) continue;
            if (spec.area == Area::R || spec.area == Area::ZR) continue;   // own test below
            if ((spec.area == Area::LT || spec.area == Area::LST) && spec.part != devicemodel::Part::Value) continue;
            const auto size = profile.size(spec.area);
            INFO(e.profile << ", " << wire.name() << ", " << (form == Form::Q ? "Q form, " : "iQ-R form, ")
                           << spec.symbol << " (" << size << " devices)");
            const auto per = static_cast<std::uint16_t>(devicemodel::words_per_device(spec));
            if (size == 0) {   // the CPU has none of these
                CHECK(wire.exchange(cpu, read_words_req(form, address(spec, 0), per)) ==
                      wire.expect(error(e.out_of_range, 0x0401, sub_words)));
                continue;
            }
            const auto last = size - 1;
            if (spec.unit == devicemodel::Unit::Bit) {
                CHECK(wire.exchange(cpu, read_bits_req(form, address(spec, last), 1)) == wire.expect(ok(bits({0}))));
                CHECK(wire.exchange(cpu, read_bits_req(form, address(spec, last), 2)) ==
                      wire.expect(error(e.out_of_range, 0x0401, sub_bits)));
                CHECK(wire.exchange(cpu, read_bits_req(form, address(spec, size), 1)) ==
                      wire.expect(error(e.out_of_range, 0x0401, sub_bits)));
                if (size >= 16)
                    CHECK(wire.exchange(cpu, read_words_req(form, address(spec, size - 16), 1)) ==
                          wire.expect(ok(words({0}))));
                if (size >= 15)
                    CHECK(wire.exchange(cpu, read_words_req(form, address(spec, size - 15), 1)) ==
                          wire.expect(error(e.out_of_range, 0x0401, sub_words)));
            } else {
                CHECK(wire.exchange(cpu, read_words_req(form, address(spec, last), per)) ==
                      wire.expect(ok(words(std::vector<std::uint16_t>(per, 0)))));
                CHECK(wire.exchange(cpu, read_words_req(form, address(spec, last), static_cast<std::uint16_t>(2 * per))) ==
                      wire.expect(error(e.out_of_range, 0x0401, sub_words)));
                CHECK(wire.exchange(cpu, read_words_req(form, address(spec, size), per)) ==
                      wire.expect(error(e.out_of_range, 0x0401, sub_words)));
            }
        }
    }
    SECTION("one word past the end of D, written: memory unchanged") {
        const auto& d = *devicemodel::find_by_symbol("D");
        const auto size = profile.size(devicemodel::Area::D);
        cpu.memory().set_value(d, size - 1, 0x1111);
        auto before = snapshot(cpu);
        CHECK(wire.exchange(cpu, write_words_req(Form::Q, address(d, size - 1), {1, 2})) ==
              wire.expect(error(e.out_of_range, 0x1401, 0x0000)));
        CHECK((snapshot(cpu) == before));
        CHECK(wire.exchange(cpu, write_words_req(Form::Q, address(d, size - 1), {2})) == wire.expect(ok()));
        CHECK(cpu.memory().value(d, size - 1) == 2);
    }
}

TEST_CASE("R and ZR: iQ-R checks the start only (hardware-behaviour §6)", "[profiles][range]") {   // signposts: allow (the name ctest lists)
    auto cpu = make_cpu("R08CPU");
    auto wire = GENERATE(kBinary3E, kBinary4E, kAscii3E, kAscii4E);
    auto form = GENERATE(Form::Q, Form::IQR);
    const auto sub = subcommand(form, false);
    const std::vector<std::uint16_t> zeros(64, 0);
    SECTION("R32767 x64 -> ok (continues into ZR)") {
        cpu.memory().set_value(*devicemodel::find_by_symbol("ZR"), 32768, 0x00AA);
        auto expect = zeros;
        expect[1] = 0x00AA;
        CHECK(wire.exchange(cpu, read_words_req(form, "R32767", 64)) == wire.expect(ok(words(expect))));
    }
    SECTION("R32768 x1 -> 4031") {
        CHECK(wire.exchange(cpu, read_words_req(form, "R32768", 1)) == wire.expect(error(0x4031, 0x0401, sub)));
    }
    SECTION("ZR163839 x64 -> ok, written and read back") {
        std::vector<std::uint16_t> in(64);
        for (std::uint16_t i = 0; i < 64; ++i) in[i] = static_cast<std::uint16_t>(0x100 + i);
        CHECK(wire.exchange(cpu, write_words_req(form, "ZR163839", in)) == wire.expect(ok()));
        CHECK(wire.exchange(cpu, read_words_req(form, "ZR163839", 64)) == wire.expect(ok(words(in))));
    }
    SECTION("ZR163839 x960 -> ok") {
        CHECK(wire.exchange(cpu, read_words_req(form, "ZR163839", 960)) ==
              wire.expect(ok(words(std::vector<std::uint16_t>(960, 0)))));
    }
    SECTION("ZR163840 x1 -> 4031, written: memory unchanged") {
        CHECK(wire.exchange(cpu, read_words_req(form, "ZR163840", 1)) == wire.expect(error(0x4031, 0x0401, sub)));
        auto before = snapshot(cpu);
        CHECK(wire.exchange(cpu, write_words_req(form, "ZR163840", {1})) == wire.expect(error(0x4031, 0x1401, sub)));
        CHECK((snapshot(cpu) == before));
    }
}

TEST_CASE("R and ZR: Q/L CPUs check the whole span", "[profiles][range]") {
    auto name = GENERATE(as<std::string>{}, "Q26UDEHCPU", "Q06UDVCPU-QJ71E71", "L26CPU-BT");
    auto cpu = make_cpu(name);
    auto wire = GENERATE(kBinary3E, kAscii3E);
    const auto zr_last = cpu.profile().size(devicemodel::Area::ZR) - 1;
    const auto zr = *devicemodel::find_by_symbol("ZR");
    CHECK(wire.exchange(cpu, read_words_req(Form::Q, "R32767", 1)) == wire.expect(ok(words({0}))));
    CHECK(wire.exchange(cpu, read_words_req(Form::Q, "R32767", 2)) == wire.expect(error(0xC056, 0x0401, 0x0000)));
    CHECK(wire.exchange(cpu, read_words_req(Form::Q, address(zr, zr_last), 1)) == wire.expect(ok(words({0}))));
    CHECK(wire.exchange(cpu, read_words_req(Form::Q, address(zr, zr_last), 2)) == wire.expect(error(0xC056, 0x0401, 0x0000)));
}

TEST_CASE("how each port refuses frames and subcommands (hardware-behaviour §4)", "[profiles][refusals]") {   // signposts: allow (the name ctest lists)
    SECTION("QnU and L built-in: a 4E request gets no answer") {
        auto name = GENERATE(as<std::string>{}, "Q26UDEHCPU", "L26CPU-BT");
        auto cpu = make_cpu(name);
        auto wire = GENERATE(kBinary4E, kAscii4E);
        auto frame = wire.request(read_words_req(Form::Q, "D0", 1));
        auto out = run(cpu, frame);
        CHECK(to_string(out.action) == "Silent");
        CHECK(out.consumed == frame.size());
        CHECK(out.response.empty());
        CHECK_FALSE(out.note.empty());
        auto before = snapshot(cpu);
        out = run(cpu, wire.request(write_words_req(Form::Q, "D0", {1})));
        CHECK(to_string(out.action) == "Silent");
        CHECK((snapshot(cpu) == before));
    }
    SECTION("QnU and L built-in: iQ-R subcommands -> C059") {
        auto name = GENERATE(as<std::string>{}, "Q26UDEHCPU", "L26CPU-BT");
        auto cpu = make_cpu(name);
        auto wire = GENERATE(kBinary3E, kAscii3E);
        CHECK(wire.exchange(cpu, read_words_req(Form::IQR, "D0", 1)) == wire.expect(error(0xC059, 0x0401, 0x0002)));
        CHECK(wire.exchange(cpu, read_bits_req(Form::IQR, "M0", 1)) == wire.expect(error(0xC059, 0x0401, 0x0003)));
        auto before = snapshot(cpu);
        CHECK(wire.exchange(cpu, write_words_req(Form::IQR, "D0", {1})) == wire.expect(error(0xC059, 0x1401, 0x0002)));
        CHECK((snapshot(cpu) == before));
    }
    SECTION("QnU and L built-in: 0406, 1406, 0613 -> C059") {
        auto name = GENERATE(as<std::string>{}, "Q26UDEHCPU", "L26CPU-BT");
        auto cpu = make_cpu(name);
        auto wire = GENERATE(kBinary3E, kAscii3E);
        for (std::uint16_t command : {0x0406, 0x1406, 0x0613})
            CHECK(wire.exchange(cpu, word(command) + word(0x0000)) == wire.expect(error(0xC059, command, 0x0000)));
    }
    SECTION("QJ71E71-100: 4E answered, iQ-R subcommands -> C061") {
        auto cpu = make_cpu("Q06UDVCPU-QJ71E71");
        auto wire = GENERATE(kBinary3E, kBinary4E, kAscii3E, kAscii4E);
        CHECK(wire.exchange(cpu, read_words_req(Form::Q, "D0", 1)) == wire.expect(ok(words({0}))));
        CHECK(wire.exchange(cpu, read_words_req(Form::IQR, "D0", 1)) == wire.expect(error(0xC061, 0x0401, 0x0002)));
        CHECK(wire.exchange(cpu, read_bits_req(Form::IQR, "M0", 1)) == wire.expect(error(0xC061, 0x0401, 0x0003)));
        CHECK(wire.exchange(cpu, word(0x0401) + word(0x0082)) == wire.expect(error(0xC061, 0x0401, 0x0082)));
        auto before = snapshot(cpu);
        CHECK(wire.exchange(cpu, write_bits_req(Form::IQR, "M0", {1})) == wire.expect(error(0xC061, 0x1401, 0x0003)));
        CHECK((snapshot(cpu) == before));
    }
    SECTION("FX5U: iQ-R subcommands close the connection") {
        auto cpu = make_cpu("FX5U-32MR");
        auto wire = GENERATE(kBinary3E, kAscii3E);
        for (const auto& request : {read_words_req(Form::IQR, "D0", 1), write_words_req(Form::IQR, "D0", {1}),
                                    read_bits_req(Form::IQR, "M0", 1)}) {
            auto before = snapshot(cpu);
            auto out = run(cpu, wire.request(request));
            CHECK(to_string(out.action) == "Close");
            CHECK(out.response.empty());
            CHECK((snapshot(cpu) == before));
        }
        CHECK(wire.exchange(cpu, read_words_req(Form::Q, "D0", 1)) == wire.expect(ok(words({0}))));
    }
    SECTION("FX5U: 0801, 0802, 0613 -> C059") {
        auto cpu = make_cpu("FX5U-32MR");
        auto wire = GENERATE(kBinary3E, kAscii3E);
        for (std::uint16_t command : {0x0801, 0x0802, 0x0613})
            CHECK(wire.exchange(cpu, word(command) + word(0x0000)) == wire.expect(error(0xC059, command, 0x0000)));
    }
    SECTION("iQ-R built-in answers both forms and both frames") {
        auto name = GENERATE(as<std::string>{}, "R08CPU", "R120PCPU");
        auto cpu = make_cpu(name);
        auto wire = GENERATE(kBinary3E, kBinary4E, kAscii3E, kAscii4E);
        CHECK(wire.exchange(cpu, read_words_req(Form::Q, "D0", 1)) == wire.expect(ok(words({0}))));
        CHECK(wire.exchange(cpu, read_words_req(Form::IQR, "D0", 1)) == wire.expect(ok(words({0}))));
    }
}
