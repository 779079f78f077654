// Triggers on a fake clock: device conditions (edges, held for N ms), time,
// traffic (command, writes to a range, the N-th request, client address) and
// the actions they start (docs/scenarios.md "Triggers").
#include "protocol/client.hpp"
#include "scenarios/incoming.hpp"
#include "support/fixtures.hpp"
#include "support/scenario_fixtures.hpp"

using namespace slmp;
using namespace slmp::test;

namespace {

// Runs one request through the runner's hook and the real engine, as the server does.
protocol::Outcome handle(ScenarioRig& rig, const std::vector<std::uint8_t>& frame, const std::string& client = "127.0.0.1",
                         std::vector<std::uint8_t>* sent = nullptr) {
    scenarios::Incoming incoming{engine_for(rig.cpu).decode(frame, protocol::DataCodePolicy::Auto),
                                 {protocol::Transport::Tcp, client, 50000, 5000}, 1};
    auto plan = rig.runner->before(incoming, frame);
    protocol::Outcome outcome;
    if (plan.pass()) {
        protocol::Session session;
        outcome = engine_for(rig.cpu).process(frame, protocol::DataCodePolicy::Auto, session);
    } else if (plan.answer) {
        outcome.action = protocol::Outcome::Action::Respond;
        outcome.response = *plan.answer;
    }
    rig.runner->after(plan, outcome, outcome.response);
    if (sent) *sent = outcome.response;
    return outcome;
}

std::vector<std::uint8_t> write_d(std::uint32_t number, std::uint16_t value) {
    std::uint16_t values[] = {value};
    return protocol::client::write_words({}, {devicemodel::find_by_symbol("D"), number}, values);
}

std::vector<std::uint8_t> read_d(std::uint32_t number, std::uint16_t points = 1) {
    return protocol::client::read_words({}, {devicemodel::find_by_symbol("D"), number}, points);
}

}  // namespace

TEST_CASE("triggers: a comparison fires when it turns true, again only after it was false", "[scenario][triggers]") {
    ScenarioRig rig(R"({"triggers": [{"when": "D100 >= 50", "do": [{"increment": "D0"}]}]})");
    rig.scan(0);
    CHECK(rig["D0"] == 0);
    set(rig.cpu, "D100", 50);
    rig.scan(10);
    CHECK(rig["D0"] == 1);
    set(rig.cpu, "D100", 70);
    rig.scan(20);
    CHECK(rig["D0"] == 1);   // still true: no new edge
    set(rig.cpu, "D100", 49);
    rig.scan(30);
    set(rig.cpu, "D100", 51);
    rig.scan(40);
    CHECK(rig["D0"] == 2);
}

TEST_CASE("triggers: held for N ms", "[scenario][triggers]") {
    ScenarioRig rig(R"({"triggers": [{"when": "D100 > D101", "for_ms": 1000, "do": [{"set": {"M1": 1}}]}]})");
    set(rig.cpu, "D100", 5);
    rig.scan_through(0, 990);
    CHECK(rig["M1"] == 0);
    set(rig.cpu, "D101", 9);   // drops out before 1 s: the wait starts over
    rig.scan(1000);
    set(rig.cpu, "D101", 0);
    rig.scan_through(1010, 2000);
    CHECK(rig["M1"] == 0);
    rig.scan(2010);
    CHECK(rig["M1"] == 1);
}

TEST_CASE("triggers: rising and falling edges, a time, and times", "[scenario][triggers]") {
    ScenarioRig rig(R"({"triggers": [
        {"when": {"rising": "X0"}, "do": [{"increment": "D0"}]},
        {"when": {"falling": "X0"}, "times": 1, "do": [{"increment": "D1"}]},
        {"when": {"at_ms": 500}, "do": [{"set": {"D2": 42}}]}
    ]})");
    set(rig.cpu, "X0", 1);
    rig.scan(0);
    CHECK(rig["D0"] == 0);   // an edge needs a change: the first scan only takes the value
    for (int i = 1; i <= 6; ++i) {
        set(rig.cpu, "X0", i % 2 == 0);
        rig.scan(i * 10);
    }
    CHECK(rig["D0"] == 3);
    CHECK(rig["D1"] == 1);   // "times": 1
    CHECK(rig["D2"] == 0);
    rig.scan(505);
    CHECK(rig["D2"] == 42);
    set(rig.cpu, "D2", 0);
    rig.scan(900);
    CHECK(rig["D2"] == 0);   // once
}

TEST_CASE("triggers: actions change the CPU: error, pulse, switch, power cycle", "[scenario][triggers]") {
    ScenarioRig rig(R"({"triggers": [
        {"when": "M0", "do": [{"error": {"code": "3100", "stop": true}}, {"pulse": "Y5", "ms": 100}]},
        {"when": "M1", "do": [{"clear_error": true}]},
        {"when": "M2", "do": [{"power_cycle": {"off_ms": 500}}]},
        {"when": "M3", "do": [{"switch": "STOP"}]},
        {"when": "M4", "do": [{"error": {"code": "2000"}}]}
    ]})");
    rig.scan(0);
    CHECK(rig.cpu.runtime().state() == devicemodel::RunState::Run);
    set(rig.cpu, "M0", 1);
    rig.scan(10);
    CHECK(rig.cpu.runtime().state() == devicemodel::RunState::Stop);
    CHECK(rig["SD0"] == 0x3100);
    CHECK(rig["SM0"] == 1);
    CHECK(rig["Y5"] == 1);
    rig.scan(109);
    CHECK(rig["Y5"] == 1);
    rig.scan(110);
    CHECK(rig["Y5"] == 0);
    set(rig.cpu, "M1", 1);     // a stop error is not cleared like a continuation error (as 1617)...
    rig.scan(120);
    CHECK(rig.cpu.runtime().state() == devicemodel::RunState::Stop);
    set(rig.cpu, "M2", 1);     // ...it takes a power cycle
    rig.scan(130);
    CHECK_FALSE(rig.runner->powered());
    rig.scan(629);
    CHECK_FALSE(rig.runner->powered());
    rig.scan(630);
    CHECK(rig.runner->powered());
    CHECK(rig.cpu.runtime().state() == devicemodel::RunState::Run);
    CHECK(rig["SD0"] == 0);
    CHECK(rig["M2"] == 0);     // M is not latched: cleared by the power cycle
    set(rig.cpu, "M4", 1);
    rig.scan(640);
    CHECK(rig.cpu.runtime().state() == devicemodel::RunState::Run);   // a continuation error keeps running
    CHECK(rig["SD0"] == 0x2000);
    set(rig.cpu, "M1", 0);
    rig.scan(650);
    set(rig.cpu, "M1", 1);
    rig.scan(660);
    CHECK(rig["SD0"] == 0);
    set(rig.cpu, "M3", 1);
    rig.scan(670);
    CHECK(rig.cpu.runtime().state() == devicemodel::RunState::Stop);
    CHECK((rig["SD203"] & 0xF) == 2);
}

TEST_CASE("triggers: traffic — a command, a write to a range, the n-th request, a client", "[scenario][triggers]") {
    ScenarioRig rig(R"({"triggers": [
        {"when": {"writes": "D100-D199"}, "do": [{"increment": "D0"}]},
        {"when": {"command": "0401", "request": 3}, "do": [{"set": {"D1": 1}}]},
        {"when": {"command": "0401", "client": "10.0.0.9"}, "do": [{"increment": "D2"}]}
    ]})");
    rig.scan(0);
    handle(rig, write_d(99, 1));
    CHECK(rig["D0"] == 0);
    handle(rig, write_d(100, 1));
    handle(rig, write_d(199, 1));
    CHECK(rig["D0"] == 2);
    handle(rig, write_d(200, 1));
    handle(rig, write_d(12000, 1));   // out of range: rejected with 4031, so not a write that happened
    CHECK(rig["D0"] == 2);
    handle(rig, read_d(150));          // a read of the range is not a write
    CHECK(rig["D0"] == 2);

    handle(rig, read_d(0));
    CHECK(rig["D1"] == 0);
    handle(rig, read_d(0), "10.0.0.9");
    CHECK(rig["D1"] == 1);             // the third 0401 since start
    CHECK(rig["D2"] == 1);
    set(rig.cpu, "D1", 0);
    handle(rig, read_d(0));
    CHECK(rig["D1"] == 0);             // only the third
}

TEST_CASE("triggers: start and stop a fault", "[scenario][triggers][faults]") {
    ScenarioRig rig(R"({
        "faults": [{"id": "busy", "enabled": false, "do": "end_code", "end_code": "CEE0"}],
        "triggers": [{"when": "M0", "do": [{"start_fault": "busy"}]},
                     {"when": "M1", "do": [{"stop_fault": "busy"}]}]})");
    rig.scan(0);
    CHECK(handle(rig, read_d(0)).end_code == protocol::EndCode::Ok);
    set(rig.cpu, "M0", 1);
    rig.scan(10);
    std::vector<std::uint8_t> sent;
    handle(rig, read_d(0), "127.0.0.1", &sent);
    CHECK(hex(sent) == "D0 00 00 FF FF 03 00 0B 00 E0 CE 00 FF FF 03 00 01 04 00 00");
    set(rig.cpu, "M1", 1);
    rig.scan(20);
    CHECK(handle(rig, read_d(0)).end_code == protocol::EndCode::Ok);
    auto stats = rig.runner->fault_stats();
    REQUIRE(stats.size() == 1);
    CHECK(stats[0].name == "busy");
    CHECK(stats[0].fired == 1);
    CHECK_FALSE(stats[0].enabled);
}
