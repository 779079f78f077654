// ScenarioRunner: one or more loaded scenarios running against a CPU. Pure:
// the server calls scan() after every CPU scan with the scan's time, and
// before() / after() around the engine for every request (its one hook);
// tests do the same on a fake clock. What reaches beyond the CPU (dropping
// connections, closing ports) goes through the Station interface.
//
// Per scan, in this order: pending power-on / end of refusal / pulse ends;
// each timeline; the rung program (RUN only); device and time triggers.
#pragma once

#include <chrono>
#include <memory>
#include <optional>
#include <vector>

#include "devicemodel/cpu.hpp"
#include "protocol/engine.hpp"
#include "scenarios/events.hpp"
#include "scenarios/faults.hpp"
#include "scenarios/logic.hpp"
#include "scenarios/replay.hpp"
#include "scenarios/incoming.hpp"
#include "scenarios/scenario.hpp"
#include "scenarios/timeline.hpp"
#include "scenarios/triggers.hpp"

namespace slmp::scenarios {

// What a scenario may do to the station around the CPU (implemented by the server).
class Station {
public:
    // Power off: every connection drops at once, TCP ports stop accepting and
    // UDP requests go unanswered until power_on().
    virtual void power_off() = 0;
    virtual void power_on() = 0;
    // New TCP connections are refused while `refuse` is true.
    virtual void refuse_connections(bool refuse) = 0;
    // Ondemand 2101 to the clients the action names (`why`: the step or trigger, for logs).
    // (Stations without clients, as in tests, ignore it.)
    virtual void ondemand(const OndemandAction& /*action*/, const std::string& /*why*/) {}
    // A redundant pair's system switch (docs/plants.md, "Redundant pairs"); a
    // station of no pair logs that it has none.
    virtual void system_switch(const std::string& /*why*/) {}

protected:
    ~Station() = default;
};

// What the server does with one request.
struct Plan {
    const Incoming* incoming = nullptr;  // what before() saw; the caller keeps it until after()
    FaultDecision decision;
    // Answer without the CPU: a forced end code or a recorded response.
    std::optional<std::vector<std::uint8_t>> answer;
    std::optional<std::uint8_t> frontend_code;   // a front end answers this code, executing nothing
    bool silent = false;                 // consume the request, send nothing
    bool close = false, reset = false;   // then close the connection (FIN / RST)
    Delivery delivery;
    bool pass() const { return !answer && !silent && !frontend_code; }   // the engine handles it
};

class ScenarioRunner {
public:
    using TimePoint = std::chrono::steady_clock::time_point;

    // Checks every device the scenarios name against the CPU's sizes (throws
    // config::ConfigError naming the file and pointer) and loads replay files.
    ScenarioRunner(std::vector<Scenario> scenarios, devicemodel::Cpu& cpu, EventSink log, Station* station = nullptr);
    ~ScenarioRunner();

    // After each CPU scan, with the scan's time.
    void scan(TimePoint now);

    // Before the engine executes `incoming` (decoded once by the station);
    // `input` starts with the request frame. `incoming` must outlive after().
    Plan before(const Incoming& incoming, std::span<const std::uint8_t> input);
    // After the engine (or the forced answer): traffic triggers, corruption,
    // the delivery plan. `response` may be changed.
    void after(Plan& plan, const protocol::Outcome& outcome, std::vector<std::uint8_t>& response);

    bool powered() const { return powered_; }
    bool refusing() const { return refusing_; }
    // Turns a fault on or off by its stats name (FaultSet::enable); false when there is none.
    bool enable_fault(const std::string& name, bool on) { return faults_.enable(name, on); }
    double now_ms() const { return now_ms_; }
    std::vector<FaultStats> fault_stats() const { return faults_.stats(); }
    const std::vector<Scenario>& scenarios() const { return scenarios_; }

private:
    void run(const Trigger& trigger);
    void replay(Plan& plan, std::span<const std::uint8_t> frame);
    void power_cycle(double off_ms, const std::string& why);
    void refuse(double for_ms, const std::string& why);
    void info(const std::string& text) { if (log_) log_(EventLevel::Info, text); }

    std::vector<Scenario> scenarios_;
    devicemodel::Cpu& cpu_;
    EventSink log_;
    Station* station_;

    std::vector<std::unique_ptr<TimelineRunner>> timelines_;
    std::vector<std::unique_ptr<LogicRunner>> logic_;
    std::vector<std::unique_ptr<ReplayBook>> replays_;
    TriggerSet triggers_;
    FaultSet faults_;
    Rng corruption_rng_;

    bool started_ = false;
    TimePoint start_{}, last_scan_{};
    double now_ms_ = 0;
    bool powered_ = true;
    double power_on_at_ = 0;
    bool refusing_ = false;
    double refuse_until_ = 0;
    struct Pulse { devicemodel::DeviceAddress device; double until_ms; };
    std::vector<Pulse> pulses_;
};

}  // namespace slmp::scenarios
