// Spec §8 worked examples (the acceptance vectors), scan by scan at engine level.
#include <catch2/catch.hpp>

#include "engine_support.hpp"

using namespace engine_test;

TEST_CASE("8.1 self-holding circuit", "[program][engine][examples]") {
    Rig rig(dotted("LD X0 · OR Y0 · ANI X1 · OUT Y0 · END"));
    struct Row { int x0, x1, y0; };
    for (auto [x0, x1, y0] : {Row{0, 0, 0}, Row{1, 0, 1}, Row{0, 0, 1}, Row{0, 1, 0}, Row{0, 0, 0}, Row{1, 1, 0}}) {
        rig.set("X0", x0);
        rig.set("X1", x1);
        rig.scan();
        INFO("scan " << rig.scans);
        CHECK(rig.get("Y0") == static_cast<std::uint32_t>(y0));
    }
}

TEST_CASE("8.2 on-delay timer K20 at 10 ms scans", "[program][engine][examples]") {
    Rig rig(dotted("LD X0 · OUT T0 K20 · LD T0 · OUT Y0 · END"));
    struct Row { int after, tn, ts, y0; };
    const std::vector<Row> rows{{1, 0, 0, 0}, {11, 1, 0, 0}, {200, 19, 0, 0}, {201, 20, 1, 1}, {250, 20, 1, 1}, {251, 0, 0, 0}};
    std::size_t next = 0;
    for (int scan = 1; scan <= 251; ++scan) {
        if (scan == 1) rig.set("X0", 1);
        if (scan == 251) rig.set("X0", 0);
        rig.scan();
        if (next < rows.size() && rows[next].after == scan) {
            INFO("after scan " << scan);
            CHECK(rig.get("TN0") == static_cast<std::uint32_t>(rows[next].tn));
            CHECK(rig.get("TS0") == static_cast<std::uint32_t>(rows[next].ts));
            CHECK(rig.get("Y0") == static_cast<std::uint32_t>(rows[next].y0));
            ++next;
        }
    }
    CHECK(next == rows.size());
}

TEST_CASE("8.3 counter K3 with reset", "[program][engine][examples]") {
    Rig rig(dotted("LD X0 · OUT C0 K3 · LD C0 · OUT Y0 · LD X1 · RST C0 · END"));
    const int x0[] = {0, 0, 1, 1, 0, 1, 0, 1, 0, 1, 0, 0, 0};   // index = scan
    struct Row { int after, cn, cs, y0; };
    const std::vector<Row> rows{{2, 1, 0, 0}, {3, 1, 0, 0}, {5, 2, 0, 0}, {7, 3, 1, 1}, {9, 3, 1, 1}, {10, 0, 0, 1}, {11, 0, 0, 0}};
    std::size_t next = 0;
    for (int scan = 1; scan <= 12; ++scan) {
        rig.set("X0", x0[scan]);
        if (scan == 10) rig.set("X1", 1);
        if (scan == 12) rig.set("X1", 0);
        rig.scan();
        if (next < rows.size() && rows[next].after == scan) {
            INFO("after scan " << scan);
            CHECK(rig.get("CN0") == static_cast<std::uint32_t>(rows[next].cn));
            CHECK(rig.get("CS0") == static_cast<std::uint32_t>(rows[next].cs));
            CHECK(rig.get("Y0") == static_cast<std::uint32_t>(rows[next].y0));
            ++next;
        }
    }
    CHECK(next == rows.size());
}

TEST_CASE("8.4 branches and blocks", "[program][engine][examples]") {
    Rig rig(dotted("LD X0 · MPS · AND X1 · OUT Y0 · MRD · AND X2 · OUT Y1 · MPP · ANI X1 · OUT Y2 · LD X3 · OR X4 · "
                   "LD X5 · OR X6 · ANB · LD X7 · AND X10 · ORB · OUT Y3 · END"));
    struct Row { std::vector<std::string> on; int y0, y1, y2, y3; };
    const std::vector<Row> rows{{{"X0", "X1"}, 1, 0, 0, 0}, {{"X0", "X2"}, 0, 1, 1, 0}, {{"X1", "X2"}, 0, 0, 0, 0},
                                {{"X3", "X6"}, 0, 0, 0, 1}, {{"X3"}, 0, 0, 0, 0},         {{"X7", "X10"}, 0, 0, 0, 1},
                                {{"X7", "X8"}, 0, 0, 0, 0}};
    for (const auto& row : rows) {
        for (int x = 0; x < 0x20; ++x) rig.memory.set_bit(Rig::spec("X"), static_cast<std::uint32_t>(x), false);
        for (const auto& x : row.on) rig.set(x, 1);
        rig.scan();
        INFO("inputs " << row.on[0] << (row.on.size() > 1 ? " " + row.on[1] : ""));
        CHECK(rig.get("Y0") == static_cast<std::uint32_t>(row.y0));
        CHECK(rig.get("Y1") == static_cast<std::uint32_t>(row.y1));
        CHECK(rig.get("Y2") == static_cast<std::uint32_t>(row.y2));
        CHECK(rig.get("Y3") == static_cast<std::uint32_t>(row.y3));
    }
}

TEST_CASE("8.5 master control", "[program][engine][examples]") {
    Rig rig(dotted("LD X0 · MC N0 M100 · LD X1 · OUT Y0 · LD X1 · OUT T0 K5 · LD X2 · SET M0 · MCR N0 · LD M100 · "
                   "OUT Y1 · END"));
    struct Row { int after, m100, y0, tn, ts, m0, y1; };
    const std::vector<Row> rows{{1, 1, 1, 0, 0, 1, 1}, {51, 1, 1, 5, 1, 1, 1}, {61, 0, 0, 0, 0, 1, 0}, {62, 1, 1, 0, 0, 1, 1}};
    std::size_t next = 0;
    for (int scan = 1; scan <= 62; ++scan) {
        if (scan == 1) {
            rig.set("X0", 1);
            rig.set("X1", 1);
            rig.set("X2", 1);
        }
        if (scan == 61) rig.set("X0", 0);
        if (scan == 62) rig.set("X0", 1);
        if (scan == 61) rig.set("X2", 0);   // SET M0 must not run anyway; M0 stays from scan 1
        rig.scan();
        if (next < rows.size() && rows[next].after == scan) {
            INFO("after scan " << scan);
            const auto& r = rows[next++];
            CHECK(rig.get("M100") == static_cast<std::uint32_t>(r.m100));
            CHECK(rig.get("Y0") == static_cast<std::uint32_t>(r.y0));
            CHECK(rig.get("TN0") == static_cast<std::uint32_t>(r.tn));
            CHECK(rig.get("TS0") == static_cast<std::uint32_t>(r.ts));
            CHECK(rig.get("M0") == static_cast<std::uint32_t>(r.m0));
            CHECK(rig.get("Y1") == static_cast<std::uint32_t>(r.y1));
        }
    }
    CHECK(next == rows.size());
}

TEST_CASE("8.6 conditional jump over a block", "[program][engine][examples]") {
    Rig rig(dotted("LD X0 · CJ P10 · LD X1 · OUT Y0 · LD SM400 · INC D1 · P10 · LD SM400 · INC D2 · END"));
    for (int scan = 1; scan <= 7; ++scan) {
        if (scan == 1) rig.set("X1", 1);
        if (scan == 4) {
            rig.set("X0", 1);
            rig.set("X1", 0);
        }
        if (scan == 7) rig.set("X0", 0);
        rig.scan();
        INFO("after scan " << scan);
        if (scan == 3) {
            CHECK(rig.get("Y0") == 1);
            CHECK(rig.get("D1") == 3);
            CHECK(rig.get("D2") == 3);
        }
        if (scan == 6) {
            CHECK(rig.get("Y0") == 1);
            CHECK(rig.get("D1") == 3);
            CHECK(rig.get("D2") == 6);
        }
        if (scan == 7) {
            CHECK(rig.get("Y0") == 0);
            CHECK(rig.get("D1") == 4);
            CHECK(rig.get("D2") == 7);
        }
    }
}

TEST_CASE("8.7 subroutine call", "[program][engine][examples]") {
    Rig rig(dotted("LD X0 · CALL P0 · LD SM400 · OUT Y1 · FEND · P0 · LD SM400 · INC D0 · RET · END"));
    rig.set("X0", 1);
    rig.scan(5);
    CHECK(rig.get("D0") == 5);
    CHECK(rig.get("Y1") == 1);
    rig.set("X0", 0);
    rig.scan(3);
    CHECK(rig.get("D0") == 5);
    CHECK(rig.get("Y1") == 1);
}

TEST_CASE("8.7 CALL nested deeper than 16 is a nest operation error", "[program][engine][examples]") {
    // P0 calls itself: the 17th CALL fails.
    program::ProgramOptions options;
    Rig rig(dotted("LD SM400 · CALL P0 · FEND · P0 · LD SM400 · INC D0 · CALL P0 · RET · END"), r08(), options);
    auto outcome = rig.scan();
    CHECK(outcome.kind == program::ScanOutcome::Kind::StopError);
    REQUIRE(outcome.error);
    CHECK(outcome.error->code == 0x3300);
    CHECK(outcome.error->mnemonic == "CALL");
    CHECK(rig.get("D0") == 16);
}

TEST_CASE("8.8 32-bit move and addition overflow", "[program][engine][examples]") {
    Rig rig(dotted("LD SM402 · DMOV K2147483647 D0 · LD SM400 · D+ K1 D0 · DMOV D0 D10 · D+ K100000 K200000 D20 · END"));
    rig.scan();
    CHECK(rig.get("D0") == 0x0000);
    CHECK(rig.get("D1") == 0x8000);
    CHECK(rig.get("D10") == 0x0000);
    CHECK(rig.get("D11") == 0x8000);
    CHECK(rig.get("D20") == 0x93E0);
    CHECK(rig.get("D21") == 0x0004);
    CHECK(rig.get("SM0") == 0);
    rig.scan();
    CHECK(rig.get("D0") == 0x0001);
    CHECK(rig.get("D1") == 0x8000);
    CHECK(rig.get("D10") == 0x0001);
    CHECK(rig.get("D11") == 0x8000);
    CHECK(rig.get("D20") == 0x93E0);
    CHECK(rig.get("D21") == 0x0004);
    CHECK(rig.get("SM0") == 0);
}

TEST_CASE("8.9 division with remainder, multiplication, BCD", "[program][engine][examples]") {
    Rig rig(dotted("LD SM400 · / K36 K-5 D0 · / K-36 K5 D2 · * K300 K400 D4 · D/ K100000 K7 D6 · BCD K1234 D20 · "
                   "BIN H0987 D21 · DBCD K12345678 D22 · END"));
    auto outcome = rig.scan();
    CHECK(outcome.kind == program::ScanOutcome::Kind::Ok);
    CHECK(rig.get("D0") == 0xFFF9);
    CHECK(rig.get("D1") == 0x0001);
    CHECK(rig.get("D2") == 0xFFF9);
    CHECK(rig.get("D3") == 0xFFFF);
    CHECK(rig.get("D4") == 0xD4C0);
    CHECK(rig.get("D5") == 0x0001);
    CHECK(rig.get("D6") == 0x37CD);
    CHECK(rig.get("D7") == 0);
    CHECK(rig.get("D8") == 0x0005);
    CHECK(rig.get("D9") == 0);
    CHECK(rig.get("D20") == 0x1234);
    CHECK(rig.get("D21") == 0x03DB);
    CHECK(rig.get("D22") == 0x5678);
    CHECK(rig.get("D23") == 0x1234);
}

TEST_CASE("8.10 digit designation", "[program][engine][examples]") {
    Rig rig(dotted("LD SM400 · MOV H1234 K4M0 · MOV K4M0 D0 · MOV K1M4 D1 · MOV K15 K1Y0 · MOV HFFFF K2M20 · "
                   "DMOV K8M0 D2 · END"));
    rig.scan();
    for (int m = 0; m < 16; ++m) {
        INFO("M" << m);
        const bool on = m == 2 || m == 4 || m == 5 || m == 9 || m == 12;
        CHECK(rig.get("M" + std::to_string(m)) == (on ? 1u : 0u));
    }
    CHECK(rig.get("D0") == 0x1234);
    CHECK(rig.get("D1") == 0x0003);
    for (int y = 0; y < 4; ++y) CHECK(rig.get("Y" + std::to_string(y)) == 1);
    CHECK(rig.get("Y4") == 0);
    for (int m = 16; m < 32; ++m) {
        INFO("M" << m);
        CHECK(rig.get("M" + std::to_string(m)) == ((m >= 20 && m <= 27) ? 1u : 0u));
    }
    CHECK(rig.get("D2") == 0x1234);
    CHECK(rig.get("D3") == 0x0FF0);
}

TEST_CASE("8.11 index modification", "[program][engine][examples]") {
    Rig rig(dotted("LD SM400 · MOV K3 Z0 · MOV K100 D10Z0 · MOV D10Z0 D20 · MOV K10Z0 D21 · MOV K5 Z1 · "
                   "MOV K1 K4M0Z1 · BMOV D10Z0 D30 K2 · END"));
    auto outcome = rig.scan();
    CHECK(outcome.kind == program::ScanOutcome::Kind::Ok);
    CHECK(rig.get("Z0") == 3);
    CHECK(rig.get("D13") == 100);
    CHECK(rig.get("D20") == 100);
    CHECK(rig.get("D21") == 13);
    CHECK(rig.get("Z1") == 5);
    CHECK(rig.get("M5") == 1);
    for (int m = 6; m <= 20; ++m) CHECK(rig.get("M" + std::to_string(m)) == 0);
    CHECK(rig.get("D30") == 100);
    CHECK(rig.get("D31") == 0);
}

TEST_CASE("8.11 variant: index past the end is a dev operation error", "[program][engine][examples]") {
    const auto source = dotted("LD SM400 · MOV K20000 Z0 · MOV K100 D10Z0 · MOV D10Z0 D20 · MOV K10Z0 D21 · END");
    {
        Rig rig(source);
        auto outcome = rig.scan();
        CHECK(outcome.kind == program::ScanOutcome::Kind::StopError);
        REQUIRE(outcome.error);
        CHECK(outcome.error->code == 0x2820);
        CHECK(outcome.error->step_index == 2);
        CHECK(outcome.error->mnemonic == "MOV");
        CHECK(rig.get("D21") == 0);   // the scan ended at the failing step
    }
    {
        Rig rig(source, q26());
        auto outcome = rig.scan();
        REQUIRE(outcome.error);
        CHECK(outcome.error->code == 4101);
    }
}

namespace {
void division_by_zero(devicemodel::CpuProfile profile, program::OnOperationError mode, std::uint16_t code) {
    program::ProgramOptions options;
    options.operation_error = mode;
    const bool q = profile.family == devicemodel::Family::QnU;
    Rig rig(dotted("LD SM400 · MOV K0 D1 · / K100 D1 D2 · MOV K1 D10 · OUT Y0 · END"), profile, options);
    auto outcome = rig.scan();
    REQUIRE(outcome.error);
    CHECK(outcome.error->code == code);
    CHECK(outcome.error->step_index == 2);
    CHECK(outcome.error->row == 3);
    CHECK(rig.get("D2") == 0);
    if (mode == program::OnOperationError::Stop) {
        CHECK(outcome.kind == program::ScanOutcome::Kind::StopError);
        CHECK(rig.get("D10") == 0);
        CHECK(rig.get("Y0") == 0);
        CHECK(rig.get("SM0") == 0);   // the caller raises the stop error (SM0/SM1/SD0/SD203)
    } else {
        CHECK(outcome.kind == program::ScanOutcome::Kind::Ok);
        CHECK(rig.get("D10") == 1);
        CHECK(rig.get("Y0") == 1);
        CHECK(rig.get("SM0") == 1);
        CHECK(rig.get("SM1") == 1);
        CHECK(rig.get("SD0") == code);
        CHECK(rig.get("SM56") == (q ? 1u : 0u));
        // Cleared (SM50 error reset, or 1617 on an iQ-F port), raised again by the next scan.
        rig.set("SM0", 0);
        rig.set("SD0", 0);
        rig.scan();
        CHECK(rig.get("SM0") == 1);
        CHECK(rig.get("SD0") == code);
    }
    CHECK(rig.execution.last_error());
}
}  // namespace

TEST_CASE("8.12 operation error: division by zero", "[program][engine][examples]") {
    division_by_zero(r08(), program::OnOperationError::Stop, 0x3400);
    division_by_zero(r08(), program::OnOperationError::Continue, 0x3400);
    division_by_zero(q26(), program::OnOperationError::Stop, 0x1004);
    division_by_zero(q26(), program::OnOperationError::Continue, 0x1004);
}

TEST_CASE("8.13 floating point", "[program][engine][examples]") {
    for (auto profile : {r08(), q26()}) {
        Rig rig(dotted("LD SM400 · FLT K10 D0 · E+ E2.5 D0 D2 · E* D2 E2 D4 · E/ D2 E4 D6 · INT D4 D8 · EMOV E-2.5 D10 · "
                       "INT D10 D12 · DFLT K100000 D14 · END"),
                profile);
        auto outcome = rig.scan();
        INFO(profile.name);
        CHECK(outcome.kind == program::ScanOutcome::Kind::Ok);
        CHECK(rig.get("D0") == 0x0000);
        CHECK(rig.get("D1") == 0x4120);
        CHECK(rig.get("D2") == 0x0000);
        CHECK(rig.get("D3") == 0x4148);
        CHECK(rig.get("D4") == 0x0000);
        CHECK(rig.get("D5") == 0x41C8);
        CHECK(rig.get("D6") == 0x0000);
        CHECK(rig.get("D7") == 0x4048);
        CHECK(rig.get("D8") == 25);
        CHECK(rig.get("D10") == 0x0000);
        CHECK(rig.get("D11") == 0xC020);
        CHECK(rig.get("D12") == 0xFFFD);
        CHECK(rig.get("D14") == 0x5000);
        CHECK(rig.get("D15") == 0x47C3);
    }
}

TEST_CASE("8.13 variant: a NaN operand is a float operation error", "[program][engine][examples]") {
    const auto source = dotted("LD SM400 · FLT K10 D0 · MOV K0 D0 · MOV H7FC0 D1 · E+ E2.5 D0 D2 · END");
    Rig r(source);
    auto outcome = r.scan();
    CHECK(outcome.kind == program::ScanOutcome::Kind::StopError);
    REQUIRE(outcome.error);
    CHECK(outcome.error->code == 0x3402);
    CHECK(outcome.error->mnemonic == "E+");
    CHECK(r.get("D3") == 0);
    Rig q(source, q26());
    outcome = q.scan();
    REQUIRE(outcome.error);
    CHECK(outcome.error->code == 4140);
}

TEST_CASE("8.14 edges: PLS, FF, LDP/LDF, INCP", "[program][engine][examples]") {
    Rig rig(dotted("LD X0 · PLS M0 · LD M0 · FF Y0 · LDP X1 · SET Y1 · LDF X1 · RST Y1 · LD X2 · INCP D0 · END"));
    struct Row { int x0, x1, x2, m0, y0, y1, d0; };
    const std::vector<Row> rows{{0, 0, 1, 0, 0, 0, 1}, {1, 0, 1, 1, 1, 0, 1}, {1, 0, 0, 0, 1, 0, 1}, {0, 1, 0, 0, 1, 1, 1},
                                {1, 1, 1, 1, 0, 1, 2}, {1, 0, 1, 0, 0, 0, 2}, {0, 0, 0, 0, 0, 0, 2}};
    for (const auto& r : rows) {
        rig.set("X0", r.x0);
        rig.set("X1", r.x1);
        rig.set("X2", r.x2);
        rig.scan();
        INFO("scan " << rig.scans);
        CHECK(rig.get("M0") == static_cast<std::uint32_t>(r.m0));
        CHECK(rig.get("Y0") == static_cast<std::uint32_t>(r.y0));
        CHECK(rig.get("Y1") == static_cast<std::uint32_t>(r.y1));
        CHECK(rig.get("D0") == static_cast<std::uint32_t>(r.d0));
    }
}

TEST_CASE("8.15 watchdog on an endless loop", "[program][engine][examples]") {
    const auto source = text_source({"P0", "LD SM400", "CJ P0", "END"});
    {
        program::ProgramOptions options;
        options.wdt_ms = 10;
        Rig rig(source, q26(), options);
        const auto start = std::chrono::steady_clock::now();
        auto outcome = rig.scan();
        const auto host = std::chrono::steady_clock::now() - start;
        CHECK(outcome.kind == program::ScanOutcome::Kind::Watchdog);
        REQUIRE(outcome.error);
        CHECK(outcome.error->code == 5001);
        CHECK(outcome.error->code == 0x1389);
        // 10 ms / (2 x 9.5 ns) = 526 315 loops, 1.05 million steps.
        CHECK(outcome.executed > 1'050'000);
        CHECK(outcome.executed < 1'054'000);
        CHECK(outcome.modelled > std::chrono::milliseconds(10));
        CHECK(host < std::chrono::seconds(1));
    }
    {
        Rig rig(source);   // R08CPU: the 10 million step guard fires first
        const auto start = std::chrono::steady_clock::now();
        auto outcome = rig.scan();
        const auto host = std::chrono::steady_clock::now() - start;
        CHECK(outcome.kind == program::ScanOutcome::Kind::Watchdog);
        REQUIRE(outcome.error);
        CHECK(outcome.error->code == 0x1810);
        CHECK(outcome.executed == 10'000'001);
        CHECK(outcome.error->message.find("max_steps_per_scan") != std::string::npos);
        CHECK(host < std::chrono::seconds(1));
    }
}

TEST_CASE("8.16 STOP/RUN around 8.1: restart() clears the engine state", "[program][engine][examples]") {
    // The output image at STOP and its restore are the station's; the engine
    // must run scan 1 after restart() from the memory it is given.
    for (bool previous : {true, false}) {
        Rig rig(dotted("LD X0 · OR Y0 · ANI X1 · OUT Y0 · END"));
        rig.scan();
        rig.set("X0", 1);
        rig.scan();
        rig.set("X0", 0);
        CHECK(rig.get("Y0") == 1);
        rig.set("Y0", 0);                   // STOP: outputs OFF
        if (previous) rig.set("Y0", 1);     // RUN, output_mode_at_run = previous: the image comes back
        rig.execution.restart();
        rig.scans = 0;
        rig.scan();
        CHECK(rig.get("Y0") == (previous ? 1u : 0u));
    }
    // restart() clears edge bits (a held input is rising again) and timer accumulators.
    Rig rig(dotted("LDP X0 · INCP D0 · LD X1 · OUT T0 K20 · END"));
    rig.set("X0", 1);
    rig.set("X1", 1);
    rig.scan(5);
    CHECK(rig.get("D0") == 1);
    rig.execution.restart();
    rig.scan();
    CHECK(rig.get("D0") == 2);
    CHECK(rig.get("TN0") == 0);   // 50 ms accumulated before restart() are gone: 0 + 0
}
