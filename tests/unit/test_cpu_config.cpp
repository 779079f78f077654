// The "cpu" configuration keys and the persistence keys (docs/cpu-runtime.md):
// values reach the runtime, and every mistake names the key and the fix.
#include "support/fixtures.hpp"

using namespace slmp;
using namespace slmp::devicemodel;
using namespace std::chrono_literals;

namespace {

config::ServerConfig parse(const std::string& json) { return config::parse_server_config(json, "test.json"); }

RuntimeConfig checked(const std::string& json, const std::string& profile = "R08CPU") {
    return config::checked_runtime_config(parse(json).cpu, config::load_profile(profile).cpu);
}

}  // namespace

TEST_CASE("cpu keys reach the runtime configuration", "[config][runtime]") {
    auto r = checked(R"({"cpu": {"switch": "stop", "scan_time_ms": 20, "remote_reset": true, "output_off_at_stop": false,
        "password": "abcdef", "password_lockout": {"attempts": 3, "seconds": 5},
        "latch": {"D": [0, 99], "W": [["W10", "W1F"]]},
        "timers": [{"device": "T0", "points": 4, "preset": 20}, {"device": "ST2", "preset": 5, "base_ms": 10},
                   {"device": "LT0", "preset": 70000}],
        "counters": [{"device": "C3", "preset": 7}, {"device": "LC0", "preset": 100000}],
        "error": {"code": "1900"}}})");
    CHECK(r.run_switch == RunSwitch::Stop);
    CHECK(r.scan_time == 20ms);
    CHECK(r.remote_reset_enabled);
    CHECK_FALSE(r.output_off_at_stop);
    CHECK(r.password == "abcdef");
    CHECK(r.lockout_attempts == 3);
    CHECK(r.lockout_period == 5s);
    REQUIRE(r.latch.size() == 2);
    CHECK((r.latch[1].area == Area::W && r.latch[1].first == 0x10 && r.latch[1].count == 16));
    REQUIRE(r.timers.size() == 3);
    CHECK((r.timers[0].area == Area::T && r.timers[0].count == 4 && r.timers[0].base == 100ms));
    CHECK((r.timers[1].area == Area::ST && r.timers[1].first == 2 && r.timers[1].base == 10ms));
    CHECK(r.timers[2].base == 1us);
    REQUIRE(r.counters.size() == 2);
    CHECK((r.counters[1].area == Area::LC && r.counters[1].preset == 100000));
    REQUIRE(r.error);
    CHECK((r.error->code == 0x1900 && !r.error->stop));
}

TEST_CASE("persistence keys", "[config][persistence]") {
    auto c = parse(R"({"state_dir": "/tmp/x", "snapshot_interval_s": 0.5, "restore": "all"})");
    CHECK(c.persistence.state_dir == "/tmp/x");
    CHECK(c.persistence.snapshot_interval_s == 0.5);
    CHECK(c.persistence.restore_all);
    CHECK_FALSE(parse("{}").persistence.restore_all);
}

TEST_CASE("cpu configuration errors name the key and the fix", "[config][runtime]") {
    auto fails = [](const std::string& json, const std::string& needle, const std::string& profile = "R08CPU") {
        INFO(json);
        try {
            checked(json, profile);
            FAIL("accepted");
        } catch (const config::ConfigError& e) {
            CHECK_THAT(std::string(e.what()), Catch::Contains(needle));
        }
    };
    fails(R"({"cpu": {"switch": "ON"}})", "/cpu/switch: unknown switch position 'ON'; use RUN or STOP");
    fails(R"({"cpu": {"scan_time_ms": 0}})", "/cpu/scan_time_ms");
    fails(R"({"cpu": {"swtich": "RUN"}})", "swtich");
    fails(R"({"cpu": {"timers": [{"device": "D0", "preset": 1}]}})", "not a timer");
    fails(R"({"cpu": {"timers": [{"device": "T0", "preset": 40000}]}})", "/cpu/timers/0/preset");
    fails(R"({"cpu": {"timers": [{"device": "T1020", "points": 10, "preset": 1}]}})",
          "/cpu/timers/0: T1020 with 10 point(s) runs past the T size of 1024");
    fails(R"({"cpu": {"counters": [{"device": "T0", "preset": 1}]}})", "not a counter");
    fails(R"({"cpu": {"latch": {"Q": [0, 1]}}})", "unknown device area 'Q'");
    fails(R"({"cpu": {"latch": {"D": [9, 1]}}})", "last is before first");
    fails(R"({"cpu": {"password": "abc"}})", "use 6 to 32 characters");
    fails(R"({"cpu": {"password": "abcdef"}})", "use exactly 4 characters", "Q26UDEHCPU");
    fails(R"({"cpu": {"password": "abc def"}})", "printable ASCII");
    CHECK_THROWS_WITH(parse(R"({"restore": "some"})"), Catch::Contains("use \"latched\" or \"all\""));
    CHECK_THROWS_WITH(parse(R"({"clock_speed": 5000})"), Catch::Contains("/clock_speed: out of range; use a factor from 0.01 to 1000"));
    CHECK(parse(R"({"clock_speed": 12.5})").clock_speed == 12.5);
}
