// Snapshots of device memory (devicemodel/snapshot.hpp): round trip, the latch
// rules of a restore, and damaged or foreign files refused whole.
#include "support/fixtures.hpp"

#include "devicemodel/snapshot.hpp"

using namespace slmp;
using namespace slmp::devicemodel;

namespace {

void set(Cpu& cpu, const std::string& address, std::uint32_t value) {
    auto a = parse_address(address);
    cpu.memory().set_value(*a->spec, a->number, value);
}
std::uint32_t get(const Cpu& cpu, const std::string& address) {
    auto a = parse_address(address);
    return cpu.memory().value(*a->spec, a->number);
}

const char* const kDevices[] = {"D0", "D100", "M5", "L7", "ZR163839", "R5", "LTN3", "LTS3", "TC1", "Y2F", "RD9", "LZ1"};

Cpu filled() {
    auto cpu = test::make_cpu();
    std::uint32_t v = 1;
    for (auto* a : kDevices) set(cpu, a, v++ * 3);   // bits become 1
    return cpu;
}

}  // namespace

TEST_CASE("snapshot: round trip of every kind of device", "[snapshot]") {
    auto source = filled();
    auto bytes = encode_snapshot(source.memory(), "R08CPU");
    auto target = test::make_cpu();
    auto result = restore_snapshot(bytes, target.memory(), "R08CPU", LatchMap{}, RestoreScope::All);
    REQUIRE(result.ok);
    CHECK(result.warnings.empty());
    for (auto* a : kDevices) CHECK(get(target, a) == get(source, a));
    CHECK(bytes.size() < 4096);   // zero runs: a mostly empty CPU is small
}

TEST_CASE("snapshot: a latched restore brings back L, R/ZR and the latch ranges only", "[snapshot]") {
    auto source = filled();
    auto bytes = encode_snapshot(source.memory(), "R08CPU");
    auto target = test::make_cpu();
    std::vector<LatchRange> ranges{{Area::D, 100, 1}};
    REQUIRE(restore_snapshot(bytes, target.memory(), "R08CPU", LatchMap(ranges), RestoreScope::Latched).ok);
    CHECK(get(target, "D0") == 0);
    CHECK(get(target, "D100") == get(source, "D100"));
    CHECK(get(target, "L7") == 1);
    CHECK(get(target, "ZR163839") == get(source, "ZR163839"));
    CHECK(get(target, "R5") == get(source, "R5"));
    CHECK(get(target, "M5") == 0);
}

TEST_CASE("snapshot: damage anywhere is refused and nothing is restored", "[snapshot]") {
    auto source = filled();
    auto bytes = encode_snapshot(source.memory(), "R08CPU");
    auto target = test::make_cpu();
    auto before = test::snapshot(target);
    SECTION("every truncation") {
        for (std::size_t n = 0; n < bytes.size(); n += 7) {
            auto r = restore_snapshot(std::span(bytes).first(n), target.memory(), "R08CPU", LatchMap{}, RestoreScope::All);
            CHECK_FALSE(r.ok);
        }
    }
    SECTION("a flipped byte") {
        bytes[bytes.size() / 2] ^= 0x40;
        CHECK_FALSE(restore_snapshot(bytes, target.memory(), "R08CPU", LatchMap{}, RestoreScope::All).ok);
    }
    SECTION("another profile") {
        auto r = restore_snapshot(bytes, target.memory(), "Q26UDEHCPU", LatchMap{}, RestoreScope::All);
        CHECK_FALSE(r.ok);
        CHECK_THAT(r.error, Catch::Contains("R08CPU"));
    }
    CHECK(test::snapshot(target) == before);
}

TEST_CASE("snapshot: a changed device size restores the common part with a warning", "[snapshot]") {
    auto source = filled();
    auto bytes = encode_snapshot(source.memory(), "R08CPU");
    auto profile = config::load_profile("R08CPU").cpu;
    profile.sizes[static_cast<std::size_t>(Area::D)] = 50;
    Cpu target(profile);
    auto r = restore_snapshot(bytes, target.memory(), "R08CPU", LatchMap{}, RestoreScope::All);
    REQUIRE(r.ok);
    REQUIRE(r.warnings.size() == 1);
    CHECK_THAT(r.warnings[0], Catch::Contains("D was saved with 10240 points"));
    CHECK(get(target, "D0") == get(source, "D0"));
}
