// Read Block 0406 / Write Block 1406 (SLMP Reference Manual §5.2):
// Example RB byte for byte (the response values are the manual's missing
// figure, so they are chosen here), Write Block with the same blocks, block
// counts and totals per profile (1406 adds 4 or 9 per block; R08CPU's observed
// 951 words, real-CPU measurements), the mixed word+bit write each profile
// refuses (§2), devices the commands may not name and wrong block kinds.
#include "support/device_commands.hpp"

using namespace slmp;
using namespace slmp::test;
using devicemodel::Cpu;

namespace {

// Example RB's blocks: words D0 ×4, W100 ×8; bits M0 ×2, M128 ×2, B100 ×3 (in words).
const Payload kRBRequest{
    "06 04 00 00 02 03 00 00 00 A8 04 00 00 01 00 B4 08 00 00 00 00 90 02 00 80 00 00 90 02 00 "
    "00 01 00 A0 03 00",
    "04060000"
    "02"
    "03"
    "D*"
    "000000"
    "0004"
    "W*"
    "000100"
    "0008"
    "M*"
    "000000"
    "0002"
    "M*"
    "000128"
    "0002"
    "B*"
    "000100"
    "0003"};

const std::vector<std::uint16_t> kD = {0x0082, 0x0131, 0x0001, 0x1995};
const std::vector<std::uint16_t> kW = {0x1234, 0x0002, 0x1130, 0x2000, 0xFFFF, 0x8000, 0x0010, 0xCAFE};
const std::vector<std::uint16_t> kM0 = {0x2030, 0x4849};  // M15..M0 = 0010 0000 0011 0000
const std::vector<std::uint16_t> kM128 = {0xB9AF, 0xC3DE};
const std::vector<std::uint16_t> kB100 = {0x0001, 0x8000, 0xA5A5};

Payload rb_answer() {
    return words(kD) + words(kW) + words(kM0) + words(kM128) + words(kB100);
}

std::vector<std::pair<Payload, std::uint16_t>> rb_words(Form f, bool ext = false) {
    return {{field(f, ext, "D0"), 4}, {field(f, ext, "W100"), 8}};
}
std::vector<std::pair<Payload, std::uint16_t>> rb_bits(Form f, bool ext = false) {
    return {{field(f, ext, "M0"), 2}, {field(f, ext, "M128"), 2}, {field(f, ext, "B100"), 3}};
}

void load_rb(Cpu& cpu) {
    auto& m = cpu.memory();
    m.write_words(spec_of("D"), 0, kD);
    m.write_words(spec_of("W"), 0x100, kW);
    m.write_words(spec_of("M"), 0, kM0);
    m.write_words(spec_of("M"), 128, kM128);
    m.write_words(spec_of("B"), 0x100, kB100);
}

}  // namespace

TEST_CASE("§6.7 Example RB: Read Block as printed, values chosen", "[block][spec]") {
    auto cpu = make_cpu("R08CPU");
    load_rb(cpu);
    // The bit blocks carry M15..M0 in one word, M0 in bit 0 (the JP caption).
    REQUIRE(cpu.memory().bit(spec_of("M"), 4));
    REQUIRE(cpu.memory().bit(spec_of("M"), 13));
    REQUIRE_FALSE(cpu.memory().bit(spec_of("M"), 0));
    auto wire = GENERATE(kBinary3E, kBinary4E, kAscii3E, kAscii4E);
    CHECK(wire.data(block_read_req(0x0000, rb_words(Form::Q), rb_bits(Form::Q))) == wire.data(kRBRequest));
    CHECK(wire.exchange(cpu, kRBRequest) == wire.expect(ok(rb_answer())));
    SECTION("iQ-R form 0002 and extended 0080/0082 (derived): same answer") {
        CHECK(wire.exchange(cpu, block_read_req(0x0002, rb_words(Form::IQR), rb_bits(Form::IQR))) ==
              wire.expect(ok(rb_answer())));
        CHECK(wire.exchange(cpu, block_read_req(0x0080, rb_words(Form::Q, true), rb_bits(Form::Q, true))) ==
              wire.expect(ok(rb_answer())));
        CHECK(wire.exchange(cpu, block_read_req(0x0082, rb_words(Form::IQR, true), rb_bits(Form::IQR, true))) ==
              wire.expect(ok(rb_answer())));
    }
    SECTION("bit blocks only, word blocks only") {
        CHECK(wire.exchange(cpu, block_read_req(0x0000, {}, {{device(Form::Q, "B100"), 3}})) ==
              wire.expect(ok(words(kB100))));
        CHECK(wire.exchange(cpu, block_read_req(0x0000, {{device(Form::Q, "W100"), 8}}, {})) ==
              wire.expect(ok(words(kW))));
    }
}

TEST_CASE("§6.8 Write Block with Example RB's blocks (values chosen)", "[block][spec]") {
    auto wire = GENERATE(kBinary3E, kBinary4E, kAscii3E, kAscii4E);
    auto form = GENERATE(Form::Q, Form::IQR);
    const auto sub = subcommand(form, false);
    const std::vector<Block> word_blocks = {{device(form, "D0"), kD}, {device(form, "W100"), kW}};
    const std::vector<Block> bit_blocks = {
        {device(form, "M0"), kM0}, {device(form, "M128"), kM128}, {device(form, "B100"), kB100}};
    SECTION("R08CPU: word blocks and bit blocks in separate requests") {
        auto cpu = make_cpu("R08CPU");
        CHECK(wire.exchange(cpu, block_write_req(sub, word_blocks, {})) == wire.expect(ok()));
        CHECK(wire.exchange(cpu, block_write_req(sub, {}, bit_blocks)) == wire.expect(ok()));
        CHECK(wire.exchange(cpu, kRBRequest) == wire.expect(ok(rb_answer())));
        CHECK(cpu.memory().bit(spec_of("M"), 13));
        CHECK(cpu.memory().bit(spec_of("B"), 0x100));
        CHECK(cpu.memory().bit(spec_of("B"), 0x11F));
        CHECK_FALSE(cpu.memory().bit(spec_of("B"), 0x11E));
    }
    SECTION("Q06UDVCPU via QJ71E71-100 takes both kinds in one request") {
        if (form == Form::IQR) return;  // C061 on this port (test_profile_limits)
        auto cpu = make_cpu("Q06UDVCPU-QJ71E71");
        CHECK(wire.exchange(cpu, block_write_req(sub, word_blocks, bit_blocks)) == wire.expect(ok()));
        CHECK(wire.exchange(cpu, kRBRequest) == wire.expect(ok(rb_answer())));
    }
}

TEST_CASE("1406 with word and bit blocks in one request: each profile's answer", "[block][profiles]") {
    struct Case {
        const char* profile;
        std::uint16_t code;  // 0: written
    };
    // real-CPU measurements: R08CPU C05B, R120PCPU C056, FX5UC C061; Q/L ports write it.
    auto c = GENERATE(Case{"R08CPU", 0xC05B}, Case{"R120PCPU", 0xC056}, Case{"FX5U-32MR", 0xC061},
                      Case{"Q06UDVCPU-QJ71E71", 0});
    auto wire = GENERATE(kBinary3E, kAscii3E);
    auto cpu = make_cpu(c.profile);
    INFO(c.profile << ", " << wire.name());
    auto before = snapshot(cpu);
    auto req = block_write_req(0x0000, {{device(Form::Q, "D0"), {1, 2}}}, {{device(Form::Q, "M0"), {0xFFFF}}});
    if (c.code) {
        CHECK(wire.exchange(cpu, req) == wire.expect(error(c.code, 0x1406, 0x0000)));
        CHECK((snapshot(cpu) == before));
    } else {
        CHECK(wire.exchange(cpu, req) == wire.expect(ok()));
        CHECK(cpu.memory().value(spec_of("D"), 1) == 2);
        CHECK(cpu.memory().bit(spec_of("M"), 15));
    }
    // Reading both kinds in one 0406 is fine everywhere.
    CHECK(wire.exchange(cpu, block_read_req(0x0000, {{device(Form::Q, "D0"), 1}}, {{device(Form::Q, "M0"), 1}})) ==
          wire.expect(ok(
              words({static_cast<std::uint16_t>(c.code ? 0 : 1), static_cast<std::uint16_t>(c.code ? 0 : 0xFFFF)}))));
}

TEST_CASE("0406/1406 are refused by the QnU and L built-in ports (C059)", "[block][profiles]") {
    auto name = GENERATE(as<std::string>{}, "Q26UDEHCPU", "L26CPU-BT");
    auto cpu = make_cpu(name);
    auto wire = GENERATE(kBinary3E, kAscii3E);
    CHECK(wire.exchange(cpu, block_read_req(0x0000, {{device(Form::Q, "D0"), 1}}, {})) ==
          wire.expect(error(0xC059, 0x0406, 0x0000)));
    CHECK(wire.exchange(cpu, block_write_req(0x0000, {{device(Form::Q, "D0"), {1}}}, {})) ==
          wire.expect(error(0xC059, 0x1406, 0x0000)));
}

// ---------------------------------------------------------------------------
// Limits

namespace {

struct BlockProfile {
    const char* profile;
    bool iqr_form;
    std::uint16_t extended_code;  // QJ71E71-100 answers an exceeded 008x limit with 4080
};
const BlockProfile kBlockProfiles[] = {
    {"R08CPU", true, 0}, {"R120PCPU", true, 0}, {"Q06UDVCPU-QJ71E71", false, 0x4080}, {"FX5U-32MR", false, 0}};

// n one-word blocks of D0, D2, D4, ... (D(k) = k).
std::vector<std::pair<Payload, std::uint16_t>> one_word_blocks(Form form, bool ext, unsigned n) {
    std::vector<std::pair<Payload, std::uint16_t>> blocks;
    for (unsigned i = 0; i < n; ++i) blocks.push_back({field(form, ext, "D" + std::to_string(2 * i)), 1});
    return blocks;
}

}  // namespace

TEST_CASE("0406/1406 block counts: below, at and above per profile", "[block][limits][profiles]") {
    auto p = GENERATE(from_range(std::begin(kBlockProfiles), std::end(kBlockProfiles)));
    auto wire = GENERATE(kBinary3E, kAscii3E);
    auto cpu = make_cpu(p.profile);
    for (std::uint32_t n = 0; n < 400; ++n) cpu.memory().set_value(spec_of("D"), n, n);
    for (auto form : {Form::Q, Form::IQR}) {
        if (form == Form::IQR && !p.iqr_form) continue;
        for (bool ext : {false, true}) {
            // Q form 120, iQ-R form 60; 0080 counts each block twice (the profile's
            // choice on Q CPUs too, where the manual's *1 names iQ-R targets only).
            const unsigned limit = form == Form::IQR ? 60 : ext ? 60 : 120;
            const auto sub = device_sub(form, ext);
            const std::uint16_t code = ext && p.extended_code ? p.extended_code : 0xC054;
            INFO(p.profile << ", " << wire.name() << ", subcommand " << hexn(sub, 4) << ", limit " << limit);
            for (unsigned n : {limit - 1, limit}) {
                std::vector<std::uint16_t> answer;
                for (unsigned i = 0; i < n; ++i) answer.push_back(static_cast<std::uint16_t>(2 * i));
                CHECK(wire.exchange(cpu, block_read_req(sub, one_word_blocks(form, ext, n), {})) ==
                      wire.expect(ok(words(answer))));
            }
            CHECK(wire.exchange(cpu, block_read_req(sub, one_word_blocks(form, ext, limit + 1), {})) ==
                  wire.expect(error(code, 0x0406, sub)));
            CHECK(wire.exchange(cpu, block_read_req(sub, {}, {})) == wire.expect(error(code, 0x0406, sub)));

            auto writes = [&](unsigned n) {
                std::vector<Block> blocks;
                for (unsigned i = 0; i < n; ++i)
                    blocks.push_back(
                        {field(form, ext, "D" + std::to_string(2 * i + 1)), {static_cast<std::uint16_t>(0x4000 + i)}});
                return block_write_req(sub, blocks, {});
            };
            // Odd D only, so the even ones keep D(k) = k for the next form's reads.
            CHECK(wire.exchange(cpu, writes(limit)) == wire.expect(ok()));
            CHECK(cpu.memory().value(spec_of("D"), 2 * limit - 1) == 0x4000 + limit - 1);
            auto before = snapshot(cpu);
            CHECK(wire.exchange(cpu, writes(limit + 1)) == wire.expect(error(code, 0x1406, sub)));
            CHECK((snapshot(cpu) == before));
        }
    }
}

TEST_CASE("0406 total points: 960 [C051]", "[block][limits]") {
    auto name = GENERATE(as<std::string>{}, "R08CPU", "Q06UDVCPU-QJ71E71", "FX5U-32MR");
    auto wire = GENERATE(kBinary3E, kAscii3E);
    auto cpu = make_cpu(name);
    INFO(name << ", " << wire.name());
    auto read = [&](std::uint16_t second) {
        return block_read_req(0x0000, {{device(Form::Q, "D0"), 480}}, {{device(Form::Q, "M0"), second}});
    };
    CHECK(wire.exchange(cpu, read(479)) == wire.expect(ok(words(std::vector<std::uint16_t>(959, 0)))));
    CHECK(wire.exchange(cpu, read(480)) == wire.expect(ok(words(std::vector<std::uint16_t>(960, 0)))));
    CHECK(wire.exchange(cpu, read(481)) == wire.expect(error(0xC051, 0x0406, 0x0000)));
    // A block of 0 points is refused as well.
    CHECK(wire.exchange(cpu, block_read_req(0x0000, {{device(Form::Q, "D0"), 0}}, {})) ==
          wire.expect(error(0xC051, 0x0406, 0x0000)));
}

TEST_CASE("1406 total: points + 4 (Q form) or 9 (iQ-R form) per block <= 960 [C051]", "[block][limits]") {
    auto wire = GENERATE(kBinary3E, kAscii3E);
    auto cpu = make_cpu("R08CPU");
    auto one_block = [](Form form, unsigned points) {
        return block_write_req(subcommand(form, false),
                               {{device(form, "D0"), std::vector<std::uint16_t>(points, 0x5A5A)}}, {});
    };
    SECTION("iQ-R form: one block of 951 words (observed on an R08CPU), 952 -> C051") {
        CHECK(wire.exchange(cpu, one_block(Form::IQR, 950)) == wire.expect(ok()));
        CHECK(wire.exchange(cpu, one_block(Form::IQR, 951)) == wire.expect(ok()));
        CHECK(cpu.memory().value(spec_of("D"), 950) == 0x5A5A);
        check_refused(cpu, wire, one_block(Form::IQR, 952), 0xC051, 0x1406, 0x0002);
    }
    SECTION("Q form: one block of 956 words, 957 -> C051") {
        CHECK(wire.exchange(cpu, one_block(Form::Q, 955)) == wire.expect(ok()));
        CHECK(wire.exchange(cpu, one_block(Form::Q, 956)) == wire.expect(ok()));
        check_refused(cpu, wire, one_block(Form::Q, 957), 0xC051, 0x1406, 0x0000);
    }
    SECTION("iQ-R form, two blocks: 2 x 9 + 942 = 960 ok, 943 -> C051") {
        auto two = [](unsigned second) {
            return block_write_req(0x0002,
                                   {{device(Form::IQR, "D0"), std::vector<std::uint16_t>(471, 1)},
                                    {device(Form::IQR, "D1000"), std::vector<std::uint16_t>(second, 2)}},
                                   {});
        };
        CHECK(wire.exchange(cpu, two(471)) == wire.expect(ok()));
        check_refused(cpu, wire, two(472), 0xC051, 0x1406, 0x0002);
    }
}

// ---------------------------------------------------------------------------
// Devices and block kinds

TEST_CASE("0406/1406 refuse the long timers/counters and LZ with 4030", "[block][devices]") {
    auto cpu = make_cpu("R08CPU");
    auto wire = GENERATE(kBinary3E, kAscii3E);
    auto before = snapshot(cpu);
    // §6.7/§6.8's lists. Contacts and coils go in bit blocks, values in word blocks.
    for (const char* symbol : {"LTS", "LTC", "LSTS", "LSTC", "LCS", "LCC"}) {
        INFO(symbol);
        auto dev = device(Form::IQR, std::string(symbol) + "0");
        CHECK(wire.exchange(cpu, block_read_req(0x0002, {}, {{dev, 1}})) == wire.expect(error(0x4030, 0x0406, 0x0002)));
        CHECK(wire.exchange(cpu, block_write_req(0x0002, {}, {{dev, {1}}})) ==
              wire.expect(error(0x4030, 0x1406, 0x0002)));
    }
    for (const char* symbol : {"LTN", "LSTN", "LCN", "LZ"}) {
        INFO(symbol);
        auto dev = device(Form::IQR, std::string(symbol) + "0");
        CHECK(wire.exchange(cpu, block_read_req(0x0002, {{dev, 2}}, {})) == wire.expect(error(0x4030, 0x0406, 0x0002)));
        CHECK(wire.exchange(cpu, block_write_req(0x0002, {{dev, {1, 2}}}, {})) ==
              wire.expect(error(0x4030, 0x1406, 0x0002)));
    }
    // S is read-only over the built-in port.
    CHECK(wire.exchange(cpu, block_write_req(0x0000, {}, {{device(Form::Q, "S0"), {1}}})) ==
          wire.expect(error(0x4030, 0x1406, 0x0000)));
    CHECK((snapshot(cpu) == before));
    // Timer contacts and coils are fine in bit blocks, their values in word blocks.
    CHECK(wire.exchange(cpu, block_read_req(0x0000, {{device(Form::Q, "TN0"), 1}},
                                            {{device(Form::Q, "TS0"), 1}, {device(Form::Q, "TC0"), 1}})) ==
          wire.expect(ok(words({0, 0, 0}))));
}

TEST_CASE("0406/1406: a word device in a bit block or a bit device in a word block -> C05C", "[block][devices]") {
    auto cpu = make_cpu("R08CPU");
    auto wire = GENERATE(kBinary3E, kAscii3E);
    check_refused(cpu, wire, block_read_req(0x0000, {}, {{device(Form::Q, "D0"), 1}}), 0xC05C, 0x0406, 0x0000);
    check_refused(cpu, wire, block_read_req(0x0000, {{device(Form::Q, "M0"), 1}}, {}), 0xC05C, 0x0406, 0x0000);
    check_refused(cpu, wire, block_write_req(0x0000, {{device(Form::Q, "D0"), {1}}, {device(Form::Q, "TS0"), {1}}}, {}),
                  0xC05C, 0x1406, 0x0000);
}

TEST_CASE("0406/1406 range: a block past the end, and nothing written when a later block fails", "[block][range]") {
    auto cpu = make_cpu("R08CPU");
    auto wire = GENERATE(kBinary3E, kAscii3E);
    CHECK(wire.exchange(cpu, block_read_req(0x0000, {{device(Form::Q, "D10238"), 2}}, {})) ==
          wire.expect(ok(words({0, 0}))));
    CHECK(wire.exchange(cpu, block_read_req(0x0000, {{device(Form::Q, "D10238"), 3}}, {})) ==
          wire.expect(error(0x4031, 0x0406, 0x0000)));
    // M has 12288 points: M12272 is the last whole word.
    CHECK(wire.exchange(cpu, block_read_req(0x0000, {}, {{device(Form::Q, "M12272"), 1}})) ==
          wire.expect(ok(words({0}))));
    CHECK(wire.exchange(cpu, block_read_req(0x0000, {}, {{device(Form::Q, "M12273"), 1}})) ==
          wire.expect(error(0x4031, 0x0406, 0x0000)));
    check_refused(cpu, wire,
                  block_write_req(0x0000, {{device(Form::Q, "D0"), {7, 7}}, {device(Form::Q, "D10239"), {1, 2}}}, {}),
                  0x4031, 0x1406, 0x0000);
}
