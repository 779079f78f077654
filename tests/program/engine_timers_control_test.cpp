// Timers and counters (docs/program.md "Timers", "Instructions"), edge memory (§4.3), MC/MCR
// (§5.1) and program control (§5.10), watchdog (§3.4), engine state.
#include <catch2/catch.hpp>

#include "engine_support.hpp"

using namespace engine_test;
using Kind = program::ScanOutcome::Kind;

TEST_CASE("OUTH times in 10 ms, OUT in 100 ms (time bases from ProgramOptions)", "[program][engine][timers]") {
    Rig rig(dotted("LD X0 · OUTH T1 K5 · LD X0 · OUT T2 K5 · END"));
    rig.set("X0", 1);
    rig.scan(6);   // 50 ms accumulated by the 6th OUTH
    CHECK(rig.get("TN1") == 5);
    CHECK(rig.get("TS1") == 1);
    CHECK(rig.get("TN2") == 0);
    program::ProgramOptions options;
    options.timer_low_ms = 10;
    Rig fast(dotted("LD X0 · OUT T2 K5 · END"), r08(), options);
    fast.set("X0", 1);
    fast.scan(6);
    CHECK(fast.get("TS2") == 1);
}

TEST_CASE("retentive ST keeps its value while the coil is OFF, RST clears it", "[program][engine][timers]") {
    Rig rig(dotted("LD X0 · OUT ST0 K10 · LD X1 · RST ST0 · END"));
    rig.set("X0", 1);
    rig.scan(51);
    CHECK(rig.get("STN0") == 5);
    rig.set("X0", 0);
    rig.scan(20);
    CHECK(rig.get("STN0") == 5);
    rig.set("X0", 1);
    rig.scan(51);
    CHECK(rig.get("STN0") == 10);
    CHECK(rig.get("STS0") == 1);
    rig.set("X1", 1);
    rig.scan();
    CHECK(rig.get("STN0") == 0);
    CHECK(rig.get("STS0") == 0);
}

TEST_CASE("LT counts in µs (iQ-R), preset from a word pair, preset 0 is ON at once", "[program][engine][timers]") {
    Rig rig(dotted("LD X0 · OUT LT0 D0 · LD X0 · OUT T3 K0 · END"));
    rig.set("D0", 25000);   // 25 ms
    rig.set("X0", 1);
    rig.scan();
    CHECK(rig.get("TS3") == 1);
    rig.scan(2);
    CHECK(rig.get("LTN0") == 20000);
    CHECK(rig.get("LTS0") == 0);
    rig.scan();
    CHECK(rig.get("LTN0") == 25000);
    CHECK(rig.get("LTS0") == 1);
}

TEST_CASE("raising the preset after time-up keeps the contact ON, negative preset is a range error",
          "[program][engine][timers]") {
    Rig rig(dotted("LD X0 · OUT T0 D0 · END"));
    rig.set("D0", 1);
    rig.set("X0", 1);
    rig.scan(11);
    CHECK(rig.get("TS0") == 1);
    rig.set("D0", 5);
    rig.scan(10);
    CHECK(rig.get("TS0") == 1);
    CHECK(rig.get("TN0") == 1);
    rig.set("D0", 0xFFFF);   // -1
    rig.execution.restart();
    rig.set("TS0", 0);
    auto outcome = rig.scan();
    REQUIRE(outcome.error);
    CHECK(outcome.error->code == 0x3405);
}

TEST_CASE("RST T with the coil still ON restarts timing", "[program][engine][timers]") {
    Rig rig(dotted("LD X0 · OUT T0 K2 · LD X1 · RST T0 · END"));
    rig.set("X0", 1);
    rig.scan(21);
    CHECK(rig.get("TS0") == 1);
    rig.set("X1", 1);
    rig.scan();
    rig.set("X1", 0);
    CHECK(rig.get("TN0") == 0);
    rig.scan(19);
    CHECK(rig.get("TS0") == 0);
    rig.scan();
    CHECK(rig.get("TS0") == 1);
}

TEST_CASE("LC is a 32-bit counter, a reset counter with its coil ON waits for OFF-ON", "[program][engine][timers]") {
    Rig rig(dotted("LD X0 · OUT LC0 K100000 · LD X0 · OUT C1 K5 · LD X1 · RST C1 · END"));
    rig.set("LCN0", 99999);
    rig.set("X0", 1);
    rig.scan();
    CHECK(rig.get("LCN0") == 100000);
    CHECK(rig.get("LCS0") == 1);
    CHECK(rig.get("CN1") == 1);
    rig.set("X1", 1);
    rig.scan();
    rig.set("X1", 0);
    rig.scan(3);
    CHECK(rig.get("CN1") == 0);
    rig.set("X0", 0);
    rig.scan();
    rig.set("X0", 1);
    rig.scan();
    CHECK(rig.get("CN1") == 1);
}

TEST_CASE("edge memory belongs to the step: two LDP of one device both see the edge", "[program][engine][edges]") {
    Rig rig(dotted("LDP X0 · INC D0 · LDP X0 · INC D1 · LDF X0 · INC D2 · LD X0 · MEP · INC D3 · LD X0 · MEF · INC D4 · "
                   "LDPI X0 · INC D5 · END"));
    rig.set("X0", 1);
    rig.scan(3);
    rig.set("X0", 0);
    rig.scan(2);
    CHECK(rig.get("D0") == 1);
    CHECK(rig.get("D1") == 1);
    CHECK(rig.get("D2") == 1);
    CHECK(rig.get("D3") == 1);
    CHECK(rig.get("D4") == 1);
    CHECK(rig.get("D5") == 4);   // ON in every scan but the one of the rising edge
}

TEST_CASE("a step skipped by CJ keeps its edge bit, PLS output stays ON while skipped", "[program][engine][edges]") {
    Rig rig(dotted("LD X1 · CJ P1 · LD X0 · PLS M0 · P1 · END"));
    rig.set("X0", 1);
    rig.scan();
    CHECK(rig.get("M0") == 1);
    rig.set("X1", 1);
    rig.scan(3);
    CHECK(rig.get("M0") == 1);
    rig.set("X1", 0);
    rig.scan();
    CHECK(rig.get("M0") == 0);
}

TEST_CASE("MC: OUT OFF, non-retentive timers reset, counters and retentive timers hold, nested levels",
          "[program][engine][mc]") {
    Rig rig(dotted("LD X0 · MC N0 M100 · LD X1 · MC N1 M101 · LD SM400 · OUT Y0 · MCR N1 · LD SM400 · OUT ST0 K100 · "
                   "LD SM400 · OUT C0 K10 · LD SM400 · MOV K7 D0 · MCR N0 · LD SM400 · OUT Y1 · END"));
    rig.set("X0", 1);
    rig.set("X1", 1);
    rig.scan(21);
    CHECK(rig.get("Y0") == 1);
    CHECK(rig.get("STN0") == 2);
    CHECK(rig.get("CN0") == 1);
    CHECK(rig.get("D0") == 7);
    rig.set("X1", 0);
    rig.scan();
    CHECK(rig.get("Y0") == 0);
    CHECK(rig.get("M101") == 0);
    CHECK(rig.get("Y1") == 1);
    rig.set("X0", 0);
    rig.set("D0", 0);
    rig.scan(30);
    CHECK(rig.get("M100") == 0);
    CHECK(rig.get("STN0") == 2);   // retentive: held
    CHECK(rig.get("CN0") == 1);
    CHECK(rig.get("D0") == 0);     // MOV did nothing
    CHECK(rig.get("Y1") == 1);     // after MCR: normal again
    rig.set("X0", 1);
    rig.scan();
    CHECK(rig.get("CN0") == 2);    // the coil went OFF in the block, ON again: counts
}

TEST_CASE("FOR/NEXT, BREAK, nesting errors", "[program][engine][control]") {
    Rig rig(dotted("FOR K5 · LD SM400 · INC D0 · NEXT · FOR K0 · LD SM400 · INC D1 · NEXT · FOR K10 · LD SM400 · INC D2 · "
                   "LD= D2 K3 · BREAK D3 P1 · NEXT · P1 · FOR K2 · FOR K3 · LD SM400 · INC D4 · NEXT · NEXT · END"));
    REQUIRE(rig.scan().kind == Kind::Ok);
    CHECK(rig.get("D0") == 5);
    CHECK(rig.get("D1") == 1);
    CHECK(rig.get("D2") == 3);
    CHECK(rig.get("D3") == 7);     // repetitions left after the current one
    CHECK(rig.get("D4") == 6);

    std::string deep;
    for (int i = 0; i < 17; ++i) deep += "FOR K1 · ";
    deep += "LD SM400 · INC D0 · ";
    for (int i = 0; i < 17; ++i) deep += "NEXT · ";
    deep += "END";
    Rig nested(dotted(deep));
    auto outcome = nested.scan();
    REQUIRE(outcome.error);
    CHECK(outcome.error->code == 0x3300);
    CHECK(outcome.error->mnemonic == "FOR");
    Rig q(dotted(deep), q26());
    outcome = q.scan();
    REQUIRE(outcome.error);
    CHECK(outcome.error->code == 4202);
}

TEST_CASE("SCJ jumps from the scan after its condition turned ON, JMP, GOEND", "[program][engine][control]") {
    Rig rig(dotted("LD X0 · SCJ P1 · LD SM400 · INC D0 · P1 · JMP P2 · LD SM400 · INC D1 · P2 · LD X1 · GOEND · "
                   "LD SM400 · INC D2 · END"));
    rig.set("X0", 1);
    rig.scan();
    CHECK(rig.get("D0") == 1);   // first scan with X0 ON: no jump yet
    rig.scan(2);
    CHECK(rig.get("D0") == 1);
    CHECK(rig.get("D1") == 0);
    CHECK(rig.get("D2") == 3);
    rig.set("X1", 1);
    rig.scan();
    CHECK(rig.get("D2") == 3);
}

TEST_CASE("WDT restarts the watchdog measurement, STOP ends RUN after the scan", "[program][engine][control]") {
    program::ProgramOptions options;
    options.wdt_ms = 10;
    // 600 000 x (LD + INC + NEXT) = 600 000 x 38 ns = 22.8 ms on Q26UDEHCPU: past 10 ms.
    Rig slow(dotted("FOR K30000 · FOR K20 · LD SM400 · INC D0 · NEXT · NEXT · END"), q26(), options);
    auto outcome = slow.scan();
    CHECK(outcome.kind == Kind::Watchdog);
    REQUIRE(outcome.error);
    CHECK(outcome.error->code == 5001);
    Rig kicked(dotted("FOR K30000 · LD SM400 · WDT · FOR K20 · LD SM400 · INC D0 · NEXT · NEXT · END"), q26(), options);
    outcome = kicked.scan();
    CHECK(outcome.kind == Kind::Ok);
    CHECK(outcome.modelled > std::chrono::milliseconds(20));   // the modelled time still counts everything
    CHECK(kicked.get("D0") == static_cast<std::uint32_t>(static_cast<std::uint16_t>(600000)));

    Rig stop(dotted("LD X0 · STOP · LD SM400 · INC D0 · END"));
    CHECK(stop.scan().kind == Kind::Ok);
    stop.set("X0", 1);
    CHECK(stop.scan().kind == Kind::StopInstruction);
    CHECK(stop.get("D0") == 2);   // the scan ran to END
}

TEST_CASE("modelled time: instruction costs plus END processing, per family", "[program][engine][time]") {
    const auto source = dotted("LD SM400 · MOV K1 D0 · + K1 D0 · EMOV E1 D2 · BMOV D0 D10 K10 · END");
    struct Case { devicemodel::CpuProfile profile; double ns; };
    for (const auto& c : {Case{r08(), 0.98 * 2 + 1.96 + 4 + 1.96 + 10 * 1 + 0.001 + 50'000},
                          Case{q26(), 9.5 * 2 + 19 + 40 + 19 + 10 * 10 + 0.001 + 150'000},
                          Case{fx5u(), 34 * 2 + 34 + 200 + 34 + 10 * 50 + 0.001 + 200'000}}) {
        Rig rig(source, c.profile);
        auto outcome = rig.scan();
        INFO(c.profile.name);
        CHECK(outcome.modelled.count() == static_cast<long long>(c.ns));
        CHECK(outcome.executed == 6);
        CHECK(rig.execution.modelled_times().last == outcome.modelled);
    }
}

TEST_CASE("engine state survives save_state/restore_state", "[program][engine][state]") {
    const auto source = dotted("LDP X0 · INC D0 · LD X1 · OUT T0 K10 · END");
    Rig a(source);
    a.set("X0", 1);
    a.set("X1", 1);
    a.scan(5);
    const auto bytes = a.execution.save_state();
    Rig b(source);
    REQUIRE(b.execution.restore_state(bytes));
    b.memory = a.memory;
    b.scans = a.scans;
    b.scan(6);
    CHECK(b.get("D0") == 1);       // the edge bit came along: no second count
    CHECK(b.get("TN0") == 1);      // 50 ms + 60 ms accumulated
    Rig other(dotted("LD X0 · OUT Y0 · END"));
    CHECK_FALSE(other.execution.restore_state(bytes));
}

TEST_CASE("compiled steps keep mnemonic, operands and source row", "[program][engine][api]") {
    auto program = program::compile(dotted("LD X0 · MOVP K1 D0 · P5 · LD X1 · + K1 D0 · END"), r08(), {});
    const auto& steps = program::compiled_steps(*program);
    REQUIRE(steps.size() == 5);
    CHECK(program::step_count(*program) == 5);
    CHECK(steps[1].mnemonic == "MOVP");
    CHECK(steps[1].operands == std::vector<std::string>{"K1", "D0"});
    CHECK(steps[3].mnemonic == "+");
    CHECK(steps[3].row == 5);
}

TEST_CASE("resume() after PAUSE: accumulators 0, edge bits kept", "[program][engine][state]") {
    Rig rig(dotted("LDP X0 · INC D0 · LD X1 · OUT T0 K10 · END"));
    rig.set("X0", 1);
    rig.set("X1", 1);
    rig.scan(9);                  // 80 ms accumulated after scan 9's OUT
    rig.execution.resume();
    rig.scan(5);
    CHECK(rig.get("D0") == 1);    // no new edge
    CHECK(rig.get("TN0") == 0);   // 40 ms since the resume
    rig.scan(6);
    CHECK(rig.get("TN0") == 1);
}

TEST_CASE("scan() refuses a memory smaller than the profile", "[program][engine][state]") {
    auto program = program::compile(dotted("LD X0 · OUT Y0 · END"), r08(), {});
    program::Execution execution(program);
    devicemodel::DeviceMemory small(q26().sizes);
    CHECK_THROWS_AS(execution.scan(small), std::invalid_argument);
}
