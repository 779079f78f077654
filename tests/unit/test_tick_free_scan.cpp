// The tick-free scan loop against the ticking one (docs/timing.md, "What
// wakes a station"): two stations with the same CPU, one scanning at every
// instant (always_scan), one that catches up only when it is read or written,
// on a fake host clock; their whole device memory (SM/SD included), scan
// counts and END times must agree at every sampled instant, at several clock
// speeds, across writes that start timers and counters, state changes,
// frozen-clock steps and speed changes.
#include "support/fixtures.hpp"

#include <random>

#include "devicemodel/runtime.hpp"
#include "devicemodel/snapshot.hpp"
#include "station/scan_loop.hpp"

using namespace slmp;
using namespace slmp::devicemodel;
using namespace std::chrono_literals;
using std::chrono::steady_clock;

namespace {

steady_clock::time_point fake_host_now = steady_clock::time_point{} + 1000h;
steady_clock::time_point fake_now() { return fake_host_now; }

RuntimeConfig timers_and_counters(const std::string& profile) {
    RuntimeConfig c;
    c.scan_time = 10ms;
    c.timers.push_back({Area::T, 0, 4, 20, 100ms});     // 2 s on a 100 ms base
    c.timers.push_back({Area::T, 4, 4, 35, 10ms});      // 350 ms on a 10 ms base
    c.timers.push_back({Area::ST, 0, 4, 7, 100ms});     // retentive
    if (profile != "Q03UDVCPU") c.timers.push_back({Area::LT, 0, 2, 1'234'567, 1us});   // iQ-R long timer, 1 us units
    c.counters.push_back({Area::C, 0, 4, 3});
    return c;
}

// One CPU and its scan loop on the fake host clock.
struct Side {
    Side(boost::asio::io_context& io, const std::string& profile, double speed, bool ticking)
        : cpu(test::make_cpu(profile)),
          loop(boost::asio::make_strand(io), {&cpu}, 10ms, speed, false, &fake_now) {
        cpu.runtime().configure(timers_and_counters(profile), cpu.memory());
        loop.always_scan(ticking);
    }
    void set(const std::string& address, std::uint32_t value) {
        loop.catch_up();   // as every request's serve path does first
        auto a = parse_address(address);
        cpu.memory().set_value(*a->spec, a->number, value);
        loop.touched();
    }
    std::vector<std::uint8_t> image() {
        loop.catch_up();
        return encode_snapshot(cpu.memory(), cpu.profile().name, SnapshotContents::WithSystem);
    }

    Cpu cpu;
    station::ScanLoop loop;
};

// Moves the host clock in steps shorter than a scan (with jitter), the ticking
// side woken at every step as its timer would be.
struct Twins {
    Twins(const std::string& profile, double speed, std::uint32_t seed)
        : ticking(io, profile, speed, true), idle(io, profile, speed, false), rng(seed) {
        const auto calendar = std::chrono::system_clock::from_time_t(1'700'000'000);
        for (auto* side : {&ticking, &idle}) {
            side->loop.set_calendar(calendar);
            side->loop.begin();
        }
    }
    void run_for(steady_clock::duration real) {
        const auto end = fake_host_now + real;
        std::uniform_int_distribution<std::int64_t> step_us(1, 4000);
        while (fake_host_now < end) {
            fake_host_now = std::min(end, fake_host_now + std::chrono::microseconds(step_us(rng)));
            ticking.loop.catch_up();
        }
    }
    void set(const std::string& address, std::uint32_t value) {
        ticking.set(address, value);
        idle.set(address, value);
    }
    void check(const std::string& when) {
        INFO(when);
        const auto ticking_image = ticking.image();
        const auto idle_image = idle.image();
        CHECK(ticking.loop.scans() == idle.loop.scans());
        CHECK(ticking.loop.last_end() == idle.loop.last_end());
        for (std::uint64_t back = 0; back < 5; ++back)
            CHECK(ticking.loop.end_time(ticking.loop.scans() - back) == idle.loop.end_time(idle.loop.scans() - back));
        REQUIRE(ticking_image == idle_image);
    }
    std::uint32_t get(const std::string& address) {
        auto a = parse_address(address);
        return idle.cpu.memory().value(*a->spec, a->number);
    }

    boost::asio::io_context io;
    Side ticking, idle;
    std::mt19937 rng;
};

}  // namespace

TEST_CASE("tick-free scans equal ticking ones at many instants, at several clock speeds", "[station][clock][idle]") {
    const auto profile = GENERATE(std::string("R08CPU"), std::string("Q03UDVCPU"));
    const auto speed = GENERATE(1.0, 2.5, 0.25, 7.0);
    INFO(profile << " at speed " << speed);
    Twins twins(profile, speed, 7);
    std::mt19937 rng(11);
    std::uniform_int_distribution<std::int64_t> gap_ms(1, 900);
    auto sample = [&](int n) {
        for (int i = 0; i < n; ++i) {
            twins.run_for(std::chrono::milliseconds(gap_ms(rng)));
            twins.check("sample " + std::to_string(i));
        }
    };
    sample(5);                       // clocks, calendar, scan times of an idle CPU
    twins.set("TC0", 1);             // a 2 s timer starts
    twins.set("TC5", 1);             // a 350 ms one
    twins.set("STC1", 1);            // a retentive one
    if (profile == "R08CPU") twins.set("LTC0", 1);
    sample(8);
    if (speed >= 1) CHECK(twins.get("TS0") == 1);   // the samples ran past its preset (2 s of CPU time)
    twins.set("STC1", 0);            // retentive: keeps its value
    twins.set("TC5", 0);             // resets
    twins.set("TN0", 3);             // a client rewinds a done timer (RST-like): it times again
    twins.set("CC0", 1);             // a rising edge counts
    twins.run_for(35ms);
    twins.set("CC0", 0);
    twins.run_for(3ms);              // no scan between these two writes at some speeds: no edge seen
    twins.set("CC0", 1);
    twins.set("CC0", 0);
    twins.set("SD414", 3);           // SM414's period follows SD414
    twins.set("SD415", 7);
    sample(6);

    SECTION("through STOP, RUN and a restart") {
        for (auto* side : {&twins.ticking, &twins.idle}) {
            side->loop.catch_up();
            side->cpu.runtime().remote_stop(side->cpu.memory(), 1);
            side->loop.touched();
        }
        sample(3);
        for (auto* side : {&twins.ticking, &twins.idle}) {
            side->loop.catch_up();
            side->cpu.runtime().remote_run(side->cpu.memory(), 1, false, ClearMode::None);
            side->loop.touched();
        }
        twins.set("TC1", 1);
        sample(4);
        for (auto* side : {&twins.ticking, &twins.idle}) {
            side->loop.catch_up();
            side->cpu.runtime().restart(side->cpu.memory());
            side->loop.touched();
        }
        sample(4);
    }
    SECTION("through frozen-clock steps and a change of speed") {
        for (auto* side : {&twins.ticking, &twins.idle}) side->loop.freeze_clock();
        twins.check("frozen");
        for (auto* side : {&twins.ticking, &twins.idle}) {
            side->loop.step_scans(3);
            side->loop.step_time(std::chrono::microseconds(45'500));
        }
        twins.run_for(2s);   // frozen: real time moves nothing
        twins.check("stepped");
        twins.set("TC2", 1);
        for (auto* side : {&twins.ticking, &twins.idle}) side->loop.step_time(1234ms);
        twins.check("stepped past a timer");
        for (auto* side : {&twins.ticking, &twins.idle}) side->loop.run_clock(speed * 3);
        sample(6);
    }
}

TEST_CASE("a sleeping station's next wake is the scan at which a timer's contact turns on", "[runtime][timers][idle]") {
    auto cpu = test::make_cpu("R08CPU");
    RuntimeConfig c;
    c.timers.push_back({Area::T, 0, 2, 20, 100ms});
    c.counters.push_back({Area::C, 0, 1, 2});
    cpu.runtime().configure(c, cpu.memory());
    auto& rt = cpu.runtime();
    auto& memory = cpu.memory();
    const CalendarTime calendar{2024, 5, 17, 13, 45, 30, 5};
    Runtime::TimePoint now{};
    auto scan = [&] {
        now += 30ms;
        rt.scan(memory, now, calendar);
    };
    auto bit = [&](const std::string& address) {
        auto a = parse_address(address);
        return memory.bit(*a->spec, a->number);
    };
    auto set = [&](const std::string& address, bool on) {
        auto a = parse_address(address);
        memory.set_bit(*a->spec, a->number, on);
    };
    scan();
    CHECK_FALSE(rt.scans_until_due(memory, 30ms));   // nothing runs: never
    set("TC0", true);
    CHECK(rt.scans_until_due(memory, 30ms) == 1u);   // the next scan starts it
    scan();
    // 2 s of 30 ms scans: the 67th scan from here reaches 2.01 s.
    const auto due = rt.scans_until_due(memory, 30ms);
    REQUIRE(due == 67u);
    rt.scan_repeated(memory, now + 66 * 30ms, calendar, 30ms, 66);
    now += 66 * 30ms;
    CHECK_FALSE(bit("TS0"));
    CHECK(rt.scans_until_due(memory, 30ms) == 1u);
    scan();
    CHECK(bit("TS0"));
    CHECK_FALSE(rt.scans_until_due(memory, 30ms));   // done: only its remainder moves
    set("CC0", true);                                // a counter's edge is due at once
    CHECK(rt.scans_until_due(memory, 30ms) == 1u);
    scan();
    CHECK_FALSE(rt.scans_until_due(memory, 30ms));
    rt.remote_stop(memory, 1);
    set("TC1", true);
    CHECK_FALSE(rt.scans_until_due(memory, 30ms));   // STOP: nothing times
}
