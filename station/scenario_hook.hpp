// The one hook between decode and execute (docs/architecture.md). Station::handle()
// decodes every request, TCP or UDP, once; before() asks the scenarios about
// the decoded Request (forced end code, recorded answer, no response, close,
// reset, power cut); the engine executes it unless the plan answers instead
// (answer()); after() lets the scenarios change the response (corruption,
// delay, split, coalesce), fires traffic triggers and records the exchange
// when --record or --record-pcap is on. With no scenario and no recording
// each is one branch.
#pragma once

#include <chrono>
#include <map>
#include <memory>
#include <optional>
#include <span>
#include <string>
#include <vector>

#include "station/station_log.hpp"
#include "protocol/engine.hpp"
#include "protocol/peer.hpp"
#include "scenarios/faults.hpp"
#include "scenarios/incoming.hpp"
#include "scenarios/runner.hpp"
#include "scenarios/runner_set.hpp"
#include "station/activity.hpp"
#include "station/capture/recorder.hpp"
#include "station/network_map.hpp"

namespace slmp::station {

// What a transport does with one frame.
struct Handled {
    protocol::Outcome outcome;
    scenarios::Delivery delivery;   // how to send outcome.response
    bool reset = false;             // close with RST (SO_LINGER 0) instead of FIN
    // Not served here: a module's port passes the frame of outcome.consumed
    // bytes on to another station (station/network_map.hpp; Relays::pass_on).
    std::optional<Relay> relay;
    // Not served here either: proxy mode sends the frame of outcome.consumed
    // bytes to the station's upstream (Station::pass_on; docs/twin.md, "Proxy").
    bool forward = false;
    // Proxy mode with --compare, timing mode "model": the time the model gave
    // the request, which this station's own answer is compared at.
    std::optional<std::chrono::microseconds> modelled;
};

class ScenarioHook : public ActivityObserver {
public:
    ScenarioHook() = default;
    ~ScenarioHook();
    // Where its lines go: the station's log (station_log.hpp).
    void set_log(std::shared_ptr<spdlog::logger> log) { log_ = std::move(log); }

    // Scenarios start running against `cpu` (checks their devices; throws config::ConfigError).
    void start(std::vector<scenarios::Scenario> scenarios, devicemodel::Cpu& cpu, scenarios::Station& station);
    // Scenarios loaded later (HTTP API) run against this CPU and station;
    // start() attaches its own. The station attaches them even with no --scenario.
    void attach(devicemodel::Cpu& cpu, scenarios::Station& station);
    // Starts one more scenario while the server runs, with its initial devices,
    // switch and error applied now (throws config::ConfigError, and then nothing changed).
    void load(scenarios::Scenario scenario);
    // Stops every scenario called `name`; false when none is.
    bool stop(const std::string& name);
    std::vector<scenarios::RunnerSet::Running> scenarios() const { return runners_.running(); }
    // Every running scenario by runner, and putting such a list back: what
    // runs now stops, the list starts afresh (clocks from 0, faults as loaded,
    // no initial state applied). For station snapshots (station_snapshot.cpp).
    std::vector<std::vector<scenarios::Scenario>> scenario_groups() const { return runners_.groups(); }
    void replace_scenarios(std::vector<std::vector<scenarios::Scenario>> groups);
    // By the name fault_stats() gives; false when there is no such fault.
    bool enable_fault(const std::string& name, bool on) { return runners_.enable_fault(name, on); }

    // Records every exchange to `file` as JSON lines from now on (throws
    // config::ConfigError, also when a JSON-lines recording already runs).
    void record(const std::string& file, const std::string& profile);
    // The JSON-lines recording's file (--record or the HTTP API); empty when off.
    const std::string& recording_file() const { return recording_file_; }
    // Ends that recording: the file is flushed and closed. False when none runs.
    bool stop_recording();
    // Captures every exchange to `file` as pcap (--record-pcap), with `bind` as the simulator's address.
    void record_pcap(const std::string& file, const std::string& bind);

    // Before the engine: what the scenarios want done with `incoming`, whose
    // peer and connection ordinal it fills when a scenario will look at them.
    // `incoming` must stay alive until after().
    scenarios::Plan before(scenarios::Incoming& incoming, std::span<const std::uint8_t> input,
                           const protocol::Session& session, const protocol::Peer& peer);
    // The outcome a plan gives instead of the engine's (plan.pass() is false).
    protocol::Outcome answer(scenarios::Plan& plan, const protocol::Request& request) const;
    // After the engine or the answer: triggers, corruption, the delivery, recording.
    void after(scenarios::Plan& plan, Handled& handled, std::span<const std::uint8_t> input,
               const protocol::Session& session, const protocol::Peer& peer);
    // A front end's request (incoming.frontend()), once its command is known:
    // what the faults want done (station/frontend_call.cpp). `session` is its TCP connection id.
    scenarios::Plan frontend_before(scenarios::Incoming& incoming, std::uint64_t session);
    // A front end's exchange, to the JSON-lines recording.
    void frontend_recorded(const FrontEndRecord& record);
    // After every CPU scan (station/scan_loop.cpp).
    void scanned(std::chrono::steady_clock::time_point now);

    bool active() const { return !runners_.empty() || !recorders_.empty(); }
    // A scenario runs: it acts at every scan (timelines, triggers, rungs, fault windows).
    bool running() const { return !runners_.empty(); }
    // Every fault: how often it matched and fired (for logs and the HTTP API).
    std::vector<scenarios::FaultStats> fault_stats() const;
    // One log line per fault that fired, at shutdown.
    void log_summary() const;

    void on_opened(const Connection& connection) override;
    void on_closed(const Connection& connection, std::string_view why) override;
    void on_pushed(const PushRecord& push) override;   // recorded as an "ondemand" event

private:
    scenarios::EventSink event_sink() const;   // the runners' lines, into log_

    std::shared_ptr<spdlog::logger> log_ = process_logger();
    scenarios::RunnerSet runners_;
    devicemodel::Cpu* cpu_ = nullptr;              // attach()
    scenarios::Station* station_ = nullptr;
    Recorder* recording_ = nullptr;     // the JSON-lines one of recorders_
    std::string recording_file_;
    std::vector<std::unique_ptr<Recorder>> recorders_;   // --record, --record-pcap
    std::map<std::uint64_t, std::uint64_t> ordinals_;   // TCP connection id -> n-th connection since start
    std::uint64_t connections_ = 0;
};

}  // namespace slmp::station
