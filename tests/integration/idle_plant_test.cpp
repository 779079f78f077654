// Idle costs nothing (docs/timing.md, "What wakes a station"): in a plant of
// 200 stations the idle ones never wake, a station whose timer runs wakes
// once, when its contact turns on, and only a station with a running scenario
// wakes every scan. Wake-ups are counted by each station's scan loop
// (GET /api/stations: "wakeups"), never timed.
#include <catch2/catch.hpp>

#include <chrono>
#include <thread>

#include "http_client.hpp"
#include "sim_process.hpp"

using namespace slmp::test;

namespace {

nlohmann::json stations(const SimProcess& sim) {
    auto reply = http_get(sim.http_port(), "/api/stations");
    REQUIRE(reply.status == 200);
    return reply.json();
}

std::uint64_t word(const SimProcess& sim, const std::string& station, const std::string& address) {
    auto reply = http_get(sim.http_port(), "/api/stations/" + station + "/devices/" + address + "?as=words");
    REQUIRE(reply.status == 200);
    return reply.json()["values"][0].get<std::uint64_t>();
}

}  // namespace

TEST_CASE("idle plant: 180 idle stations never wake, 10 timers wake once, 10 scenarios every scan", "[plant][idle]") {
    SimOptions options;
    options.plant = true;
    // The clock runs 10× fast: the timers' 1.5 s of CPU time pass in 150 ms.
    options.args = {"--threads", "2", "--clock-speed", "10"};
    options.config_json = R"({"bind": "127.0.0.1", "http": {"port": 0},
        "stations": [
          {"template": {"profile": "R08CPU"}, "count": 180, "name": "idle-{i}", "tcp_port": 0},
          {"template": {"profile": "R08CPU", "devices": {"TC0": 1},
                        "cpu": {"timers": [{"device": "T0", "preset": 15, "base_ms": 100}]}},
           "count": 10, "name": "timer-{i}", "tcp_port": 0},
          {"template": {"profile": "R08CPU"}, "count": 10, "name": "scenario-{i}", "tcp_port": 0}]})";
    SimProcess sim(options);
    auto started = http(sim.http_port(), "POST", "/api/plant/scenarios",
                        R"({"stations": "scenario-*", "scenario": {"name": "ramp",
                            "timeline": {"steps": [{"at_ms": 0, "ramp": "D0", "from": 0, "to": 1000, "over_ms": 100000}]}}})");
    REQUIRE(started.status == 201);

    // Until every timer is done (a read brings a station up to date, so this
    // waits on the clock, not on wake-ups).
    const auto give_up = std::chrono::steady_clock::now() + std::chrono::seconds(30);
    for (int i = 1; i <= 10; ++i) {
        const auto name = "timer-" + std::to_string(i);
        while (word(sim, name, "TS0") != 1) {
            REQUIRE(std::chrono::steady_clock::now() < give_up);
            std::this_thread::sleep_for(std::chrono::milliseconds(20));
        }
        CHECK(word(sim, name, "TN0") == 15);
    }
    // Each scenario station has scanned many times by now (its ramp moved).
    for (int i = 1; i <= 10; ++i)
        while (word(sim, "scenario-" + std::to_string(i), "D0") == 0) {
            REQUIRE(std::chrono::steady_clock::now() < give_up);
            std::this_thread::sleep_for(std::chrono::milliseconds(20));
        }

    const auto list = stations(sim);
    REQUIRE(list.size() == 200);
    std::size_t idle = 0, timers = 0, scenarios = 0;
    for (const auto& s : list) {
        const auto name = s["name"].get<std::string>();
        const auto wakeups = s["wakeups"].get<std::uint64_t>();
        const auto scans = s["scans"].get<std::uint64_t>();
        INFO(name << ": " << wakeups << " wake-up(s), " << scans << " scan(s)");
        CHECK(scans > 1);   // every clock moved: reads see the scans due
        if (name.starts_with("idle-")) {
            CHECK(wakeups == 0);
            ++idle;
        } else if (name.starts_with("timer-")) {
            CHECK(wakeups <= 1);   // the scan that turns TS0 on (a read may have run it first)
            ++timers;
        } else {
            CHECK(wakeups >= 1);   // a scenario acts at every scan
            CHECK(wakeups <= scans);
            ++scenarios;
        }
    }
    CHECK(idle == 180);
    CHECK(timers == 10);
    CHECK(scenarios == 10);

    // The scenarios stop: those stations sleep again (at most the scan already due).
    REQUIRE(http(sim.http_port(), "DELETE", "/api/plant/scenarios/ramp").status == 200);
    std::map<std::string, std::uint64_t> before;
    for (const auto& s : stations(sim)) before[s["name"].get<std::string>()] = s["wakeups"].get<std::uint64_t>();
    std::this_thread::sleep_for(std::chrono::milliseconds(300));
    for (const auto& s : stations(sim)) {
        const auto name = s["name"].get<std::string>();
        INFO(name);
        CHECK(s["wakeups"].get<std::uint64_t>() <= before[name] + 1);
    }
}
