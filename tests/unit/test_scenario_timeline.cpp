// Timeline steps on a fake clock: values at given times, independent of how
// often the clock is read (docs/scenarios.md "Timeline").
#include <bit>
#include <cmath>

#include "support/scenario_fixtures.hpp"

using namespace slmp;
using namespace slmp::test;

TEST_CASE("timeline: set, increment and copy happen once, at their time", "[scenario][timeline]") {
    ScenarioRig rig(R"({"timeline": {"steps": [
        {"at_ms": 0, "set": {"D100": 7, "M0": 1, "D200": [1, 2, 3]}},
        {"at_ms": 100, "increment": "D100", "by": 5},
        {"after_ms": 50, "increment": "D100", "by": -20},
        {"at_ms": 300, "copy": "D200", "to": "D300", "points": 3}
    ]}})");
    rig.scan(0);
    CHECK(rig["D100"] == 7);
    CHECK(rig["M0"] == 1);
    CHECK(rig["D202"] == 3);
    rig.scan(99);
    CHECK(rig["D100"] == 7);
    rig.scan(100);
    CHECK(rig["D100"] == 12);
    rig.scan(120);
    CHECK(rig["D100"] == 12);   // once only
    rig.scan(150);              // after_ms counts from the previous step's time
    CHECK(rig["D100"] == static_cast<std::uint16_t>(-8));
    CHECK(rig["D301"] == 0);
    rig.scan(1000);
    CHECK(rig["D300"] == 1);
    CHECK(rig["D302"] == 3);
}

TEST_CASE("timeline: a ramp is linear and ends on its target", "[scenario][timeline]") {
    ScenarioRig rig(R"({"timeline": {"steps": [{"at_ms": 1000, "ramp": "D10", "from": 0, "to": 100, "over_ms": 2000}]}})");
    rig.scan(0);
    CHECK(rig["D10"] == 0);
    rig.scan(1500);
    CHECK(rig["D10"] == 25);
    rig.scan(2000);
    CHECK(rig["D10"] == 50);
    set(rig.cpu, "D10", 999);   // a client write in between is overwritten while the ramp runs
    rig.scan(2999);
    CHECK(rig["D10"] == 100);   // 99.95 rounds to 100
    rig.scan(5000);             // the clock jumped past the end: the final value
    CHECK(rig["D10"] == 100);
    set(rig.cpu, "D10", 5);
    rig.scan(6000);
    CHECK(rig["D10"] == 5);     // after the end the ramp leaves the device alone
}

TEST_CASE("timeline: sine and square waves, as int16, int32 and float", "[scenario][timeline]") {
    ScenarioRig rig(R"({"timeline": {"steps": [
        {"sine": "D0", "center": 100, "amplitude": 50, "period_ms": 1000},
        {"square": "M5", "period_ms": 200, "duty": 0.25},
        {"square": "D20", "low": -1, "high": 70000, "period_ms": 100, "as": "int32"},
        {"sine": "D30", "center": 20.5, "amplitude": 1, "period_ms": 400, "as": "float"}
    ]}})");
    auto float_at = [&](const char* a) {
        auto low = value(rig.cpu, a);
        auto high = value(rig.cpu, std::string("D") + std::to_string(std::stoi(a + 1) + 1));
        return std::bit_cast<float>(low | high << 16);
    };
    rig.scan(0);
    CHECK(rig["D0"] == 100);
    CHECK(rig["M5"] == 1);
    CHECK(rig["D20"] == (70000u & 0xFFFF));
    CHECK(rig["D21"] == (70000u >> 16));
    CHECK(float_at("D30") == Approx(20.5));
    rig.scan(240);
    CHECK(rig["M5"] == 1);     // 240 mod 200 = 40: within the first 25 %
    CHECK(rig["D20"] == (70000u & 0xFFFF));
    rig.scan(250);
    CHECK(rig["D0"] == 150);   // a quarter period: the top
    CHECK(rig["M5"] == 0);     // 50 of 200: the duty has ended
    CHECK(rig["D20"] == 0xFFFF);   // low: -1 as a 32-bit value, FFFF FFFF
    CHECK(rig["D21"] == 0xFFFF);
    rig.scan(300);
    CHECK(float_at("D30") == Approx(20.5 - 1));   // 300/400: three quarters
    rig.scan(750);
    CHECK(rig["D0"] == 50);
}

TEST_CASE("timeline: a random walk stays in bounds and does not depend on the scan rate", "[scenario][timeline]") {
    const char* json = R"({"seed": 7, "timeline": {"steps": [
        {"random_walk": "D50", "start": 50, "min": 40, "max": 60, "step": 3, "every_ms": 100}
    ]}})";
    ScenarioRig fine(json), coarse(json), other_seed(R"({"seed": 8, "timeline": {"steps": [
        {"random_walk": "D50", "start": 50, "min": 40, "max": 60, "step": 3, "every_ms": 100}]}})");
    std::vector<std::uint32_t> walk;
    for (int t = 0; t <= 10000; t += 10) {
        fine.scan(t);
        CHECK(fine["D50"] >= 40);
        CHECK(fine["D50"] <= 60);
        if (t % 1000 == 0) walk.push_back(fine["D50"]);
    }
    std::vector<std::uint32_t> coarse_walk, other_walk;
    for (int t = 0; t <= 10000; t += 1000) {
        coarse.scan(t);
        other_seed.scan(t);
        coarse_walk.push_back(coarse["D50"]);
        other_walk.push_back(other_seed["D50"]);
    }
    CHECK(walk == coarse_walk);
    CHECK(walk != other_walk);
    CHECK(walk.front() == 50);
}

TEST_CASE("timeline: loops repeat each pass, a finite loop ends", "[scenario][timeline]") {
    ScenarioRig rig(R"({"timeline": {"loop": 3, "duration_ms": 1000, "steps": [
        {"at_ms": 0, "increment": "D1"},
        {"at_ms": 0, "ramp": "D2", "from": 0, "to": 10, "over_ms": 500}
    ]}})");
    rig.scan_through(0, 990);
    CHECK(rig["D1"] == 1);
    CHECK(rig["D2"] == 10);
    rig.scan(1250);
    CHECK(rig["D1"] == 2);
    CHECK(rig["D2"] == 5);
    rig.scan(5000);             // passes 2 and 3 ran (one jump), then the timeline ended
    CHECK(rig["D1"] == 3);
    rig.scan(8000);
    CHECK(rig["D1"] == 3);
    CHECK(std::count(rig.events.begin(), rig.events.end(), "timeline finished after 3 pass(es)") == 1);
}

TEST_CASE("timeline: an endless loop without duration takes its length from the steps", "[scenario][timeline]") {
    ScenarioRig rig(R"({"timeline": {"loop": true, "steps": [
        {"set": {"M0": 1}}, {"after_ms": 100, "set": {"M0": 0}}, {"after_ms": 100, "increment": "D0"}
    ]}})");
    rig.scan(0);
    CHECK(rig["M0"] == 1);
    rig.scan(100);
    CHECK(rig["M0"] == 0);
    rig.scan(200);   // the pass is 200 ms long: its last step and the next pass's first happen at 200 ms
    CHECK(rig["M0"] == 1);
    CHECK(rig["D0"] == 1);
    rig.scan(2000);
    CHECK(rig["D0"] == 10);
}
