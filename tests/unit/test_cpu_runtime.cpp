// The running CPU driven by a fake clock: timers, counters, the special relays
// and registers, state changes, device clears and the latch rules. No sleeping:
// every scan gets an explicit time.
#include "support/fixtures.hpp"

#include "devicemodel/runtime.hpp"

using namespace slmp;
using namespace slmp::devicemodel;
using namespace std::chrono_literals;

namespace {

// A CPU with its runtime configured, and a clock the test moves.
struct Rig {
    explicit Rig(RuntimeConfig config = {}, const std::string& profile = "R08CPU") : cpu(test::make_cpu(profile)) {
        cpu.runtime().configure(std::move(config), cpu.memory());
    }
    void scan(std::chrono::microseconds step = 10ms) {
        now += step;
        cpu.runtime().scan(cpu.memory(), now, calendar);
    }
    void scans(int n, std::chrono::microseconds step) {
        for (int i = 0; i < n; ++i) scan(step);
    }
    std::uint32_t get(const std::string& address) {
        auto a = parse_address(address);
        return cpu.memory().value(*a->spec, a->number);
    }
    void set(const std::string& address, std::uint32_t value) {
        auto a = parse_address(address);
        cpu.memory().set_value(*a->spec, a->number, value);
    }
    Runtime& rt() { return cpu.runtime(); }
    DeviceMemory& mem() { return cpu.memory(); }

    Cpu cpu;
    Runtime::TimePoint now{};
    CalendarTime calendar{2024, 5, 17, 13, 45, 30, 5};
};

RuntimeConfig with_timer(Area area, std::uint32_t preset, std::chrono::microseconds base, std::uint32_t first = 0) {
    RuntimeConfig c;
    c.timers.push_back({area, first, 2, preset, base});
    return c;
}

}  // namespace

TEST_CASE("timer: K20 on a 100 ms base sets its contact after 20 ticks", "[runtime][timers]") {
    Rig rig(with_timer(Area::T, 20, 100ms));
    rig.scan(100ms);
    rig.set("TC0", 1);
    rig.scan(100ms);   // this scan sees the coil on: timing starts at 0
    CHECK(rig.get("TN0") == 0);
    rig.scans(19, 100ms);
    CHECK(rig.get("TN0") == 19);
    CHECK(rig.get("TS0") == 0);
    rig.scan(100ms);
    CHECK(rig.get("TN0") == 20);
    CHECK(rig.get("TS0") == 1);
    rig.scans(5, 100ms);
    CHECK(rig.get("TN0") == 20);   // the current value stops at the preset
    CHECK(rig.get("TN1") == 0);    // its neighbour's coil is off
    SECTION("coil off resets a non-retentive timer") {
        rig.set("TC0", 0);
        rig.scan();
        CHECK(rig.get("TN0") == 0);
        CHECK(rig.get("TS0") == 0);
    }
}

TEST_CASE("timer: the remainder is carried across scans (10 ms scan, 100 ms base)", "[runtime][timers]") {
    Rig rig(with_timer(Area::T, 5, 100ms));
    rig.set("TC0", 1);
    rig.scan(10ms);
    rig.scans(49, 10ms);
    CHECK(rig.get("TN0") == 4);
    CHECK(rig.get("TS0") == 0);
    rig.scan(10ms);
    CHECK(rig.get("TN0") == 5);
    CHECK(rig.get("TS0") == 1);
}

TEST_CASE("timer kinds: 10 ms and 1 ms bases, retentive ST, long LT in 1 us units", "[runtime][timers]") {
    SECTION("10 ms base, K3") {
        Rig rig(with_timer(Area::T, 3, 10ms));
        rig.set("TC0", 1);
        rig.scans(3, 10ms);
        CHECK(rig.get("TS0") == 0);
        rig.scan(10ms);
        CHECK(rig.get("TS0") == 1);
    }
    SECTION("1 ms base counts 10 per 10 ms scan") {
        Rig rig(with_timer(Area::T, 100, 1ms));
        rig.set("TC0", 1);
        rig.scans(5, 10ms);
        CHECK(rig.get("TN0") == 40);
    }
    SECTION("ST keeps its value while the coil is off") {
        Rig rig(with_timer(Area::ST, 10, 100ms));
        rig.set("STC0", 1);
        rig.scans(5, 100ms);
        CHECK(rig.get("STN0") == 4);
        rig.set("STC0", 0);
        rig.scans(3, 100ms);
        CHECK(rig.get("STN0") == 4);
        rig.set("STC0", 1);
        rig.scans(7, 100ms);   // restart scan + 6 more
        CHECK(rig.get("STN0") == 10);
        CHECK(rig.get("STS0") == 1);
    }
    SECTION("LT with the default 1 us base: 70000 us preset after 70 ms") {
        Rig rig(with_timer(Area::LT, 70000, 1us));
        rig.set("LTC0", 1);
        rig.scans(7, 10ms);
        CHECK(rig.get("LTN0") == 60000);
        rig.scan(10ms);
        CHECK(rig.get("LTN0") == 70000);
        CHECK(rig.get("LTS0") == 1);
    }
}

TEST_CASE("counters count rising edges of the coil up to the preset", "[runtime][counters]") {
    RuntimeConfig c;
    c.counters.push_back({Area::C, 0, 1, 3});
    c.counters.push_back({Area::LC, 0, 1, 100000});
    Rig rig(c);
    for (int i = 0; i < 3; ++i) {
        rig.set("CC0", 1);
        rig.scan();
        rig.scan();   // still on: no second count
        rig.set("CC0", 0);
        rig.scan();
    }
    CHECK(rig.get("CN0") == 3);
    CHECK(rig.get("CS0") == 1);
    rig.set("CC0", 1);
    rig.scan();
    CHECK(rig.get("CN0") == 3);   // stops at the preset
    rig.set("LCN0", 99999);
    rig.set("LCC0", 1);
    rig.scan();
    CHECK(rig.get("LCN0") == 100000);
    CHECK(rig.get("LCS0") == 1);
}

TEST_CASE("nothing times in STOP or PAUSE, and time spent there does not count", "[runtime][timers]") {
    Rig rig(with_timer(Area::T, 100, 100ms));
    rig.set("TC0", 1);
    rig.scans(6, 100ms);
    CHECK(rig.get("TN0") == 5);
    rig.rt().remote_pause(rig.mem(), 1, false);
    rig.scans(10, 100ms);
    CHECK(rig.get("TN0") == 5);
    rig.rt().remote_stop(rig.mem(), 1);
    rig.scans(10, 100ms);
    CHECK(rig.get("TN0") == 5);
    rig.rt().remote_run(rig.mem(), 1, false, ClearMode::None);
    rig.scan(100ms);   // first scan after RUN starts timing again
    CHECK(rig.get("TN0") == 5);
    rig.scan(100ms);
    CHECK(rig.get("TN0") == 6);
}

TEST_CASE("special relays and registers", "[runtime][special]") {
    Rig rig;
    SECTION("SM400 always ON, SM401 always OFF") {
        CHECK(rig.get("SM400") == 1);
        CHECK(rig.get("SM401") == 0);
    }
    SECTION("SM402/SM403: ON/OFF during the first scan after RUN only") {
        CHECK(rig.get("SM402") == 1);
        CHECK(rig.get("SM403") == 0);
        rig.scan();
        CHECK(rig.get("SM402") == 0);
        CHECK(rig.get("SM403") == 1);
        rig.rt().remote_stop(rig.mem(), 1);
        rig.scan();
        rig.rt().remote_run(rig.mem(), 1, false, ClearMode::None);
        CHECK(rig.get("SM402") == 1);
        rig.scan();
        CHECK(rig.get("SM402") == 0);
    }
    SECTION("SD203: 0 RUN, 2 STOP, 3 PAUSE with the cause in bits 4-7") {
        CHECK(rig.get("SD203") == 0x00);
        rig.rt().remote_stop(rig.mem(), 1);
        CHECK(rig.get("SD203") == 0x22);
        rig.rt().remote_run(rig.mem(), 1, false, ClearMode::None);
        rig.rt().remote_pause(rig.mem(), 1, false);
        CHECK(rig.get("SD203") == 0x23);
        rig.rt().set_switch(rig.mem(), RunSwitch::Stop);
        CHECK(rig.get("SD203") == 0x02);
        rig.rt().raise_error(rig.mem(), {0x3300, true});
        CHECK(rig.get("SD203") == 0x42);
    }
    SECTION("SD0 / SM0 / SM1 follow the error, Clear Error resets them") {
        rig.rt().raise_error(rig.mem(), {0x1900, false});
        CHECK(rig.get("SD0") == 0x1900);
        CHECK(rig.get("SM0") == 1);
        CHECK(rig.get("SM1") == 1);
        CHECK(rig.rt().clear_error(rig.mem()) == RemoteRefusal::None);
        CHECK(rig.get("SD0") == 0);
        CHECK(rig.get("SM0") == 0);
    }
    SECTION("SM412 1 s clock and SD412 seconds counter") {
        rig.scan(0us);   // time origin
        rig.scans(49, 10ms);
        CHECK(rig.get("SM412") == 1);   // 490 ms: first half
        rig.scans(2, 10ms);
        CHECK(rig.get("SM412") == 0);   // 510 ms: second half
        rig.scans(149, 10ms);           // 2000 ms
        CHECK(rig.get("SD412") == 2);
        CHECK(rig.get("SM413") == 1);
    }
    SECTION("SD520-SD525: current, minimum and maximum scan time (ms, us)") {
        rig.scan(10ms);   // first scan: not measured
        rig.scan(12'345us);
        rig.scan(9'500us);
        CHECK(rig.get("SD520") == 9);
        CHECK(rig.get("SD521") == 500);
        CHECK(rig.get("SD522") == 9);
        CHECK(rig.get("SD524") == 12);
        CHECK(rig.get("SD525") == 345);
    }
    SECTION("SD210-SD216 calendar, binary on iQ-R") {
        rig.scan();
        CHECK(rig.get("SD210") == 2024);
        CHECK(rig.get("SD211") == 5);
        CHECK(rig.get("SD212") == 17);
        CHECK(rig.get("SD213") == 13);
        CHECK(rig.get("SD214") == 45);
        CHECK(rig.get("SD215") == 30);
        CHECK(rig.get("SD216") == 5);
    }
}

TEST_CASE("SD210-SD213 calendar in BCD on QnU", "[runtime][special]") {
    Rig rig({}, "Q26UDEHCPU");
    rig.scan();
    CHECK(rig.get("SD210") == 0x2405);
    CHECK(rig.get("SD211") == 0x1713);
    CHECK(rig.get("SD212") == 0x4530);
    CHECK(rig.get("SD213") == 0x2005);
}

TEST_CASE("outputs Y turn off when the CPU enters STOP, unless configured otherwise", "[runtime][state]") {
    SECTION("default") {
        Rig rig;
        rig.set("Y10", 1);
        rig.rt().remote_stop(rig.mem(), 1);
        CHECK(rig.get("Y10") == 0);
    }
    SECTION("output_off_at_stop = false") {
        RuntimeConfig c;
        c.output_off_at_stop = false;
        Rig rig(c);
        rig.set("Y10", 1);
        rig.rt().remote_stop(rig.mem(), 1);
        CHECK(rig.get("Y10") == 1);
    }
}

TEST_CASE("device clears follow the latch rules", "[runtime][latch]") {
    RuntimeConfig c;
    c.latch.push_back({Area::D, 100, 10});
    c.remote_reset_enabled = true;
    Rig rig(c);
    auto fill = [&] {
        for (auto* a : {"D0", "D100", "D109", "D110", "L5", "M3", "ZR7", "X4", "TN1", "SD1000"}) rig.set(a, 1);
    };
    auto values = [&] {
        std::vector<std::uint32_t> v;
        for (auto* a : {"D0", "D100", "D109", "D110", "L5", "M3", "ZR7", "X4", "TN1", "SD1000"}) v.push_back(rig.get(a));
        return v;
    };
    fill();
    rig.rt().remote_stop(rig.mem(), 1);
    SECTION("Remote RUN clear mode 00 clears nothing") {
        rig.rt().remote_run(rig.mem(), 1, false, ClearMode::None);
        CHECK(values() == std::vector<std::uint32_t>{1, 1, 1, 1, 1, 1, 1, 1, 1, 1});
    }
    SECTION("clear mode 01 clears outside the latch range (X, R/ZR and SM/SD are never cleared)") {
        rig.rt().remote_run(rig.mem(), 1, false, ClearMode::NonLatched);
        CHECK(values() == std::vector<std::uint32_t>{0, 1, 1, 0, 1, 0, 1, 1, 0, 1});
    }
    SECTION("clear mode 02 clears the latch range too") {
        rig.rt().remote_run(rig.mem(), 1, false, ClearMode::All);
        CHECK(values() == std::vector<std::uint32_t>{0, 0, 0, 0, 0, 0, 1, 1, 0, 1});
    }
    SECTION("Remote Latch Clear clears latched and non-latched devices") {
        CHECK(rig.rt().latch_clear(rig.mem(), 1) == RemoteRefusal::None);
        CHECK(values() == std::vector<std::uint32_t>{0, 0, 0, 0, 0, 0, 1, 1, 0, 1});
    }
    SECTION("Remote RESET keeps the latched devices and starts from the switch") {
        CHECK(rig.rt().reset(rig.mem()) == RemoteRefusal::None);
        CHECK(values() == std::vector<std::uint32_t>{0, 1, 1, 0, 1, 0, 1, 1, 0, 1});
        CHECK(rig.rt().state() == RunState::Run);
        CHECK(rig.get("SD203") == 0);
        CHECK(rig.get("SD280") == 10240);   // device-size registers survive
    }
    SECTION("a clear mode at switch STOP does nothing: the CPU does not go to RUN") {
        rig.rt().set_switch(rig.mem(), RunSwitch::Stop);
        rig.rt().remote_run(rig.mem(), 1, false, ClearMode::All);
        CHECK(values()[0] == 1);
    }
    SECTION("initial values are re-applied after a clear") {
        rig.rt().set_initial_values([&](DeviceMemory&) { rig.set("D0", 42); });
        rig.rt().remote_run(rig.mem(), 1, false, ClearMode::NonLatched);
        CHECK(rig.get("D0") == 42);
    }
}

TEST_CASE("remote password lock-out with a fake clock", "[runtime][password]") {
    RemotePassword pw;
    pw.configure("secret1", 3, std::chrono::seconds(60));
    auto bytes = [](std::string_view s) { return std::vector<std::uint8_t>(s.begin(), s.end()); };
    RemotePassword::TimePoint t{};
    t += 1s;
    CHECK(pw.check(bytes("wrong"), t) == RemotePassword::Check::Mismatch);
    CHECK(pw.check(bytes("secret1"), t) == RemotePassword::Check::Match);   // a match resets the count
    CHECK(pw.check(bytes("x"), t) == RemotePassword::Check::Mismatch);
    CHECK(pw.check(bytes("y"), t) == RemotePassword::Check::Mismatch);
    CHECK(pw.check(bytes("z"), t) == RemotePassword::Check::Mismatch);      // third in a row: lock-out starts
    CHECK(pw.check(bytes("secret1"), t + 59s) == RemotePassword::Check::LockedOut);
    CHECK(pw.check(bytes("SECRET1"), t + 60s) == RemotePassword::Check::Mismatch);   // case-sensitive
    CHECK(pw.check(bytes("secret1"), t + 60s) == RemotePassword::Check::Match);
}

TEST_CASE("Q/L scan-time registers: SD522/523 initial, SD524/525 minimum, SD526/527 maximum", "[runtime]") {
    Rig rig({}, "Q26UDEHCPU");
    rig.scan(10ms);   // first scan: not measured
    rig.scan(12'345us);
    rig.scan(9'500us);
    rig.scan(11ms);
    CHECK(rig.get("SD520") == 11);
    CHECK(rig.get("SD521") == 0);
    CHECK(rig.get("SD522") == 12);
    CHECK(rig.get("SD523") == 345);
    CHECK(rig.get("SD524") == 9);
    CHECK(rig.get("SD525") == 500);
    CHECK(rig.get("SD526") == 12);
    CHECK(rig.get("SD527") == 345);
}
