// Loading scenario files: every shipped example loads and fits its CPU, and
// each kind of mistake gives its message — the file, the JSON pointer and the
// fix. The list of mistakes (tests/data/scenario_mistakes.json) is shared with
// the schema test (tests/schema/check_scenarios.py), which checks that
// schema.json rejects the same documents where a schema can.
#include <filesystem>

#include <nlohmann/json.hpp>

#include "support/files.hpp"
#include "support/scenario_fixtures.hpp"

using namespace slmp;
using namespace slmp::test;

TEST_CASE("scenario loader: each kind of mistake names the file, the pointer and the fix", "[scenario][loader]") {
    auto list = nlohmann::json::parse(read_text(std::filesystem::path(SLMP_SOURCE_DIR) / "tests/data/scenario_mistakes.json"));
    REQUIRE(list.size() >= 30);
    for (const auto& item : list) {
        auto text = item.contains("text") ? item["text"].get<std::string>() : item["doc"].dump();
        auto message = item["message"].get<std::string>();
        INFO(item["what"].get<std::string>() << ": " << text);
        if (item.value("runner", false))
            CHECK_THROWS_WITH(ScenarioRig(text), Catch::Contains(message));
        else
            CHECK_THROWS_WITH(scenario(text), Catch::Contains(message));
    }
}

TEST_CASE("scenario loader: every shipped example loads and fits its CPU", "[scenario][loader][examples]") {
    std::size_t examples = 0;
    for (const auto& entry : std::filesystem::directory_iterator(std::filesystem::path(SLMP_SOURCE_DIR) / "scenarios/examples")) {
        if (entry.path().extension() != ".json") continue;
        INFO(entry.path().string());
        auto s = scenarios::load_scenario(entry.path());
        CHECK_FALSE(s.description.empty());
        devicemodel::Cpu cpu(config::load_profile("R08CPU").cpu);
        std::vector<scenarios::Scenario> list{s};
        CHECK_NOTHROW(scenarios::ScenarioRunner(std::move(list), cpu, nullptr));
        ++examples;
    }
    CHECK(examples >= 6);
}

TEST_CASE("scenario loader: defaults and the values it reads", "[scenario][loader]") {
    auto s = scenario(R"({"timeline": {"steps": [{"ramp": "D0", "from": 1, "to": 2, "over_ms": 100},
                                                  {"after_ms": 50, "set": {"M0": true}}]},
                          "faults": [{"do": "delay", "delay_ms": 5, "match": {"devices": "X0-X1F"}}]})");
    CHECK(s.name == "test");
    CHECK(s.seed == 1);
    REQUIRE(s.timeline.steps.size() == 2);
    CHECK(s.timeline.steps[1].start_ms == 150);   // after the ramp's end, plus 50
    CHECK(s.timeline.loops == 1);
    REQUIRE(s.faults.size() == 1);
    CHECK(s.faults[0].enabled);
    CHECK(s.faults[0].match.devices[0].last == 0x1F);
    CHECK(s.faults[0].action.delay_min_ms == 5);
}

TEST_CASE("scenario loader: ids must be unique across files", "[scenario][loader]") {
    std::vector<scenarios::Scenario> list{scenarios::parse_scenario(R"({"faults": [{"id": "a", "do": "close"}]})", "one.json"),
                                          scenarios::parse_scenario(R"({"faults": [{"id": "a", "do": "reset"}]})", "two.json")};
    CHECK_THROWS_WITH(scenarios::check_together(list),
                      "two.json: /faults/0/id: fault id 'a' is also used at one.json: /faults/0; give each fault its own id");
}

TEST_CASE("scenario loader: a missing file names the option", "[scenario][loader]") {
    CHECK_THROWS_WITH(scenarios::load_scenario("/nonexistent/plant.json"),
                      "/nonexistent/plant.json: cannot open the scenario file; check the path given to --scenario");
}
