// The built-in profiles (config/profiles/*.json) and "extends". Identities are
// the model-code list of the SLMP Reference Manual §5.6 and real-CPU
// measurements; which ports answer 0101, real-CPU measurements (QnU and L built-in
// ports refuse it with C059).
#include <filesystem>
#include <fstream>

#include "config/builtin_profiles.hpp"
#include "support/fixtures.hpp"

using namespace slmp;
using namespace slmp::test;

namespace {

struct Identity {
    const char* profile;
    const char* type_name;
    std::uint16_t model_code;
    const char* family;
    bool answers_0101;
};

// Every built-in profile: what 0101 answers and the family it belongs to.
const Identity kIdentities[] = {
    {"R00CPU", "R00CPU", 0x48A0, "iQ-R", true},        {"R01CPU", "R01CPU", 0x48A1, "iQ-R", true},
    {"R02CPU", "R02CPU", 0x48A2, "iQ-R", true},        {"R04CPU", "R04CPU", 0x4800, "iQ-R", true},
    {"R08CPU", "R08CPU", 0x4801, "iQ-R", true},        {"R16CPU", "R16CPU", 0x4802, "iQ-R", true},
    {"R32CPU", "R32CPU", 0x4803, "iQ-R", true},        {"R120CPU", "R120CPU", 0x4804, "iQ-R", true},
    {"R08PCPU", "R08PCPU", 0x4841, "iQ-R", true},      {"R16PCPU", "R16PCPU", 0x4842, "iQ-R", true},
    {"R32PCPU", "R32PCPU", 0x4843, "iQ-R", true},      {"R120PCPU", "R120PCPU", 0x4844, "iQ-R", true},
    {"RJ71EN71", "R08CPU", 0x4801, "iQ-R", true},      {"RJ71GN11-T2", "R08CPU", 0x4801, "iQ-R", true},
    {"L16HCPU", "L16HCPU", 0x48C2, "iQ-R", true},
    {"L02CPU", "L02CPU", 0x0541, "L", false},          {"L26CPU-BT", "L26CPU-BT", 0x0542, "L", false},
    {"Q03UDVCPU", "Q03UDVCPU", 0x0366, "QnU", false},  {"Q06UDVCPU", "Q06UDVCPU", 0x0368, "QnU", false},
    {"Q26UDEHCPU", "Q26UDEHCPU", 0x026C, "QnU", false}, {"Q06UDVCPU-QJ71E71", "Q06UDVCPU", 0x0368, "QJ71E71", true},
    {"Q02UCPU", "Q02UCPU", 0x0263, "QJ71E71", true},   {"FX5U-32MR", "FX5U-32MR/DS", 0x4A41, "iQ-F", true},
    {"FX5UC-32MT", "FX5UC-32MT/D", 0x4A91, "iQ-F", true},
};

const Payload kReadTypeName{"01 01 00 00", "01010000"};

Payload type_name_data(const std::string& name, std::uint16_t code) {
    std::string padded = name;
    padded.resize(16, ' ');
    return Payload{hex(text(padded)), padded} + word(code);
}

std::filesystem::path temp_dir() {
    auto dir = std::filesystem::temp_directory_path() / ("slmp-profiles-" + std::to_string(::getpid()));
    std::filesystem::create_directories(dir);
    return dir;
}

void write_file(const std::filesystem::path& file, const std::string& text) { std::ofstream(file) << text; }

}  // namespace

TEST_CASE("every built-in profile is listed here with its identity, and 0101 answers it", "[profiles][type_name]") {
    CHECK(config::builtin_profiles().size() == std::size(kIdentities));
    for (const auto& id : kIdentities) {
        INFO(id.profile);
        auto profile = config::load_profile(id.profile);
        CHECK(profile.cpu.name == id.profile);
        CHECK(profile.cpu.type_name == id.type_name);
        CHECK(profile.cpu.model_code == id.model_code);
        CHECK(config::family_name(profile.cpu.family) == id.family);
        CHECK(!profile.description.empty());
        auto cpu = make_cpu(id.profile);
        for (const auto& wire : {kBinary3E, kAscii3E}) {
            auto expected = id.answers_0101 ? ok(type_name_data(id.type_name, id.model_code)) : error(0xC059, 0x0101, 0x0000);
            CHECK(wire.exchange(cpu, kReadTypeName) == wire.expect(expected));
        }
    }
}

TEST_CASE("a profile that extends another keeps the base's facts and overrides what it names", "[profiles]") {
    auto base = config::load_profile("R08CPU");
    auto derived = config::parse_profile(R"({"name": "R16CPU-big-D", "extends": "R08CPU", "description": "test",
        "type_name": "R16CPU", "model_code": "4802", "device_sizes": {"D": 20480}, "start_only_range_check": ["ZR"]})",
                                         "big.json");
    CHECK(derived.cpu.type_name == "R16CPU");
    CHECK(derived.cpu.model_code == 0x4802);
    // Objects merge key by key: D changes, the other sizes are the base's.
    CHECK(derived.cpu.size(devicemodel::Area::D) == 20480);
    CHECK(derived.cpu.size(devicemodel::Area::M) == base.cpu.size(devicemodel::Area::M));
    CHECK(derived.cpu.size(devicemodel::Area::ZR) == base.cpu.size(devicemodel::Area::ZR));
    // Arrays replace.
    CHECK(derived.cpu.start_only_range_check == std::vector{devicemodel::Area::ZR});
    CHECK(derived.port.batch_words.max == base.port.batch_words.max);
    CHECK(derived.cpu.family == base.cpu.family);
}

TEST_CASE("a profile file may extend a file beside it, chains resolve", "[profiles]") {
    auto dir = temp_dir();
    write_file(dir / "plant-base.json", R"({"name": "PlantBase", "extends": "Q26UDEHCPU", "description": "site base",
        "device_sizes": {"D": 4096}})");
    write_file(dir / "line1.json", R"({"name": "Line1", "extends": "plant-base.json", "description": "line 1",
        "type_name": "Q06UDVCPU", "model_code": "0368"})");
    auto profile = config::load_profile((dir / "line1.json").string());
    CHECK(profile.cpu.name == "Line1");
    CHECK(profile.cpu.type_name == "Q06UDVCPU");
    CHECK(profile.cpu.size(devicemodel::Area::D) == 4096);
    CHECK(profile.cpu.family == devicemodel::Family::QnU);
    std::filesystem::remove_all(dir);
}

TEST_CASE("extends mistakes name the profile and the fix", "[profiles][config]") {
    using Catch::Contains;
    CHECK_THROWS_WITH(config::parse_profile(R"({"name": "X", "description": "x", "extends": "R99CPU"})", "x.json"),
                      Contains("x.json: /extends: unknown base profile 'R99CPU'; extend one of: ") &&
                          Contains("R08CPU"));
    CHECK_THROWS_WITH(config::parse_profile(R"({"extends": "R08CPU", "description": "x"})", "x.json"),
                      Contains("x.json: /: a profile that extends another needs its own \"name\" and \"description\""));
    CHECK_THROWS_WITH(config::parse_profile(R"({"name": "X", "description": "x", "extends": "other.json"})", "x.json"),
                      Contains("x.json: /extends: a built-in profile extends a file ('other.json'); extend a built-in "
                               "profile by name"));
    auto dir = temp_dir();
    write_file(dir / "a.json", R"({"name": "A", "description": "a", "extends": "b.json"})");
    write_file(dir / "b.json", R"({"name": "B", "description": "b", "extends": "a.json"})");
    CHECK_THROWS_WITH(config::load_profile((dir / "a.json").string()),
                      Contains("profiles extend each other in a cycle; break the chain of \"extends\""));
    write_file(dir / "c.json", R"({"name": "C", "description": "c", "extends": "missing.json"})");
    CHECK_THROWS_WITH(config::load_profile((dir / "c.json").string()), Contains("cannot open the base profile"));
    std::filesystem::remove_all(dir);
}

TEST_CASE("the ports' default connection count comes from the profile", "[profiles][connections]") {
    for (const auto& name : config::builtin_profile_names()) {
        INFO(name);
        auto profile = config::load_profile(name);
        unsigned expected = profile.cpu.family == devicemodel::Family::IQF ? 8 : name == "RJ71EN71" ? 56 : 16;
        CHECK(profile.port.max_connections == expected);
    }
    CHECK_THROWS_WITH(config::parse_profile(R"({"extends": "R08CPU", "name": "X", "description": "x", "max_connections": 0})", "p.json"),
                      Catch::Contains("max_connections") && Catch::Contains("must be at least 1"));
    CHECK_THROWS_WITH(config::parse_profile(R"({"extends": "R08CPU", "name": "X", "description": "x", "xy_radix": 10})", "p.json"),
                      Catch::Contains("xy_radix") && Catch::Contains("must be 8 or 16"));
}
