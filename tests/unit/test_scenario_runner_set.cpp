// RunnerSet without sockets: scenarios added and removed at run time, the
// first runner that keeps a request from the CPU decides, ids and names
// unique across runners, each runner on its own clock (scenarios/runner_set.hpp).
#include "config/config.hpp"
#include <deque>

#include "scenarios/incoming.hpp"
#include "scenarios/runner_set.hpp"
#include "support/fixtures.hpp"
#include "support/scenario_fixtures.hpp"

using namespace slmp;
using namespace slmp::test;

namespace {

const Bytes kRead3E = bytes("50 00 00 FF FF 03 00 0C 00 10 00 01 04 00 00 64 00 00 A8 01 00");   // 0401 D100 x1

struct Rig {
    Rig() : cpu(config::load_profile("R08CPU").cpu) {}
    void add(std::vector<std::string> json) {
        std::vector<scenarios::Scenario> list;
        for (const auto& j : json) list.push_back(scenarios::parse_scenario(j, "s" + std::to_string(files++) + ".json"));
        set.add(std::move(list), cpu, nullptr, nullptr);
    }
    scenarios::Plan plan() {
        seen.push_back({engine_for(cpu).decode(kRead3E, protocol::DataCodePolicy::Auto), {}, 0});
        return set.before(seen.back(), kRead3E);
    }
    std::vector<std::string> names() {
        std::vector<std::string> out;
        for (const auto& r : set.running()) out.push_back(r.scenario->name);
        return out;
    }
    devicemodel::Cpu cpu;
    scenarios::RunnerSet set;
    std::deque<scenarios::Incoming> seen;   // each plan's request, alive until after()
    int files = 0;
};

}  // namespace

TEST_CASE("runner set: the first runner that answers decides, later ones do not see the request", "[scenario][runner-set]") {
    Rig rig;
    rig.add({R"({"name": "a", "faults": [{"id": "slow", "do": "delay", "delay_ms": 50}]})"});
    rig.add({R"({"name": "b", "faults": [{"id": "refuse", "do": "end_code", "end_code": "C051"}]})"});
    rig.add({R"({"name": "c", "faults": [{"id": "lost", "do": "no_response"}]})"});
    CHECK(rig.names() == std::vector<std::string>{"a", "b", "c"});
    rig.set.scan(at(0));

    auto p = rig.plan();
    REQUIRE(p.answer);
    CHECK_FALSE(p.silent);
    CHECK(p.decision.fired == std::vector<std::string>{"slow", "refuse"});
    protocol::Outcome outcome;
    rig.set.after(p, outcome, *p.answer);
    CHECK(p.delivery.delay == std::chrono::milliseconds(50));   // a's delay applies to b's answer

    auto stats = rig.set.fault_stats();
    REQUIRE(stats.size() == 3);
    CHECK(stats[0].scenario == "a");
    CHECK(stats[1].fired == 1);
    CHECK(stats[2].matched == 0);   // c never saw it

    CHECK(rig.set.enable_fault("refuse", false));
    CHECK_FALSE(rig.set.enable_fault("nope", false));
    CHECK(rig.plan().silent);   // now c decides
}

TEST_CASE("runner set: names and ids are unique across runners, a rejected add changes nothing", "[scenario][runner-set]") {
    Rig rig;
    rig.add({R"({"name": "a", "faults": [{"id": "f", "do": "no_response"}]})"});
    CHECK_THROWS_WITH(rig.add({R"({"name": "a"})"}),
                      "s1.json: /name: a scenario named 'a' is already running (s0.json); stop that one first or give "
                      "this one another \"name\"");
    CHECK_THROWS_WITH(rig.add({R"({"name": "b", "faults": [{"id": "f", "do": "close"}]})"}),
                      "s2.json: /faults/0/id: fault id 'f' is also used at s0.json: /faults/0; give each fault its own id");
    CHECK(rig.names() == std::vector<std::string>{"a"});
}

TEST_CASE("runner set: stopping a scenario", "[scenario][runner-set]") {
    Rig rig;
    // One group, as --scenario files: a's fault starts at 10 ms by its own trigger.
    rig.add({R"({"name": "a", "faults": [{"id": "f", "do": "no_response", "enabled": false}],
                 "triggers": [{"when": {"at_ms": 10}, "do": [{"start_fault": "f"}]}]})",
             R"({"name": "b", "faults": [{"id": "g", "do": "close", "count": 1}]})"});
    rig.add({R"({"name": "c"})"});
    CHECK_FALSE(rig.set.remove("nope", rig.cpu, nullptr, nullptr));
    rig.set.scan(at(0));
    rig.set.scan(at(20));
    CHECK(rig.plan().silent);   // a's fault, started by its trigger

    CHECK(rig.set.remove("b", rig.cpu, nullptr, nullptr));   // a's group restarts without b: a new clock
    CHECK(rig.names() == std::vector<std::string>{"a", "c"});
    REQUIRE(rig.set.fault_stats().size() == 1);
    CHECK(rig.set.fault_stats()[0].name == "f");
    rig.set.scan(at(100));
    CHECK_FALSE(rig.plan().silent);   // 0 ms on a's new clock: the trigger has not fired yet
    rig.set.scan(at(115));
    CHECK(rig.plan().silent);
    CHECK(rig.set.remove("a", rig.cpu, nullptr, nullptr));
    CHECK(rig.set.remove("c", rig.cpu, nullptr, nullptr));
    CHECK(rig.set.empty());
}
