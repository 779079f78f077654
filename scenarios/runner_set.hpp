// RunnerSet: the ScenarioRunners that run side by side, so a scenario can be
// loaded or stopped while the server runs (HTTP API) without restarting the
// others. The --scenario files form one runner, as they always have (one
// clock, one power state); each scenario loaded later gets a runner of its
// own, whose clock (timeline, time triggers, fault windows) starts when it is
// loaded. A trigger switches faults of its own file only (loader.cpp), so
// no runner depends on another.
//
// A request goes to the runners in load order. The first whose plan keeps it
// from the CPU (a forced answer, a drop) decides; later runners do not see it.
// Every runner that saw it runs after(); the first delivery that is not plain
// wins. With one runner this is exactly that runner's before()/after().
#pragma once

#include <memory>
#include <string>
#include <vector>

#include "scenarios/runner.hpp"

namespace slmp::scenarios {

class RunnerSet {
public:
    using TimePoint = ScenarioRunner::TimePoint;

    // Starts `list` as one more runner. Checks names, fault and trigger ids
    // against the running scenarios and devices against the CPU; throws
    // config::ConfigError naming the file and the fix, and then nothing changed.
    void add(std::vector<Scenario> list, devicemodel::Cpu& cpu, EventSink log, Station* station);
    // Stops every scenario called `name`. One that shares a runner with others
    // restarts that runner without it (their clocks and counts start over).
    // Returns false when none has that name.
    bool remove(const std::string& name, devicemodel::Cpu& cpu, EventSink log, Station* station);

    bool empty() const { return runners_.empty(); }
    // What each runner runs, in load order (a station snapshot keeps this).
    std::vector<std::vector<Scenario>> groups() const;
    // Stops every runner; what they did to the station (power cut, refusal) ends.
    void clear(Station* station);
    void scan(TimePoint now);
    Plan before(const Incoming& incoming, std::span<const std::uint8_t> input);
    void after(Plan& plan, const protocol::Outcome& outcome, std::vector<std::uint8_t>& response);
    // A front end's request (incoming.frontend()): only the faults decide; no
    // replay, no traffic triggers, no after(). The delay is plan.decision.delay_ms.
    Plan before_frontend(const Incoming& incoming);

    // What runs, in load order, with the time since each runner's first scan.
    struct Running {
        const Scenario* scenario;
        double clock_ms;
    };
    std::vector<Running> running() const;
    std::vector<FaultStats> fault_stats() const;
    // By the name fault_stats() gives; false when no fault has it.
    bool enable_fault(const std::string& name, bool on);

private:
    std::vector<Scenario> all() const;   // copies of every running scenario, for checks

    std::vector<std::unique_ptr<ScenarioRunner>> runners_;
    std::vector<Plan> consulted_;   // before() -> after(): the plan of each runner that saw the request
};

}  // namespace slmp::scenarios
