// The rung language, scan by scan on a fake clock (docs/scenarios.md "Logic").
#include "support/scenario_fixtures.hpp"

using namespace slmp;
using namespace slmp::test;

namespace {

std::string rung_file(std::initializer_list<const char*> rungs) {
    std::string json = R"({"logic": [)";
    bool first = true;
    for (const auto* r : rungs) {
        json += (first ? "\"" : ", \"") + std::string(r) + "\"";
        first = false;
    }
    return json + "]}";
}

}  // namespace

TEST_CASE("logic: a start button latches the motor, stop releases it", "[scenario][logic]") {
    ScenarioRig rig(rung_file({"LD M0 OR Y0 ANI M1 OUT Y0"}));
    rig.scan(0);
    CHECK(rig["Y0"] == 0);
    set(rig.cpu, "M0", 1);
    rig.scan(10);
    CHECK(rig["Y0"] == 1);
    set(rig.cpu, "M0", 0);
    rig.scan(20);
    CHECK(rig["Y0"] == 1);   // latched through OR Y0
    set(rig.cpu, "M1", 1);
    rig.scan(30);
    CHECK(rig["Y0"] == 0);
}

TEST_CASE("logic: an on-delay timer (100 ms base) and its contact", "[scenario][logic]") {
    ScenarioRig rig(rung_file({"LD Y0 OUT T0 K20", "LD T0 OUT Y1", "LD SM400 MOV T0 D0"}));
    set(rig.cpu, "Y0", 1);
    rig.scan_through(0, 2000);
    CHECK(rig["Y1"] == 0);   // T0 reaches K20 at the END of the 2000 ms scan; its rungs still saw 19
    CHECK(rig["D0"] == 19);
    rig.scan(2010);
    CHECK(rig["TN0"] == 20);
    rig.scan(2020);
    CHECK(rig["Y1"] == 1);   // the contact set at END is seen by the next scan's rungs
    CHECK(rig["D0"] == 20);
    set(rig.cpu, "Y0", 0);
    rig.scan(2030);
    CHECK(rig["TN0"] == 0);
    rig.scan(2040);
    CHECK(rig["Y1"] == 0);
}

TEST_CASE("logic: a counter counts rising edges up to its preset, RST clears it", "[scenario][logic]") {
    ScenarioRig rig(rung_file({"LD X0 OUT C0 K3", "LD C0 OUT Y2", "LD X1 RST C0"}));
    rig.scan(0);
    for (int i = 1; i <= 10; ++i) {
        set(rig.cpu, "X0", i % 2);
        rig.scan(i * 10);
    }
    CHECK(rig["CN0"] == 3);
    rig.scan(110);
    CHECK(rig["Y2"] == 1);
    set(rig.cpu, "X1", 1);
    rig.scan(120);
    CHECK(rig["CN0"] == 0);
    CHECK(rig["CS0"] == 0);
}

TEST_CASE("logic: compare contacts, SET/RST, arithmetic, P forms", "[scenario][logic]") {
    ScenarioRig rig(rung_file({
        "LD>= D100 K50 SET M10",
        "LD< D100 K10 RST M10",
        "LD<> D1 D2 OUT M11",
        "LD SM400 ADD D100 K1 D3",
        "LD SM400 SUB K0 K32767 D4 SUB D4 K2 D4",
        "LDP X0 INC D5",
        "LD X0 INCP D6 INC D7",
        "LD X0 MOVP H7FFF D8 DEC D9",
    }));
    set(rig.cpu, "D100", 50);
    rig.scan(0);
    CHECK(rig["M10"] == 1);
    set(rig.cpu, "D100", 20);
    rig.scan(10);
    CHECK(rig["M10"] == 1);   // SET holds
    set(rig.cpu, "D100", 9);
    rig.scan(20);
    CHECK(rig["M10"] == 0);
    CHECK(rig["M11"] == 0);
    set(rig.cpu, "D1", 4);
    rig.scan(30);
    CHECK(rig["M11"] == 1);
    CHECK(rig["D3"] == 10);
    CHECK(rig["D4"] == 0x7FFF);   // -32767 - 2 wraps to 32767, as 16-bit BIN arithmetic does
    set(rig.cpu, "X0", 1);
    rig.scan(40);
    rig.scan(50);
    rig.scan(60);
    CHECK(rig["D5"] == 1);   // LDP: once per rising edge
    CHECK(rig["D6"] == 1);   // INCP: once per rising edge of the rung
    CHECK(rig["D7"] == 3);   // INC: every scan
    CHECK(rig["D8"] == 0x7FFF);
    CHECK(rig["D9"] == static_cast<std::uint16_t>(-3));
}

TEST_CASE("logic: ANB, ORB and several lines in one rung", "[scenario][logic]") {
    ScenarioRig rig(rung_file({"LD X0 OR X1 LD X2 OR X3 ANB OUT Y0 LD X4 LD X5 ORB OUT Y1"}));
    auto check = [&](std::initializer_list<int> x, int y0, int y1) {
        int i = 0;
        for (int v : x) set(rig.cpu, "X" + std::to_string(i++), v);
        rig.scan(0);
        CHECK(rig["Y0"] == static_cast<unsigned>(y0));
        CHECK(rig["Y1"] == static_cast<unsigned>(y1));
    };
    check({1, 0, 0, 0, 0, 0}, 0, 0);
    check({0, 1, 0, 1, 0, 0}, 1, 0);
    check({1, 0, 1, 0, 0, 1}, 1, 1);
    check({0, 0, 1, 1, 1, 0}, 0, 1);
}

TEST_CASE("logic: runs only in RUN, outside RUN nothing changes and timers do not time", "[scenario][logic]") {
    ScenarioRig rig(rung_file({"LD SM400 INC D0", "LD SM400 OUT T1 K5"}));
    rig.scan(0);
    rig.scan(10);
    CHECK(rig["D0"] == 2);
    rig.cpu.runtime().set_switch(rig.cpu.memory(), devicemodel::RunSwitch::Stop);
    rig.scan_through(20, 1000);
    CHECK(rig["D0"] == 2);
    CHECK(rig["TN1"] == 0);
    rig.cpu.runtime().set_switch(rig.cpu.memory(), devicemodel::RunSwitch::Run);
    rig.scan(1010);
    CHECK(rig["D0"] == 3);
}

TEST_CASE("logic: rung mistakes are refused with the rung's pointer and the fix", "[scenario][logic][loader]") {
    auto fails_with = [](std::initializer_list<const char*> rungs, const std::string& message) {
        CHECK_THROWS_WITH(scenario(rung_file(rungs)), Catch::Contains(message));
    };
    fails_with({"LD X0 OUT Y0", "OUT Y1"}, "test.json: /logic/1: 'OUT': no condition before this output; start the rung with LD");
    fails_with({"LD X0 LD X1 OUT Y0"}, "test.json: /logic/0: 'OUT': 2 open blocks before this output; join them with ANB or ORB");
    fails_with({"LD X0 AND"}, "/logic/0: 'AND': missing device; complete the instruction");
    fails_with({"LD X0 OUT Y0 AND X1"}, "/logic/0: the rung ends without an output");
    fails_with({"LD X0 OUT T0"}, "/logic/0: 'OUT': OUT T0 needs a preset; write e.g. OUT T0 K20");
    fails_with({"LD X0 OUT T0 K10", "LD X1 OUT T0 K5"}, "/logic/1: 'OUT': this timer/counter already has an OUT");
    fails_with({"LD D0 OUT Y0"}, "/logic/0: 'LD': D0 is a word device; name a bit device here");
    fails_with({"LD X0 MOV K1 K2"}, "/logic/0: 'MOV': a constant cannot be a destination");
    fails_with({"LD X0 MOV K99999 D0"}, "K99999 does not fit 16 bits");
    fails_with({"LD X0 JMP P0"}, "/logic/0: 'JMP': unknown instruction");
    fails_with({"LD X0 ORB OUT Y0"}, "'ORB': needs two blocks");
    fails_with({"LD X0 MOV K4M0 D0"}, "not a constant");
}

TEST_CASE("logic: an operand that is neither a device nor a label is refused when the scenario starts",
          "[scenario][logic][loader]") {
    // Not a device, so possibly a label: only the CPU's label table can tell (bind_labels).
    CHECK_THROWS_WITH(ScenarioRig(rung_file({"LD Q0 OUT Y0"})),
                      "test.json: /logic/0: 'Q0' is neither a device nor a global label (no global label or member of "
                      "that name); name a device such as D100, or declare the label in \"labels\" / --labels "
                      "(docs/labels.md)");
    CHECK_THROWS_WITH(ScenarioRig(rung_file({"LD X0 OUT M1G"})), Catch::EndsWith(
                      "as a device: bad device number '1G' in address 'M1G' (M is numbered in decimal); name a device "
                      "such as D100, or declare the label in \"labels\" / --labels (docs/labels.md)"));
}

TEST_CASE("logic: devices past the CPU's sizes are refused when the scenario starts", "[scenario][logic][loader]") {
    CHECK_THROWS_WITH(ScenarioRig(rung_file({"LD X0 OUT M20000"})),
                      "test.json: /logic/0: M20000 is outside the M size of 12288 in profile R08CPU; use a smaller device number or raise device_sizes");
}

TEST_CASE("logic: rungs are compiled by the program engine: its instructions beyond the rung list work",
          "[scenario][logic]") {
    ScenarioRig rig(rung_file({
        "LD X0 MPS AND X1 OUT Y0 MRD AND X2 OUT Y1 MPP OUT Y2",
        "LD SM400 DMOV K100000 D10 + K5 D20",
        "LDP X0 FF M5",
    }));
    set(rig.cpu, "X0", 1);
    set(rig.cpu, "X2", 1);
    rig.scan(0);
    CHECK(rig["Y0"] == 0);
    CHECK(rig["Y1"] == 1);
    CHECK(rig["Y2"] == 1);
    CHECK((rig["D10"] | rig["D11"] << 16) == 100000);
    CHECK(rig["D20"] == 5);   // + s d: d := d + s
    CHECK(rig["M5"] == 1);
}

TEST_CASE("logic: timers follow the CPU rule: the contact moves when OUT T executes", "[scenario][logic]") {
    // The rung before OUT T0 sees its contact one scan after the rung after it.
    ScenarioRig rig(rung_file({"LD T0 OUT Y0", "LD SM400 OUT T0 K1", "LD T0 OUT Y1"}));
    rig.scan(0);
    rig.scan(100);   // OUT T0 sees the 0 ms collected so far
    CHECK(rig["Y1"] == 0);
    rig.scan(200);   // the 100 ms of scan 100 reached the preset at this OUT T0
    CHECK(rig["TN0"] == 1);
    CHECK(rig["Y1"] == 1);
    CHECK(rig["Y0"] == 0);
    rig.scan(300);
    CHECK(rig["Y0"] == 1);
}

TEST_CASE("logic: what only the CPU can tell is refused at start with the rung's pointer", "[scenario][logic][loader]") {
    CHECK_THROWS_WITH(ScenarioRig(rung_file({"LD X0 OUT Y0", "LD X0 LDPI X1 ORB OUT Y1"}), "Q03UDVCPU"),
                      Catch::StartsWith("test.json: /logic/1: 'LDPI' is no instruction of Q03UDVCPU"));
    CHECK_THROWS_WITH(scenario(rung_file({"LD X0 CALL P0"})), Catch::Contains("/logic/0: 'CALL': unknown instruction in the rung language"));
}
