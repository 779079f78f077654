// Scenarios naming global labels (docs/scenarios.md "Labels"): timeline steps,
// "set", trigger conditions, edges and increments, on labels assigned to a
// device and on labels in the label area; and the start-up errors.
#include <bit>

#include "support/scenario_fixtures.hpp"

using namespace slmp;
using namespace slmp::test;

namespace {

const char* kLabels = R"J({"labels": [
    {"name": "LabelW", "type": "Word [Signed]", "device": "D9000"},
    {"name": "Level", "type": "FLOAT [Single Precision]"},
    {"name": "Count", "type": "Double Word [Signed]"},
    {"name": "Alarm", "type": "Bit"},
    {"name": "Start", "type": "Bit", "device": "M100"},
    {"name": "Speeds", "type": "Word [Signed](0..9)"},
    {"name": "Name", "type": "String(8)"},
    {"name": "Hidden", "type": "Word [Signed]", "external": false}]})J";

// A label's words as the label commands carry them.
std::vector<std::uint16_t> words(const devicemodel::Cpu& cpu, const std::string& name) {
    devicemodel::LabelFault fault{};
    auto ref = cpu.labels().resolve(name, {}, fault, false);
    REQUIRE(ref);
    return devicemodel::read_element(cpu.memory(), *ref, 0);
}
std::int32_t dint(const devicemodel::Cpu& cpu, const std::string& name) {
    auto w = words(cpu, name);
    return static_cast<std::int32_t>(w[0] | std::uint32_t(w[1]) << 16);
}
float real(const devicemodel::Cpu& cpu, const std::string& name) {
    auto w = words(cpu, name);
    return std::bit_cast<float>(w[0] | std::uint32_t(w[1]) << 16);
}

std::string start_error(const std::string& scenario_json) {
    try {
        ScenarioRig rig(scenario_json, "R08CPU", kLabels);
    } catch (const config::ConfigError& e) {
        return e.what();
    }
    return "(no error)";
}

}  // namespace

TEST_CASE("scenario labels: set and ramp write labels on a device and in the label area", "[scenario][labels]") {
    ScenarioRig rig(R"({"timeline": {"steps": [
        {"at_ms": 0, "set": {"LabelW": -5, "Alarm": true, "Speeds[3]": 70, "D0": 9}},
        {"at_ms": 0, "ramp": "Level", "from": 0, "to": 100, "over_ms": 1000},
        {"at_ms": 0, "ramp": "Count", "from": 0, "to": 100000, "over_ms": 1000}]}})",
                    "R08CPU", kLabels);
    rig.scan(0);
    CHECK(rig["D9000"] == 0xFFFB);   // LabelW is D9000: the same memory
    CHECK(words(rig.cpu, "LabelW") == std::vector<std::uint16_t>{0xFFFB});
    CHECK(words(rig.cpu, "Alarm") == std::vector<std::uint16_t>{1});
    CHECK(words(rig.cpu, "Speeds[3]") == std::vector<std::uint16_t>{70});
    CHECK(words(rig.cpu, "Speeds[2]") == std::vector<std::uint16_t>{0});
    CHECK(rig["D0"] == 9);
    rig.scan(500);
    CHECK(real(rig.cpu, "Level") == Approx(50.0f));
    CHECK(dint(rig.cpu, "Count") == 50000);   // two words, beyond 16 bits
    rig.scan(1000);
    CHECK(real(rig.cpu, "Level") == Approx(100.0f));
    CHECK(dint(rig.cpu, "Count") == 100000);
}

TEST_CASE("scenario labels: a trigger compares labels and sets and increments labels", "[scenario][labels]") {
    ScenarioRig rig(R"({"triggers": [
        {"when": "Level >= 50.5", "do": [{"set": {"Alarm": 1}}, {"increment": "Count", "by": 70000}]},
        {"when": "LabelW > Speeds[0]", "do": [{"increment": "D1"}]}]})",
                    "R08CPU", kLabels);
    rig.scan(0);
    CHECK(words(rig.cpu, "Alarm") == std::vector<std::uint16_t>{0});
    std::uint16_t level[2];
    auto bits = std::bit_cast<std::uint32_t>(50.5f);
    level[0] = bits & 0xFFFF, level[1] = bits >> 16;
    devicemodel::LabelFault fault{};
    devicemodel::write_element(rig.cpu.memory(), *rig.cpu.labels().resolve("Level", {}, fault), 0, level);
    rig.scan(10);
    CHECK(words(rig.cpu, "Alarm") == std::vector<std::uint16_t>{1});
    CHECK(dint(rig.cpu, "Count") == 70000);
    CHECK(rig["D1"] == 0);
    set(rig.cpu, "D9000", 3);   // LabelW through its device
    rig.scan(20);
    CHECK(rig["D1"] == 1);
}

TEST_CASE("scenario labels: rising on a Bit label assigned to M100", "[scenario][labels]") {
    ScenarioRig rig(R"({"triggers": [{"when": {"rising": "Start"}, "do": [{"increment": "LabelW"}]}]})", "R08CPU", kLabels);
    rig.scan(0);
    set(rig.cpu, "M100", 1);
    rig.scan(10);
    CHECK(rig["D9000"] == 1);
    rig.scan(20);
    CHECK(rig["D9000"] == 1);   // an edge, not a level
}

TEST_CASE("scenario labels: the simulator drives labels without external access", "[scenario][labels]") {
    ScenarioRig rig(R"({"timeline": {"steps": [{"at_ms": 0, "set": {"Hidden": 12}}]}})", "R08CPU", kLabels);
    rig.scan(0);
    CHECK(words(rig.cpu, "Hidden") == std::vector<std::uint16_t>{12});
}

TEST_CASE("scenario labels: names that do not resolve stop the start with the pointer and the fix", "[scenario][labels]") {
    CHECK(start_error(R"({"timeline": {"steps": [{"at_ms": 0, "ramp": "Nope", "from": 0, "to": 1, "over_ms": 10}]}})") ==
          "test.json: /timeline/steps/0: 'Nope' is neither a device nor a global label (no global label or member of "
          "that name); name a device such as D100, or declare the label in \"labels\" / --labels "
          "(docs/labels.md)");
    CHECK(start_error(R"({"triggers": [{"when": "Speeds[10] > 0", "do": [{"increment": "D0"}]}]})") ==
          "test.json: /triggers/0/when: 'Speeds[10]' is neither a device nor a global label (an element index is past "
          "the end of the array); name a device such as D100, or declare the label in \"labels\" / --labels "
          "(docs/labels.md)");
    CHECK_THAT(start_error(R"({"timeline": {"steps": [{"at_ms": 0, "increment": "D1O0"}]}})"),
               Catch::EndsWith("; as a device: bad device number '1O0' in address 'D1O0' (D is numbered in decimal); "
                               "name a device such as D100, or declare the label in \"labels\" / --labels (docs/labels.md)"));
    CHECK(start_error(R"({"timeline": {"steps": [{"at_ms": 0, "set": {"Name": 1}}]}})") ==
          "test.json: /timeline/steps/0/set/Name: label 'Name' is of type String(8), which a scenario cannot write "
          "numbers to; drive a Bit, Word, Double Word, FLOAT [Single Precision] or Time label (or an element or member "
          "of one)");
    CHECK(start_error(R"({"triggers": [{"when": {"falling": "LabelW"}, "do": [{"increment": "D0"}]}]})") ==
          "test.json: /triggers/0/when: label 'LabelW' is of type Word [Signed], not Bit; name a Bit label or a bit "
          "device for \"rising\" / \"falling\"");
}

TEST_CASE("scenario labels: load errors for labels are found before the CPU is known", "[scenario][labels]") {
    auto load_error = [](const std::string& json) -> std::string {
        try {
            scenario(json);
        } catch (const config::ConfigError& e) {
            return e.what();
        }
        return "(no error)";
    };
    CHECK(load_error(R"({"timeline": {"steps": [{"increment": "Count", "as": "int32"}]}})") ==
          "test.json: /timeline/steps/0/as: \"as\" applies to devices; 'Count' is a label, whose type gives the "
          "format; remove \"as\"");
    CHECK(load_error(R"({"timeline": {"steps": [{"set": {"Level": [1, 2]}}]}})") ==
          "test.json: /timeline/steps/0/set/Level: 'Level' is a label (no device is named so); a label takes one "
          "number; write e.g. {\"Level\": 50}, or name a device such as D100");
    CHECK_THAT(load_error(R"({"timeline": {"steps": [{"increment": "9D"}]}})"),
               Catch::StartsWith("test.json: /timeline/steps/0/increment: "));
}

TEST_CASE("scenario labels: the rung logic reads and writes Bit and Word labels", "[scenario][labels][logic]") {
    ScenarioRig rig(R"({"logic": ["LD Start OR Alarm OUT Alarm",
                                  "LD>= LabelW K5 MOV K7 Speeds[1]",
                                  "LDP Alarm INC LabelW",
                                  "LD M0 RST LabelW RST Alarm"]})",
                    "R08CPU", kLabels);
    rig.scan(0);
    CHECK(words(rig.cpu, "Alarm") == std::vector<std::uint16_t>{0});
    set(rig.cpu, "M100", 1);   // Start is M100
    rig.scan(10);
    CHECK(words(rig.cpu, "Alarm") == std::vector<std::uint16_t>{1});   // label-area bit, latched through OR Alarm
    CHECK(rig["D9000"] == 1);                                           // INC LabelW on the rising edge of Alarm
    set(rig.cpu, "M100", 0);
    set(rig.cpu, "D9000", 5);
    rig.scan(20);
    CHECK(words(rig.cpu, "Alarm") == std::vector<std::uint16_t>{1});
    CHECK(words(rig.cpu, "Speeds[1]") == std::vector<std::uint16_t>{7});
    set(rig.cpu, "M0", 1);
    rig.scan(30);
    CHECK(rig["D9000"] == 0);   // RST of a Word label clears it
    CHECK(words(rig.cpu, "Alarm") == std::vector<std::uint16_t>{0});
}

TEST_CASE("scenario labels: rungs reach 32-bit labels in the label area through the engine", "[scenario][labels][logic]") {
    ScenarioRig rig(R"({"logic": ["LD SM400 DMOV K100000 Count DINC Count"]})", "R08CPU", kLabels);
    rig.scan(0);
    CHECK(dint(rig.cpu, "Count") == 100001);
    CHECK_THAT(start_error(R"({"logic": ["LD SM400 DMOV K1 Level"]})"),
               Catch::StartsWith("test.json: /logic/0: label 'Level' is of type FLOAT [Single Precision]; 'DMOV' needs a "
                                 "Double Word or Time label here"));
}

TEST_CASE("scenario labels: rung operands of the wrong type or unknown stop the start", "[scenario][labels][logic]") {
    CHECK(start_error(R"({"logic": ["LD LabelW OUT Y0"]})") ==
          "test.json: /logic/0: label 'LabelW' is of type Word [Signed], where the rung needs a bit; name a Bit label "
          "or a bit device here");
    CHECK(start_error(R"({"logic": ["LD X0 MOV Count D0"]})") ==
          "test.json: /logic/0: label 'Count' is of type Double Word [Signed], where the rung needs a 16-bit word; "
          "name a Word [Signed] or Word [Unsigned] label, or a word device");
    CHECK_THAT(start_error(R"({"logic": ["LD X0 OUT Motor"]})"),
               Catch::StartsWith("test.json: /logic/0: 'Motor' is neither a device nor a global label"));
}
