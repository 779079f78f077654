// Read Random 0403 / Write Random 1402: the worked examples RR and WR1 of
// SLMP Reference Manual §5.2 byte for byte (binary and ASCII, 3E and
// 4E), WR2 (whose values the manual does not give) with chosen values, then
// the limits of every profile one point below, at and above
// (real-CPU measurements), the devices the commands may not name, bit units
// on word devices, and ranges — with memory unchanged after every rejected write.
#include "support/device_commands.hpp"

using namespace slmp;
using namespace slmp::test;
using devicemodel::Cpu;

namespace {

// Example RR's device list in a form: word D0 TN0 M100 X20, dword D1500 Y160 M1111.
std::vector<Payload> rr_words(Form f, bool ext = false) {
    return {field(f, ext, "D0"), field(f, ext, "TN0"), field(f, ext, "M100"), field(f, ext, "X20")};
}
std::vector<Payload> rr_dwords(Form f, bool ext = false) {
    return {field(f, ext, "D1500"), field(f, ext, "Y160"), field(f, ext, "M1111")};
}

// §6.3, the JP ASCII vector and the binary vector (inferred from JP's 0801 binary example).
const Payload kRRRequest{
    "03 04 00 00 04 03 00 00 00 A8 00 00 00 C2 64 00 00 90 20 00 00 9C DC 05 00 A8 60 01 00 9D 57 04 00 90",
    "04030000"
    "04"
    "03"
    "D*000000"
    "TN000000"
    "M*000100"
    "X*000020"
    "D*001500"
    "Y*000160"
    "M*001111"};

}  // namespace

TEST_CASE("§6.3 Example RR: Read Random as printed", "[random][spec]") {
    auto cpu = make_cpu("R08CPU");
    load_example_rr(cpu);
    auto wire = GENERATE(kBinary3E, kBinary4E, kAscii3E, kAscii4E);
    // The test encoder writes the manual's bytes (a check on the helper itself).
    CHECK(wire.data(random_read_req(0x0000, rr_words(Form::Q), rr_dwords(Form::Q))) == wire.data(kRRRequest));
    CHECK(wire.exchange(cpu, kRRRequest) == wire.expect(ok(kExampleRRAnswer)));
    SECTION("iQ-R form 0002 (derived): same answer") {
        CHECK(wire.exchange(cpu, random_read_req(0x0002, rr_words(Form::IQR), rr_dwords(Form::IQR))) ==
              wire.expect(ok(kExampleRRAnswer)));
    }
    SECTION("extended 0080 / 0082 with plain devices (derived): same answer") {
        CHECK(wire.exchange(cpu, random_read_req(0x0080, rr_words(Form::Q, true), rr_dwords(Form::Q, true))) ==
              wire.expect(ok(kExampleRRAnswer)));
        CHECK(wire.exchange(cpu, random_read_req(0x0082, rr_words(Form::IQR, true), rr_dwords(Form::IQR, true))) ==
              wire.expect(ok(kExampleRRAnswer)));
    }
    SECTION("a dword list only, and a word list only") {
        CHECK(wire.exchange(cpu, random_read_req(0x0000, {}, {device(Form::Q, "D1500")})) ==
              wire.expect(ok(dword(0x4C544F4E))));
        CHECK(wire.exchange(cpu, random_read_req(0x0000, {device(Form::Q, "X20")}, {})) ==
              wire.expect(ok(word(0x4849))));
    }
}

TEST_CASE("§6.4 Example WR1: Write Random bits, M50 off and Y2F on, as printed", "[random][spec]") {
    auto cpu = make_cpu("R08CPU");
    auto wire = GENERATE(kBinary3E, kBinary4E, kAscii3E, kAscii4E);
    const Payload wr1{"02 14 01 00 02 32 00 00 90 00 2F 00 00 9D 01",
                      "14020001"
                      "02"
                      "M*000050"
                      "00"
                      "Y*00002F"
                      "01"};
    CHECK(wire.data(random_write_bits_req(0x0001, {{device(Form::Q, "M50"), false}, {device(Form::Q, "Y2F"), true}})) ==
          wire.data(wr1));
    cpu.memory().set_bit(spec_of("M"), 50, true);
    CHECK(wire.exchange(cpu, wr1) == wire.expect(ok()));
    CHECK_FALSE(cpu.memory().bit(spec_of("M"), 50));
    CHECK(cpu.memory().bit(spec_of("Y"), 0x2F));
    CHECK_FALSE(cpu.memory().bit(spec_of("Y"), 0x2E));
    CHECK_FALSE(cpu.memory().bit(spec_of("Y"), 0x30));
    SECTION("iQ-R form 0003 (derived): set/reset is a word, \"0001\" / 01 00") {
        const Payload wr1_iqr{"02 14 03 00 02 32 00 00 00 90 00 01 00 2F 00 00 00 9D 00 00 00",
                              "14020003"
                              "02"
                              "M***00000050"
                              "0001"
                              "Y***0000002F"
                              "0000"};
        CHECK(wire.exchange(cpu, wr1_iqr) == wire.expect(ok()));
        CHECK(cpu.memory().bit(spec_of("M"), 50));
        CHECK_FALSE(cpu.memory().bit(spec_of("Y"), 0x2F));
    }
}

TEST_CASE("§6.4 Example WR2 (values chosen): word and dword Write Random, read back by RR", "[random][spec]") {
    // The manual gives the device list (D0 D1 M100 X20; D1500 Y160 M1111) but no values.
    auto cpu = make_cpu("R08CPU");
    auto wire = GENERATE(kBinary3E, kBinary4E, kAscii3E, kAscii4E);
    auto form = GENERATE(Form::Q, Form::IQR);
    const std::uint16_t sub = form == Form::Q ? 0x0000 : 0x0002;
    auto req = random_write_words_req(
        sub,
        {{device(form, "D0"), 0x0550},
         {device(form, "D1"), 0x0575},
         {device(form, "M100"), 0x0540},
         {device(form, "X20"), 0x0583}},
        {{device(form, "D1500"), 0x04390469}, {device(form, "Y160"), 0x04240473}, {device(form, "M1111"), 0x0C3DEB9A}});
    CHECK(wire.exchange(cpu, req) == wire.expect(ok()));
    CHECK(cpu.memory().value(spec_of("D"), 1) == 0x0575);
    CHECK(cpu.memory().bit(spec_of("M"), 106));  // 0x0540: bit 6
    CHECK_FALSE(cpu.memory().bit(spec_of("M"), 105));
    CHECK(cpu.memory().bit(spec_of("Y"), 0x160));  // 0x...73: bit 0
    CHECK(wire.exchange(cpu, random_read_req(0x0000, rr_words(Form::Q), rr_dwords(Form::Q))) ==
          wire.expect(
              ok(words({0x0550, 0x0000, 0x0540, 0x0583}) + dword(0x04390469) + dword(0x04240473) + dword(0x0C3DEB9A))));
}

// ---------------------------------------------------------------------------
// Limits (real-CPU measurements), written down here rather than read from the profiles.

namespace {

struct Limits {
    const char* profile;
    bool iqr_form;                // serves 0002/0003 (and 0082/0083)
    std::uint16_t extended_code;  // end code for an exceeded 008x limit (QJ71E71-100: 4080), else 0
};
const Limits kProfiles[] = {
    {"R08CPU", true, 0},     {"R120PCPU", true, 0},   {"Q26UDEHCPU", false, 0}, {"Q06UDVCPU-QJ71E71", false, 0x4080},
    {"L26CPU-BT", false, 0}, {"FX5U-32MR", false, 0},
};

// The request forms to try on a profile: {form, extended}.
std::vector<std::pair<Form, bool>> forms_of(const Limits& l) {
    std::vector<std::pair<Form, bool>> forms = {{Form::Q, false}, {Form::Q, true}};
    if (l.iqr_form) forms.insert(forms.end(), {{Form::IQR, false}, {Form::IQR, true}});
    return forms;
}

// The effective limit: Q form 192-style, iQ-R form 96-style; 0080/0081 count
// every point twice. (For 1402 the manual's *1 names iQ-R targets only; the
// profiles double on Q/L/iQ-F CPUs too — a judgement call, reported.)
unsigned effective(Form form, bool extended, unsigned q, unsigned iqr) {
    return form == Form::IQR ? iqr : extended ? q / 2 : q;
}

std::uint16_t over_code(const Limits& l, bool extended, std::uint16_t code) {
    return extended && l.extended_code ? l.extended_code : code;
}

// D(n) = n for n < 3000, so any random read of D has a known answer.
void number_d(Cpu& cpu) {
    for (std::uint32_t n = 0; n < 3000; ++n) cpu.memory().set_value(spec_of("D"), n, n);
}

// n points for 0403/0801: two thirds words D0.., one third dwords D2000, D2002, ...
struct RandomList {
    std::vector<Payload> words, dwords;
    Payload answer;
};
RandomList random_list(Form form, bool extended, unsigned n) {
    RandomList list;
    unsigned dw = n / 3, w = n - dw;
    for (unsigned i = 0; i < w; ++i) {
        list.words.push_back(field(form, extended, "D" + std::to_string(i)));
        list.answer = list.answer + word(static_cast<std::uint16_t>(i));
    }
    for (unsigned j = 0; j < dw; ++j) {
        auto d = 2000 + 2 * j;
        list.dwords.push_back(field(form, extended, "D" + std::to_string(d)));
        list.answer = list.answer + dword((d + 1) << 16 | d);
    }
    return list;
}

}  // namespace

TEST_CASE("0403 word+dword points: below, at and above the limit per profile", "[random][limits][profiles]") {
    auto l = GENERATE(from_range(std::begin(kProfiles), std::end(kProfiles)));
    auto form_ext = GENERATE_COPY(from_range(forms_of(l)));
    const Form form = form_ext.first;
    const bool extended = form_ext.second;
    auto wire = GENERATE(kBinary3E, kAscii3E);
    auto cpu = make_cpu(l.profile);
    number_d(cpu);
    const auto limit = effective(form, extended, 192, 96);
    const auto sub = device_sub(form, extended);
    INFO(l.profile << ", " << wire.name() << ", subcommand " << hexn(sub, 4) << ", limit " << limit);
    for (unsigned n : {1u, limit - 1, limit}) {
        auto list = random_list(form, extended, n);
        CHECK(wire.exchange(cpu, random_read_req(sub, list.words, list.dwords)) == wire.expect(ok(list.answer)));
    }
    auto list = random_list(form, extended, limit + 1);
    CHECK(wire.exchange(cpu, random_read_req(sub, list.words, list.dwords)) ==
          wire.expect(error(over_code(l, extended, 0xC054), 0x0403, sub)));
    // No points at all is outside 1..limit too.
    CHECK(wire.exchange(cpu, random_read_req(sub, {}, {})) ==
          wire.expect(error(over_code(l, extended, 0xC054), 0x0403, sub)));
}

TEST_CASE("1402 word units: 12 per word + 14 per dword, below, at and above per profile",
          "[random][limits][profiles]") {
    auto l = GENERATE(from_range(std::begin(kProfiles), std::end(kProfiles)));
    auto form_ext = GENERATE_COPY(from_range(forms_of(l)));
    const Form form = form_ext.first;
    const bool extended = form_ext.second;
    auto wire = GENERATE(kBinary3E, kAscii3E);
    auto cpu = make_cpu(l.profile);
    // 1920 (Q form) / 960 (iQ-R form); 0080 counts twice, so 960 too.
    const unsigned budget = effective(form, extended, 1920, 960);
    const auto sub = device_sub(form, extended);
    INFO(l.profile << ", " << wire.name() << ", subcommand " << hexn(sub, 4) << ", weight limit " << budget);
    auto request = [&](unsigned w, unsigned dw) {
        std::vector<std::pair<Payload, std::uint16_t>> words;
        std::vector<std::pair<Payload, std::uint32_t>> dwords;
        for (unsigned i = 0; i < w; ++i) words.push_back({field(form, extended, "D" + std::to_string(i)), 0x5000 + i});
        for (unsigned j = 0; j < dw; ++j)
            dwords.push_back({field(form, extended, "D" + std::to_string(2000 + 2 * j)), 0xA0000000u + j});
        return random_write_words_req(sub, words, dwords);
    };
    const unsigned all_words = budget / 12;               // 160 / 80
    const unsigned dw = 12, w = (budget - 14 * dw) / 12;  // 146+12 / 66+12: exactly the budget
    REQUIRE(12 * w + 14 * dw == budget);
    SECTION("words only: one below, at") {
        CHECK(wire.exchange(cpu, request(all_words - 1, 0)) == wire.expect(ok()));
        CHECK(wire.exchange(cpu, request(all_words, 0)) == wire.expect(ok()));
        CHECK(cpu.memory().value(spec_of("D"), all_words - 1) == 0x5000 + all_words - 1);
    }
    SECTION("words and dwords exactly at the weight") {
        CHECK(wire.exchange(cpu, request(w, dw)) == wire.expect(ok()));
        CHECK(cpu.memory().value(spec_of("D"), 2000 + 2 * (dw - 1)) == dw - 1);
        CHECK(cpu.memory().value(spec_of("D"), 2001 + 2 * (dw - 1)) == 0xA000);
    }
    SECTION("one word over (words only, and mixed) -> C054, nothing written") {
        auto before = snapshot(cpu);
        CHECK(wire.exchange(cpu, request(all_words + 1, 0)) ==
              wire.expect(error(over_code(l, extended, 0xC054), 0x1402, sub)));
        CHECK(wire.exchange(cpu, request(w + 1, dw)) ==
              wire.expect(error(over_code(l, extended, 0xC054), 0x1402, sub)));
        CHECK(wire.exchange(cpu, request(w - 1, dw + 1)) ==
              wire.expect(error(over_code(l, extended, 0xC054), 0x1402, sub)));
        CHECK(wire.exchange(cpu, request(0, 0)) == wire.expect(error(over_code(l, extended, 0xC054), 0x1402, sub)));
        CHECK((snapshot(cpu) == before));
    }
}

TEST_CASE("1402 bit units: below, at and above per profile", "[random][limits][profiles]") {
    auto l = GENERATE(from_range(std::begin(kProfiles), std::end(kProfiles)));
    auto form_ext = GENERATE_COPY(from_range(forms_of(l)));
    const Form form = form_ext.first;
    const bool extended = form_ext.second;
    auto wire = GENERATE(kBinary3E, kAscii3E);
    auto cpu = make_cpu(l.profile);
    const unsigned limit = effective(form, extended, 188, 94);
    const auto sub = device_sub(form, extended, true);
    INFO(l.profile << ", " << wire.name() << ", subcommand " << hexn(sub, 4) << ", limit " << limit);
    auto request = [&](unsigned n) {
        std::vector<std::pair<Payload, bool>> points;
        for (unsigned i = 0; i < n; ++i) points.push_back({field(form, extended, "M" + std::to_string(2 * i)), true});
        return random_write_bits_req(sub, points);
    };
    CHECK(wire.exchange(cpu, request(limit - 1)) == wire.expect(ok()));
    CHECK_FALSE(cpu.memory().bit(spec_of("M"), 2 * (limit - 1)));
    CHECK(wire.exchange(cpu, request(limit)) == wire.expect(ok()));
    CHECK(cpu.memory().bit(spec_of("M"), 2 * (limit - 1)));
    CHECK_FALSE(cpu.memory().bit(spec_of("M"), 2 * limit - 1));
    auto before = snapshot(cpu);
    CHECK(wire.exchange(cpu, request(limit + 1)) == wire.expect(error(over_code(l, extended, 0xC053), 0x1402, sub)));
    CHECK(wire.exchange(cpu, request(0)) == wire.expect(error(over_code(l, extended, 0xC053), 0x1402, sub)));
    CHECK((snapshot(cpu) == before));
}

// ---------------------------------------------------------------------------
// Devices, units and ranges (R08CPU unless named)

TEST_CASE("0403 refuses the long contacts and coils with 4030, 1402 names anything but S", "[random][devices]") {
    auto cpu = make_cpu("R08CPU");
    auto wire = GENERATE(kBinary3E, kAscii3E);
    for (const char* symbol : {"LTS", "LTC", "LSTS", "LSTC", "LCS", "LCC"}) {
        INFO(symbol);
        auto name = std::string(symbol) + "0";
        CHECK(wire.exchange(cpu, random_read_req(0x0002, {device(Form::IQR, "D0"), device(Form::IQR, name)}, {})) ==
              wire.expect(error(0x4030, 0x0403, 0x0002)));
        CHECK(wire.exchange(cpu, random_write_bits_req(0x0003, {{device(Form::IQR, name), true}})) ==
              wire.expect(ok()));
    }
    // The current values are fine: LTN/LCN as a dword is the 32-bit value.
    cpu.memory().set_value(spec_of("LCN"), 3, 0x12345678);
    CHECK(wire.exchange(cpu, random_read_req(0x0002, {device(Form::IQR, "LCN3")}, {device(Form::IQR, "LCN3")})) ==
          wire.expect(ok(word(0x5678) + dword(0x12345678))));
    // S is read-only over the built-in port (real-CPU measurements): 4030, nothing written.
    check_refused(cpu, wire,
                  random_write_bits_req(0x0001, {{device(Form::Q, "M0"), true}, {device(Form::Q, "S0"), true}}), 0x4030,
                  0x1402, 0x0001);
    check_refused(cpu, wire,
                  random_write_words_req(0x0000, {{device(Form::Q, "D0"), 1}, {device(Form::Q, "S0"), 1}}, {}), 0x4030,
                  0x1402, 0x0000);
}

TEST_CASE("1402 bit units on a word device -> C05C, nothing written", "[random][devices]") {
    auto cpu = make_cpu("R08CPU");
    auto wire = GENERATE(kBinary3E, kAscii3E);
    check_refused(cpu, wire,
                  random_write_bits_req(0x0001, {{device(Form::Q, "M0"), true}, {device(Form::Q, "D0"), true}}), 0xC05C,
                  0x1402, 0x0001);
    check_refused(cpu, wire, random_write_bits_req(0x0003, {{device(Form::IQR, "TN0"), true}}), 0xC05C, 0x1402, 0x0003);
}

TEST_CASE("0403/1402 range: the last device, one past it, a dword across the end", "[random][range]") {
    auto wire = GENERATE(kBinary3E, kAscii3E);
    SECTION("R08CPU: D has 10240 devices, out of range is 4031") {
        auto cpu = make_cpu("R08CPU");
        cpu.memory().set_value(spec_of("D"), 10239, 0x7777);
        CHECK(wire.exchange(cpu, random_read_req(0x0000, {device(Form::Q, "D10239")}, {})) ==
              wire.expect(ok(word(0x7777))));
        CHECK(wire.exchange(cpu, random_read_req(0x0000, {device(Form::Q, "D10240")}, {})) ==
              wire.expect(error(0x4031, 0x0403, 0x0000)));
        CHECK(wire.exchange(cpu, random_read_req(0x0000, {}, {device(Form::Q, "D10239")})) ==
              wire.expect(error(0x4031, 0x0403, 0x0000)));
        check_refused(cpu, wire,
                      random_write_words_req(0x0000, {{device(Form::Q, "D0"), 1}}, {{device(Form::Q, "D10239"), 2}}),
                      0x4031, 0x1402, 0x0000);
        check_refused(cpu, wire,
                      random_write_bits_req(0x0001, {{device(Form::Q, "M0"), true}, {device(Form::Q, "M12288"), true}}),
                      0x4031, 0x1402, 0x0001);
    }
    SECTION("Q26UDEHCPU: D has 12288 devices, out of range is C056") {
        auto cpu = make_cpu("Q26UDEHCPU");
        CHECK(wire.exchange(cpu, random_read_req(0x0000, {device(Form::Q, "D12287")}, {})) == wire.expect(ok(word(0))));
        CHECK(wire.exchange(cpu, random_read_req(0x0000, {device(Form::Q, "D12288")}, {})) ==
              wire.expect(error(0xC056, 0x0403, 0x0000)));
        check_refused(cpu, wire,
                      random_write_words_req(0x0000, {{device(Form::Q, "D0"), 1}, {device(Form::Q, "D12288"), 1}}, {}),
                      0xC056, 0x1402, 0x0000);
    }
}

TEST_CASE("0403/1402 malformed lists: short or long data -> C061, nothing written", "[random][errors]") {
    auto cpu = make_cpu("R08CPU");
    auto wire = GENERATE(kBinary3E, kAscii3E);
    // Two word points announced, one device sent.
    check_refused(cpu, wire, word(0x0403) + word(0) + byte(2) + byte(0) + device(Form::Q, "D0"), 0xC061, 0x0403,
                  0x0000);
    // One word write with a trailing extra word.
    check_refused(cpu, wire, random_write_words_req(0x0000, {{device(Form::Q, "D0"), 1}}, {}) + word(0), 0xC061, 0x1402,
                  0x0000);
}
