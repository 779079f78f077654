// One simulated controller: the CPU set (CPU No.1 and the other CPUs of a
// multi-CPU rack), the protocol engine in front of it, the scenario hook and
// recording around the engine, the scan cycle, persistence and the activity
// reports. Every transport hands each request to handle(). Everything runs on
// the station's strand (station::Home), so none of this needs a lock (docs/plants.md,
// "Threads"); a connection's reads and writes may run on other threads meanwhile.
#pragma once

#include <atomic>
#include <cstdint>
#include <memory>
#include <optional>
#include <chrono>
#include <functional>
#include <span>
#include <string_view>
#include <vector>

#include "station/asio.hpp"

#include "config/config.hpp"
#include "devicemodel/cpu.hpp"
#include "protocol/differential.hpp"
#include "protocol/engine.hpp"
#include "protocol/peer.hpp"
#include "station/activity.hpp"
#include "station/redundant_pair.hpp"
#include "station/scenario_hook.hpp"
#include "station/station_log.hpp"
#include "station/transports.hpp"

namespace slmp::frontends { class Unit; }

namespace slmp::station {

class Comparison;
class CpuProgram;
class LinkScan;
class DriveState;
class Persistence;
class ResponseTiming;
class ScanLoop;
class ScenarioStation;
struct StationSnapshot;
class Upstream;
struct UpstreamAnswer;

// When a request held for the clock (the end_of_scan and model timing
// modes, docs/timing.md) is served: the station decides (station/inbox.hpp
// holds the request meanwhile), then serves it with this.
struct Service {
    std::chrono::steady_clock::time_point at;            // CPU time
    bool timed_out = false;                              // the monitoring timer ran out first: CF71, not executed
    std::optional<std::chrono::microseconds> modelled;   // model mode: the modelled time (metrics)
};

// The first whole request held bytes start with (Station::next_request).
struct Queued {
    std::size_t start = 0;                // bytes the port skips before it (0: it starts the input)
    std::size_t end = 0;                  // bytes from the start of the input to its end
    std::chrono::milliseconds timer{0};   // its monitoring timer (0: none or waits forever)
    bool too_large = false;               // its length field is past the maximum: refused at once, not held
};

// model: one request taken out of the transport's bytes, decoded once, with
// the time the model gives it (Station::schedule). Move-only: `request`
// points into `bytes`, whose buffer moves with it.
struct Ticket {
    std::vector<std::uint8_t> bytes;
    protocol::DataCodePolicy policy = protocol::DataCodePolicy::Auto;
    protocol::Request request;
    std::optional<Service> service;   // nullopt: served at once (no command to model)

    Ticket() = default;
    Ticket(Ticket&&) = default;
    Ticket& operator=(Ticket&&) = default;
    Ticket(const Ticket&) = delete;
    Ticket& operator=(const Ticket&) = delete;
};

class Station {
public:
    // A bare station: CPU No.1 and its engine, no scan cycle, no state
    // directory, no scenarios (unit tests).
    Station(config::Profile profile, protocol::EngineOptions options);
    // The controller the configuration describes: its profile, the initial
    // values (with the --scenario files' initial state), modules and networks,
    // CPU No.2–4, the "cpu" parameters, the scan cycle and the state directory
    // (restored now). Throws config::ConfigError naming the problem.
    Station(const station::Home& home, const config::ServerConfig& config);
    ~Station();
    Station(const Station&) = delete;
    Station& operator=(const Station&) = delete;

    // Once the transports exist: recordings and scenarios start (a scenario's
    // power cut acts on `transports`, which must outlive the station's use).
    void connect(Transports& transports);
    // Then, before the io_context runs: the state POST /api/reset returns to,
    // and --snapshot's file applied. Touches this station alone, so a plant
    // takes its stations' snapshots on all cores at once (server.cpp).
    void take_initial_snapshot();                                 // station_snapshot.cpp
    void start();   // the scan cycle and interval snapshots
    void stop();    // at shutdown: the scan stops, faults are summed up, a last snapshot is saved

    // One request frame from any transport: the scenario hook and the engine
    // handle it, it is logged and reported to the activity observers (not when
    // the input holds no whole frame yet: NeedMore). The transports serve
    // through station/inbox.hpp, which calls these when the timing mode says.
    // `service`: end_of_scan, the END (or monitoring timer) that serves it; a
    // timed-out request is answered CF71 (1E: 60) and not executed.
    Handled handle(std::span<const std::uint8_t> input, protocol::DataCodePolicy policy, protocol::Session& session,
                   const protocol::Peer& peer, const Service* service = nullptr);
    // model: a request schedule() decoded, at its time.
    Handled handle(Ticket& ticket, protocol::Session& session, const protocol::Peer& peer);
    // The first whole request in `input`, after bytes the port would skip;
    // nullopt while none is whole. Frames, does not decode.
    std::optional<Queued> next_request(std::span<const std::uint8_t> input, protocol::DataCodePolicy policy) const;
    // model: the whole request `frame`, which arrived at `arrival` (CPU time),
    // decoded, and when it is executed and answered — arrival + the modelled
    // time, or + its monitoring timer when that runs out first. Draws the
    // next jitter value, so call it in arrival order.
    Ticket schedule(std::vector<std::uint8_t> frame, protocol::DataCodePolicy policy, const protocol::Session& session,
                    std::chrono::steady_clock::time_point arrival);
    // A plant's networks (station/network_map.hpp): a request naming another
    // station on a module's port (the profile's "relays") goes where the
    // network map says. Set before the io_context runs; without it such a request
    // gets 4A01/4A02 as on a lone station.
    // Its link scan starts sending its LB/LW (station/link_scan.hpp).
    void join(const NetworkMap& networks);
    const NetworkMap* network_map() const { return network_map_; }
    // A redundant pair's system switch (docs/plants.md, "Redundant pairs"): by
    // the HTTP API and the scenario action. Empty when it switched, else why not.
    std::string system_switch(const std::string& why);
    // A scenario's power cut and return: the pair's CPU is down or up again; the
    // control system's power cut switches the systems.
    void powered(bool on);
    // A redundant pair switched (RedundantPair::switch_over posts it to both
    // CPUs' strands): this CPU acts in the new epoch and shows its new role in
    // its SM/SD (station_redundancy.cpp).
    void pair_switched();
    // Its home strand (a bare station has none: no relays reach it).
    const Home& home() const { return *home_; }
    bool has_home() const { return home_.has_value(); }
    // A request a route brought here (Relays::pass_on), on this station's
    // strand: served in this station's timing mode with `session`, this
    // connection's session here (made on first use: routed, without the
    // remote password, which the receiving port checks).
    StrandTask<Handled> serve_routed(std::vector<std::uint8_t> frame, protocol::DataCodePolicy policy,
                                     std::optional<protocol::Session>& session, protocol::Peer peer);
    // A request this station passes on to another (Relays::pass_on), on its
    // strand: its passing-on time (model: its Ke, on its clock; not for the
    // receiving station, whose timing mode held the request already) and its
    // scenario faults — a forced end code or a drop answers here instead
    // (nullopt: passed on), a delay holds it.
    StrandTask<std::optional<Handled>> pass_through(std::vector<std::uint8_t> frame, protocol::DataCodePolicy policy,
                                                    protocol::Peer peer, bool receiving);
    // A request handle() left for elsewhere (Handled::relay: another station
    // of the plant; Handled::forward: the upstream, in proxy mode), its
    // `frame`, carried there; its answer. From any strand; `session` is the
    // connection's, which waits for the answer meanwhile.
    StrandTask<Handled> pass_on(Handled pending, std::vector<std::uint8_t> frame, protocol::DataCodePolicy policy,
                                Relays& relays, protocol::Session& session, protocol::Peer peer);
    // Proxy mode (docs/twin.md, "Proxy"): null when the station serves from its own memory.
    Upstream* upstream() { return upstream_.get(); }
    // Differential mode (--compare; docs/twin.md, "Compare"): its counts and
    // last differences; null without it.
    Comparison* comparison() { return comparison_.get(); }
    // Waits `timer` on this station's clock (a relay that got no answer, a
    // delay on the way, a face's timer). `wanted`, when given, is asked at
    // every END and ends the wait early once false; stop_waiting() makes the
    // waits ask at once (a relay's monitoring timer when the answer came).
    StrandTask<> wait_on_clock(std::chrono::microseconds timer, std::function<bool()> wanted = {});
    // On its strand: the waits on its clock look again at their conditions.
    void stop_waiting();
    // Whether a request is served as soon as it is whole (instant timing):
    // then a transport may serve on its own strand and skip the clock.
    bool serves_at_once() const { return !scan_ || timing_mode_ == config::TimingMode::Instant; }
    // end_of_scan: how a request that arrived at `arrival` with `timer` is
    // served at CPU time `now`, `at_end` telling whether `now` is the END that
    // serves it; nullopt: not yet (it waits for that END).
    static std::optional<Service> end_of_scan_service(std::chrono::steady_clock::time_point arrival,
                                                      std::chrono::milliseconds timer,
                                                      std::chrono::steady_clock::time_point now, bool at_end);
    // Ondemand 2101 (docs/timing.md): the words of `action`'s devices, now,
    // framed in each client's shape, to the clients its `to` names; recorded
    // and reported to the activity observers. Returns what was sent to whom
    // (empty: no client). Throws config::ConfigError for devices past the
    // CPU's sizes or an unknown target.
    struct Pushed {
        std::uint64_t connection = 0;
        protocol::Peer peer;
        std::vector<std::uint8_t> frame;
    };
    std::vector<Pushed> ondemand(const scenarios::OndemandAction& action, const std::string& why);
    // Called by a transport after a Remote RESET (Outcome::Action::Restart) was
    // answered: the CPU has restarted, every connection closes.
    void restart();
    // A new protocol session's id (a TCP connection, a UDP port's session).
    std::uint64_t next_session_id() { return next_session_id_++; }
    // A new protocol session for a connection on `port`: a fresh id and the
    // port's settings (remote password, online change), with the profile's
    // defaults where the port sets none.
    protocol::Session new_session(const config::PortConfig& port);

    // With a state directory: saves a snapshot now (false on failure).
    bool has_state_directory() const { return persistence_ != nullptr; }
    bool save_snapshot(std::string_view why);

    // The whole station now, and back to it (station/station_snapshot.hpp).
    // restore() throws config::ConfigError for a snapshot of another
    // configuration. Connections stay open unless `drop_connections`.
    StationSnapshot snapshot();
    void restore(const StationSnapshot& snapshot, bool drop_connections);
    // Back to the state connect() started in: the configuration's initial
    // values and the --scenario files, before --snapshot was applied.
    void reset(bool drop_connections);

    // The scan cycle and its virtual clock (station/scan_loop.hpp); null in a bare station.
    ScanLoop* scan_loop() { return scan_.get(); }
    // Before anything outside the station's own requests reads or changes it
    // (the HTTP API, a front end): the scans due by now run
    // (ScanLoop::catch_up). After something changed it: touched() wakes the
    // scan loop at the next scan (ScanLoop::touched). No-ops in a bare station.
    void catch_up();
    void touched();
    // When requests are served (docs/timing.md). Instant in a bare station.
    // With end_of_scan a request waits for the END after its arrival (or its
    // monitoring timer), so it executes at END; with model, for schedule()'s time.
    config::TimingMode timing_mode() const { return timing_mode_; }
    const config::TimingModel& timing_model() const { return timing_model_; }

    // CPU No.1's PLC program (station/cpu_program.hpp); null in a bare station.
    CpuProgram* program() { return program_.get(); }
    devicemodel::Cpu& cpu() { return cpu_; }
    const devicemodel::Cpu& cpu() const { return cpu_; }
    // The protocol faces' units serving this station's memory (frontends/face.hpp),
    // registered by the transports that own them (server/listeners.cpp) and
    // cleared when those stop; empty: none. The HTTP API resolves their address
    // names through them; snapshots and the state directory keep their unit state.
    using FrontEnds = std::vector<frontends::Unit*>;
    FrontEnds& frontends() { return frontends_; }
    // Registers them (before connect(), so the initial snapshot holds their
    // state) and, with a state directory, restores what it saved of them.
    // Throws config::ConfigError when that does not fit this configuration.
    void attach_frontends(FrontEnds frontends);
    const FrontEnds& frontends() const { return frontends_; }
    protocol::Engine& engine() { return engine_; }
    Activity& activity() { return activity_; }   // requests and connections, for metrics and the HTTP API
    // Scenarios and recording: the one hook around the engine (station/scenario_hook.hpp).
    ScenarioHook& scenario() { return scenario_; }
    const ScenarioHook& scenario() const { return scenario_; }
    // Its log: lines start with the station's name in a plant (station_log.hpp).
    spdlog::logger& log() const { return *log_; }
    // Whether a scenario is for this station: it names no stations, this
    // station has no name (a lone station), or one of its patterns matches.
    bool runs(const scenarios::Scenario& s) const;

private:
    // Calls touched() when the scope that may change the station ends, on every path.
    struct TouchedAtExit {
        Station& station;
        ~TouchedAtExit() { station.touched(); }
    };
    void start_cpu_runtime(const station::Home& home);          // "cpu" parameters, scan cycle, state directory
    std::vector<scenarios::Scenario> load_scenarios();
    void start_scenarios(std::vector<scenarios::Scenario> list);
    std::vector<devicemodel::Cpu*> all_cpus();
    // The monitoring timer's answer: CF71 (1E: 60), nothing executed.
    static protocol::Outcome timed_out(const protocol::Request& request, std::chrono::milliseconds timer);
    // A request for another station (Request::elsewhere): its answer when the
    // network map finds no way (the request's route_error becomes the map's
    // code) or finds this station (decoded again, as routed here); a Handled
    // with `relay` when another station serves it.
    std::optional<Handled> route(protocol::Request& request, std::span<const std::uint8_t> input,
                                 protocol::DataCodePolicy policy);
    // Proxy mode: a whole request frame goes to the upstream (a Handled with
    // `forward`); nullopt: served here (no upstream, or no whole frame).
    std::optional<Handled> to_upstream(const protocol::Request& request) const;
    // On this station's strand: the scenario hook around the upstream's
    // answer instead of the engine, then the log, recording and activity.
    // With --compare the request is served here too (serve_twin) and the two
    // answers compared; `modelled`: its time in timing mode "model".
    StrandTask<Handled> forward(std::vector<std::uint8_t> frame, protocol::DataCodePolicy policy, protocol::Session& session,
                                protocol::Peer peer, std::optional<std::chrono::microseconds> modelled = std::nullopt);
    // Differential mode: `frame` served from this station's own memory by its
    // own profile's port (twin_engine_), as without an upstream, and what a
    // client would have seen. `request`: the frame as forward() decoded it.
    // Differential mode: the upstream's `answer` and the twin's to the same
    // request, into the report (comparison_).
    void compare(std::span<const std::uint8_t> frame, protocol::DataCodePolicy policy, const protocol::Request& request,
                 const UpstreamAnswer& answer, protocol::Session& session, const protocol::Peer& peer,
                 std::optional<std::chrono::microseconds> modelled);
    protocol::differential::Observed serve_twin(std::span<const std::uint8_t> frame, protocol::DataCodePolicy policy,
                                                const protocol::Request& request, protocol::Session& session,
                                                const protocol::Peer& peer, std::optional<std::chrono::microseconds> modelled);
    // handle()'s body, for a request decoded from `input` (once).
    Handled serve(protocol::Request request, std::span<const std::uint8_t> input, protocol::Session& session,
                  const protocol::Peer& peer, const Service* service);

    config::ServerConfig config_;   // with the scenarios' initial state joined
    std::optional<Home> home_;      // null in a bare station
    // A redundant pair's CPU (station_redundancy.cpp): at every END the
    // control system tracks its devices to the standby and switches on a stop
    // error; each CPU publishes the pair's SM/SD.
    RedundantPair* pair_ = nullptr;
    std::uint64_t pair_epoch_ = 0;      // the switches this CPU has heard of (RedundantPair, "Epochs")
    bool stop_error_switched_ = false;   // this stop error has asked for its switch already (logged once)
    void pair_end_of_scan();
    void publish_pair_flags();
    void track_from(const RedundantPair::Image& image);
    void pair_restarted(bool reset);   // a RESET or power-on: registers afresh; the control system's RESET switches
    const NetworkMap* network_map_ = nullptr;
    std::unique_ptr<LinkScan> link_scan_;                // null: sends no link devices
    protocol::Session passing_;                          // the scenario faults' view of requests it passes on
    std::shared_ptr<spdlog::logger> log_ = process_logger();
    devicemodel::Cpu cpu_;
    protocol::Engine engine_;
    std::vector<std::unique_ptr<devicemodel::Cpu>> other_cpus_;   // CPU No.2–4 of a multi-CPU system
    std::uint64_t next_session_id_ = 1;
    Activity activity_;
    FrontEnds frontends_;
    ScenarioHook scenario_;
    std::unique_ptr<CpuProgram> program_;                // null in a bare station
    std::unique_ptr<ScanLoop> scan_;                     // null in a bare station
    std::unique_ptr<Persistence> persistence_;           // null without a state directory
    std::unique_ptr<DriveState> drive_state_;            // null without a state directory
    std::vector<scenarios::Scenario> pending_scenarios_;   // loaded, started by connect()
    Transports* transports_ = nullptr;                   // connect()
    std::unique_ptr<ScenarioStation> scenario_station_;  // null without scenarios
    std::unique_ptr<StationSnapshot> initial_;           // what reset() returns to (connect())
    config::TimingModel timing_model_;                   // the profile's, with the configuration's overrides
    config::TimingMode timing_mode_ = config::TimingMode::Instant;
    std::unique_ptr<ResponseTiming> timing_;             // model mode only
    std::unique_ptr<Upstream> upstream_;                 // proxy mode only
    // Differential mode only: the engine of the profile's own port (engine_
    // frames every frame, for the upstream) over the same CPUs, and the report.
    std::unique_ptr<protocol::Engine> twin_engine_;
    std::unique_ptr<Comparison> comparison_;
};

}  // namespace slmp::station
