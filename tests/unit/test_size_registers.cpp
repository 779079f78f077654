// Special registers that publish device sizes (real-CPU measurements):
// clients build their address catalogues from them, so they must match the
// sizes the CPU really enforces.
#include "support/fixtures.hpp"

using namespace slmp;
using namespace slmp::test;
using devicemodel::Area;

namespace {

struct Reg {
    const char* device;
    std::uint16_t sd;
    unsigned bits;
};

// §6, copied from the spec.
const std::vector<Reg> kIqrRegisters = {
    {"X", 260, 32},  {"Y", 262, 32},  {"M", 264, 32},  {"B", 266, 32},   {"SB", 268, 32}, {"F", 270, 32},
    {"V", 272, 32},  {"L", 274, 32},  {"S", 276, 32},  {"D", 280, 32},   {"W", 282, 32},  {"SW", 284, 32},
    {"T", 288, 32},  {"ST", 290, 32}, {"C", 292, 32},  {"LT", 294, 32},  {"LST", 296, 32}, {"LC", 298, 32},
    {"Z", 300, 16},  {"LZ", 302, 16}, {"ZR", 306, 32}, {"RD", 308, 32},
};
const std::vector<Reg> kQnuRegisters = {
    {"M", 286, 32}, {"B", 288, 32}, {"X", 290, 16},  {"Y", 291, 16},  {"L", 293, 16},  {"F", 295, 16},
    {"SB", 296, 16}, {"V", 297, 16}, {"S", 298, 16}, {"T", 299, 16}, {"ST", 300, 16}, {"C", 301, 16},
    {"SW", 304, 16}, {"D", 308, 32}, {"W", 310, 32},
};

std::vector<Reg> registers_of(const devicemodel::CpuProfile& profile) {
    std::vector<Reg> out;
    for (const auto& r : profile.size_registers)
        out.push_back({devicemodel::area_name(r.area).data(), r.sd, r.bits});
    return out;
}

bool same(const std::vector<Reg>& a, const std::vector<Reg>& b) {
    if (a.size() != b.size()) return false;
    for (std::size_t i = 0; i < a.size(); ++i)
        if (std::string(a[i].device) != b[i].device || a[i].sd != b[i].sd || a[i].bits != b[i].bits) return false;
    return true;
}

Payload sd_words(std::uint32_t value, unsigned bits) {
    return bits == 32 ? words({static_cast<std::uint16_t>(value), static_cast<std::uint16_t>(value >> 16)})
                      : words({static_cast<std::uint16_t>(value)});
}

}  // namespace

TEST_CASE("size registers are laid out as the spec lists them", "[size_registers]") {
    SECTION("iQ-R and iQ-F: SD260 onward") {
        for (const char* name : {"R08CPU", "R120PCPU", "FX5U-32MR"}) {
            INFO(name);
            CHECK(same(registers_of(make_cpu(name).profile()), kIqrRegisters));
        }
    }
    SECTION("QnU and L") {
        for (const char* name : {"Q26UDEHCPU", "L26CPU-BT", "Q06UDVCPU-QJ71E71"}) {
            INFO(name);
            CHECK(same(registers_of(make_cpu(name).profile()), kQnuRegisters));
        }
    }
}

TEST_CASE("size registers read over SLMP match the profile sizes", "[size_registers]") {
    auto name = GENERATE(as<std::string>{}, "R08CPU", "R120PCPU", "Q26UDEHCPU", "Q06UDVCPU-QJ71E71", "L26CPU-BT",
                         "FX5U-32MR");
    auto cpu = make_cpu(name);
    auto wire = GENERATE(kBinary3E, kAscii3E);
    for (const auto& reg : cpu.profile().size_registers) {
        auto points = cpu.profile().size(reg.area);
        INFO(name << " SD" << reg.sd << " (" << devicemodel::area_name(reg.area) << " = " << points << ")");
        CHECK(wire.exchange(cpu, read_words_req(Form::Q, "SD" + std::to_string(reg.sd), reg.bits / 16)) ==
              wire.expect(ok(sd_words(points, reg.bits))));
    }
}

TEST_CASE("R08CPU publishes the sizes observed on a real R08CPU", "[size_registers][spec]") {
    auto cpu = make_cpu("R08CPU");
    auto wire = GENERATE(kBinary3E, kBinary4E, kAscii3E, kAscii4E);
    struct Case {
        const char* sd;
        std::uint32_t points;
        unsigned bits;
    };
    const Case cases[] = {
        {"SD260", 12288, 32}, {"SD262", 12288, 32}, {"SD264", 12288, 32}, {"SD266", 8192, 32},  {"SD268", 2048, 32},
        {"SD270", 2048, 32},  {"SD272", 2048, 32},  {"SD274", 8192, 32},  {"SD276", 1024, 32},  {"SD280", 10240, 32},
        {"SD282", 8192, 32},  {"SD284", 2048, 32},  {"SD288", 1024, 32},  {"SD290", 1024, 32},  {"SD292", 512, 32},
        {"SD294", 1024, 32},  {"SD296", 1024, 32},  {"SD298", 512, 32},   {"SD300", 20, 16},    {"SD302", 2, 16},
        {"SD306", 163840, 32}, {"SD308", 524288, 32},
    };
    for (const auto& c : cases) {
        INFO(c.sd << " = " << c.points);
        CHECK(wire.exchange(cpu, read_words_req(Form::IQR, c.sd, c.bits / 16)) ==
              wire.expect(ok(sd_words(c.points, c.bits))));
    }
    SECTION("ZR 163840 = 0002 8000: low word first") {
        CHECK(wire.exchange(cpu, read_words_req(Form::Q, "SD306", 2)) == wire.expect(ok(words({0x8000, 0x0002}))));
    }
}

TEST_CASE("size registers follow a configured size", "[size_registers]") {
    auto profile = config::load_profile("R08CPU").cpu;
    profile.sizes[static_cast<std::size_t>(Area::D)] = 20000;
    profile.sizes[static_cast<std::size_t>(Area::ZR)] = 70000;
    devicemodel::Cpu cpu(profile);
    auto wire = GENERATE(kBinary3E, kAscii3E);
    CHECK(wire.exchange(cpu, read_words_req(Form::Q, "SD280", 2)) == wire.expect(ok(words({20000, 0}))));
    CHECK(wire.exchange(cpu, read_words_req(Form::Q, "SD306", 2)) == wire.expect(ok(words({0x1170, 0x0001}))));
    CHECK(wire.exchange(cpu, read_words_req(Form::Q, "D19999", 1)) == wire.expect(ok(words({0}))));
    CHECK(wire.exchange(cpu, read_words_req(Form::Q, "D20000", 1)) == wire.expect(error(0x4031, 0x0401, 0x0000)));
}

TEST_CASE("SM and SD sizes per family (hardware-behaviour §6)", "[size_registers]") {   // signposts: allow (the name ctest lists)
    struct Case {
        const char* profile;
        std::uint32_t sm, sd;
        std::uint16_t out_of_range;
    };
    const Case cases[] = {
        {"R08CPU", 4096, 4096, 0x4031},          {"R120PCPU", 4096, 4096, 0x4031},
        {"Q26UDEHCPU", 2048, 2048, 0xC056},      {"L26CPU-BT", 2048, 2048, 0xC056},
        {"Q06UDVCPU-QJ71E71", 2048, 2048, 0xC056}, {"FX5U-32MR", 10000, 12000, 0xC056},
    };
    auto wire = GENERATE(kBinary3E, kAscii3E);
    for (const auto& c : cases) {
        INFO(c.profile);
        auto cpu = make_cpu(c.profile);
        CHECK(cpu.profile().size(Area::SM) == c.sm);
        CHECK(cpu.profile().size(Area::SD) == c.sd);
        auto sd_last = "SD" + std::to_string(c.sd - 1), sd_end = "SD" + std::to_string(c.sd);
        auto sm_last = "SM" + std::to_string(c.sm - 1), sm_end = "SM" + std::to_string(c.sm);
        CHECK(wire.exchange(cpu, read_words_req(Form::Q, sd_last, 1)) == wire.expect(ok(words({0}))));
        CHECK(wire.exchange(cpu, read_words_req(Form::Q, sd_end, 1)) == wire.expect(error(c.out_of_range, 0x0401, 0)));
        CHECK(wire.exchange(cpu, read_bits_req(Form::Q, sm_last, 1)) == wire.expect(ok(bits({0}))));
        CHECK(wire.exchange(cpu, read_bits_req(Form::Q, sm_end, 1)) == wire.expect(error(c.out_of_range, 0x0401, 1)));
    }
}
