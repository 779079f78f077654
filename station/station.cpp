// One simulated controller (station.hpp): built from the configuration,
// serving every request (handle), its scenarios, Ondemand pushes and when
// the timing modes serve a request. Its snapshots: station_snapshot.cpp.
#include "station/station.hpp"

#include <algorithm>
#include <chrono>

#include <spdlog/spdlog.h>

#include "config/station_pattern.hpp"
#include "frontends/face.hpp"
#include "protocol/command_table.hpp"
#include "protocol/error_response.hpp"
#include "protocol/lock_owner.hpp"
#include "protocol/ondemand.hpp"
#include "scenarios/initial_state.hpp"
#include "scenarios/loader.hpp"
#include "station/comparison.hpp"
#include "station/cpu_program.hpp"
#include "station/drive_state.hpp"
#include "station/inbox.hpp"
#include "station/link_scan.hpp"
#include "station/network_map.hpp"
#include "station/log_outcome.hpp"
#include "station/node_identity.hpp"
#include "station/persistence.hpp"
#include "station/response_timing.hpp"
#include "station/scan_loop.hpp"
#include "station/scenario_station.hpp"
#include "station/station_snapshot.hpp"
#include "station/upstream.hpp"

namespace slmp::station {

namespace asio = boost::asio;
using protocol::Outcome;
using std::chrono::microseconds;

namespace {

// Proxy mode cuts every frame SLMP has (1E, the station-number-extended
// frame), whatever its own profile's port takes: the upstream decides.
config::Profile framing_every_frame(config::Profile profile, const config::ServerConfig& config) {
    if (config.upstream.empty()) return profile;
    profile.port.frame_1e = true;
    profile.port.station_extended_frame = true;
    return profile;
}

}  // namespace

Station::Station(config::Profile profile, protocol::EngineOptions options)
    : cpu_(std::move(profile.cpu)), engine_(cpu_, std::move(profile.port), options), timing_model_(profile.timing) {}

Station::Station(const station::Home& home, const config::ServerConfig& config)
    : Station(framing_every_frame(config::resolve_profile(config), config), protocol::EngineOptions{config.max_request_bytes}) {
    home_ = home;
    // The scenario files' addresses follow this CPU (FX5: X/Y in octal).
    devicemodel::NumberingScope numbering(cpu_.profile().numbering);
    config_ = config;
    log_ = station_logger(config_.name);
    scenario_.set_log(log_);
    pending_scenarios_ = load_scenarios();   // their initial state joins config_ first
    config::apply_initial_values(cpu_, config_);
    config::attach_hardware(cpu_, config_);
    config::attach_drives(cpu_, config_);
    config::declare_labels(cpu_, config_.labels);
    cpu_.node().identity() = node_identity(config_, cpu_.profile());   // what node search reports (docs/nodes.md)
    if (config_.compare)   // the port of the profile itself: engine_'s frames every frame for the upstream
        twin_engine_ = std::make_unique<protocol::Engine>(cpu_, config::resolve_profile(config_).port,
                                                          protocol::EngineOptions{config_.max_request_bytes});
    for (const auto& cpu : config_.cpus) {
        auto profile = config::resolve_profile(cpu);
        other_cpus_.push_back(std::make_unique<devicemodel::Cpu>(std::move(profile.cpu)));
        config::apply_initial_values(*other_cpus_.back(), cpu.devices);
        if (twin_engine_) twin_engine_->add_cpu(cpu.number, *other_cpus_.back(), profile.port);
        engine_.add_cpu(cpu.number, *other_cpus_.back(), std::move(profile.port));
    }
    start_cpu_runtime(home);
    timing_mode_ = config_.timing.mode;
    timing_model_ = config_.timing.model.over(timing_model_);
    if (timing_mode_ == config::TimingMode::Model)
        timing_ = std::make_unique<ResponseTiming>(timing_model_, config_.timing.jitter, config_.timing.seed);
    if (!config_.upstream.empty()) {
        upstream_ = std::make_unique<Upstream>(home, config::parse_upstream(config_.upstream, "upstream"),
                                               std::chrono::milliseconds(config_.upstream_timeout_ms), *log_);
        if (config_.compare) {
            comparison_ = std::make_unique<Comparison>(std::chrono::milliseconds(config_.compare_slack_ms), *log_);
            log_->info("differential mode: every SLMP request goes to {} (timeout {} ms) and is served by this station's "
                       "{} too; clients get the upstream's answers, each difference is logged and listed at /api/compare",
                       upstream_->address().text(), config_.upstream_timeout_ms, cpu_.profile().name);
        } else {
            log_->info("proxy mode: every SLMP request goes to {} (timeout {} ms); the local devices serve none",
                       upstream_->address().text(), config_.upstream_timeout_ms);
        }
    }
}

Station::~Station() = default;

void Station::connect(Transports& transports) {
    transports_ = &transports;
    start_scenarios(std::move(pending_scenarios_));
}

void Station::start_cpu_runtime(const station::Home& home) {
    cpu_.runtime().configure(config::checked_runtime_config(config_.cpu, cpu_.profile()), cpu_.memory());
    // Device clears (Remote RUN clear modes, latch clear, reset) re-apply the
    // configured initial values, as the CPU's "device initial value" parameter does.
    cpu_.runtime().set_initial_values([this](devicemodel::DeviceMemory&) { config::apply_initial_values(cpu_, config_.devices); });
    scan_ = std::make_unique<ScanLoop>(home, all_cpus(), cpu_.runtime().config().scan_time, config_.clock_speed,
                                       config_.clock_frozen);
    program_ = std::make_unique<CpuProgram>(cpu_, config_.cpu.program, *log_);
    scan_->run_program(program_.get());
    scan_->needs_every_scan([this] { return scenario_.running(); });
    // The protocol faces' units read the ladder's requests to them at END (frontends/face.hpp).
    scan_->after_scan([this](std::chrono::steady_clock::time_point) {
        for (auto* unit : frontends_) unit->end_of_scan();
    });
    if (!config_.persistence.state_dir.empty()) {
        persistence_ = std::make_unique<Persistence>(home, cpu_, config_.persistence, *log_);
        persistence_->before_save = [this] { catch_up(); };
        persistence_->restore();
        drive_state_ = std::make_unique<DriveState>(config_.persistence.state_dir, cpu_.drives(), cpu_.profile().name, *log_);
        drive_state_->restore();
        cpu_.drives().set_on_change([this] { drive_state_->save(); });
    }
    // Files are dated by the CPU's calendar, which --clock frozen stops too.
    cpu_.drives().set_clock([this] {
        return std::chrono::duration_cast<std::chrono::seconds>(scan_->clock().calendar().time_since_epoch()).count();
    });
}

void Station::catch_up() {
    if (scan_) scan_->catch_up();
}

void Station::touched() {
    if (scan_) scan_->touched();
}

void Station::start() {
    if (scan_) scan_->start();
    if (persistence_) persistence_->start();
}

void Station::stop() {
    catch_up();   // the last snapshot holds what a scan now would show
    if (scan_) scan_->stop();
    if (upstream_) upstream_->stop();
    scenario_.log_summary();
    if (persistence_) {
        persistence_->stop();
        persistence_->save("shutdown");
    }
}

bool Station::save_snapshot(std::string_view why) {
    return persistence_ && persistence_->save(why);
}

protocol::Session Station::new_session(const config::PortConfig& port) {
    protocol::Session session;
    session.id = next_session_id();
    session.port.remote_password = port.remote_password;
    session.port.online_change = port.online_change.value_or(engine_.port().online_change);
    session.own = port.numbers;
    // The node's write timeout and the password lock-out run on the station's clock (docs/nodes.md).
    session.clock = [this] { return scan_ ? scan_->clock().now() : cpu_.runtime().now(); };
    return session;
}

Handled Station::handle(std::span<const std::uint8_t> input, protocol::DataCodePolicy policy, protocol::Session& session,
                        const protocol::Peer& peer, const Service* service) {
    auto request = engine_.decode(input, policy, session.own, session.routed);
    if (auto forwarded = to_upstream(request)) return std::move(*forwarded);
    if (auto relayed = route(request, input, policy)) return std::move(*relayed);
    return serve(std::move(request), input, session, peer, service);
}

Handled Station::handle(Ticket& ticket, protocol::Session& session, const protocol::Peer& peer) {
    if (auto forwarded = to_upstream(ticket.request)) {
        if (ticket.service) forwarded->modelled = ticket.service->modelled;
        return std::move(*forwarded);
    }
    // A request the module passes on: its modelled time here (Ke) is the first
    // part of the monitoring timer's way (Relays::pass_on); when that alone
    // runs past the timer, the module answers CF71 itself (serve()).
    const bool timed_out = ticket.service && ticket.service->timed_out;
    if (!timed_out)
        if (auto relayed = route(ticket.request, ticket.bytes, ticket.policy)) {
            if (ticket.service) relayed->modelled = ticket.service->modelled;
            return std::move(*relayed);
        }
    return serve(std::move(ticket.request), ticket.bytes, session, peer, ticket.service ? &*ticket.service : nullptr);
}

void Station::join(const NetworkMap& networks) {
    network_map_ = &networks;
    engine_.set_identity(networks.identity(*this));
    pair_ = networks.pair_of(*this);
    if (pair_) publish_pair_flags();
    if (!scan_) return;
    if (pair_) scan_->at_end([this] { pair_end_of_scan(); });
    auto link = std::make_unique<LinkScan>(*this, networks, config_.networks);
    if (link->empty()) return;
    link_scan_ = std::move(link);
    scan_->after_scan([this](std::chrono::steady_clock::time_point) { link_scan_->scanned(); });
}

// docs/plants.md, "Networks and routes", "Redundant pairs", "Multidrop stations".
std::optional<Handled> Station::route(protocol::Request& request, std::span<const std::uint8_t> input,
                                      protocol::DataCodePolicy policy) {
    if (!network_map_ || request.routed || !request.complete() || !request.has_command) return std::nullopt;
    // The own station (most requests): only a CPU of a redundant pair may send
    // it on (03D0-03D3 naming its partner), or refuse it while the pair switches.
    if (!request.elsewhere && (request.route_error != protocol::EndCode::Ok || !engine_.identity().redundant))
        return std::nullopt;
    const auto& route = request.header.route;
    const auto* row = request.spec ? request.spec : protocol::find_any_row(request.command);
    const bool file = row && row->file_route();
    NetworkMap::Found found;
    // The station-number-extended frame's station 7C names its station by the
    // extended station No. (§3.1.6); that frame travels only through stations
    // whose ports take it (§2.3: RJ71GN11-T2), others cannot be reached by it.
    const bool extended_frame = request.header.kind == protocol::FrameKind::Ext;
    if (request.elsewhere) {
        const bool by_extended = extended_frame && route.station == 0x7C;
        found = network_map_->find(*this, route.network, by_extended ? request.header.extended_station : route.station,
                                   by_extended);
        if (found.error == protocol::EndCode::Ok && extended_frame) {
            const auto takes_frame = [](const Station* station) { return station->engine_.port().station_extended_frame; };
            const auto& hops = found.relay.hops;   // hops[0] is this station, whose port took the frame
            if (!std::all_of(hops.begin() + 1, hops.end(), takes_frame) || !takes_frame(found.relay.target))
                found.error = protocol::EndCode::RouteStationNotFound;
        }
    } else {
        const bool by_pair = route.module_io >= 0x03D0 && route.module_io <= 0x03D3;
        if (!(by_pair || file)) return std::nullopt;
        found.relay.hops.push_back(this);
        found.relay.target = this;
    }
    if (found.error == protocol::EndCode::Ok) network_map_->beyond(found, route.module_io, route.multidrop, file);
    if (found.error != protocol::EndCode::Ok) {
        request.route_error = found.error;
        request.elsewhere = false;
        return std::nullopt;
    }
    if (found.relay.target == this) {   // this station by its network/station numbers
        if (request.elsewhere) request = engine_.decode(input, policy, {}, true);
        return std::nullopt;
    }
    Handled relayed;
    relayed.outcome.consumed = request.size;
    relayed.outcome.command = request.command;
    relayed.outcome.subcommand = request.subcommand;
    relayed.relay = std::move(found.relay);
    log_->debug("request {:04X}/{:04X} for network {:02X} station {:02X} module I/O {:04X} multidrop {:02X}: passed on",
                request.command, request.subcommand, route.network, route.station, route.module_io, route.multidrop);
    return relayed;
}

// Proxy mode (docs/twin.md, "Proxy"): the frame goes on as it came. A frame
// not yet whole, or bytes that start none, stay the port's own business.
std::optional<Handled> Station::to_upstream(const protocol::Request& request) const {
    if (!upstream_ || !request.complete()) return std::nullopt;
    Handled pending;
    pending.outcome.consumed = request.size;
    pending.outcome.command = request.command;
    pending.outcome.subcommand = request.subcommand;
    pending.forward = true;
    return pending;
}

StrandTask<Handled> Station::pass_on(Handled pending, std::vector<std::uint8_t> frame, protocol::DataCodePolicy policy,
                                     Relays& relays, protocol::Session& session, protocol::Peer peer) {
    if (pending.relay)
        co_return co_await relays.pass_on(std::move(*pending.relay), std::move(frame), policy, std::move(peer),
                                          pending.modelled.value_or(std::chrono::microseconds{0}));
    co_return co_await asio::co_spawn(home(), forward(std::move(frame), policy, session, std::move(peer), pending.modelled),
                                      use_strand);
}

StrandTask<Handled> Station::forward(std::vector<std::uint8_t> frame, protocol::DataCodePolicy policy, protocol::Session& session,
                                     protocol::Peer peer, std::optional<std::chrono::microseconds> modelled) {
    catch_up();
    activity_.request_starting();
    const auto started = std::chrono::steady_clock::now();
    // Decoded here only for the scenario faults, the log and the recording: the upstream gets the bytes.
    scenarios::Incoming incoming{engine_.decode(frame, policy, session.own, session.routed)};
    const auto& request = incoming.request;
    auto plan = scenario_.before(incoming, frame, session, peer);
    Handled handled;
    auto& o = handled.outcome;
    if (plan.pass()) {
        auto answer = co_await upstream_->exchange(frame, request);
        // Differential mode: the twin serves it once the upstream has (requests
        // take turns there, so both see the clients' requests in one order).
        if (comparison_) compare(frame, policy, request, answer, session, peer, modelled);
        o.action = Outcome::Action::Respond;
        o.consumed = request.size;
        o.command = request.command;
        o.subcommand = request.subcommand;
        if (answer.failure.empty()) {
            o.end_code = answer_end_code(answer.bytes, request);
            o.response = std::move(answer.bytes);
        } else {   // what a relay gives when its target does not answer (docs/end-codes.md)
            o.end_code = protocol::EndCode::RelayTimeout;
            o.response = protocol::encode_error_response(request.header, request.command, request.subcommand, o.end_code);
            o.note = "upstream " + upstream_->address().text() + ": " + answer.failure + "; answered CF71";
        }
    } else {
        o = scenario_.answer(plan, request);
    }
    scenario_.after(plan, handled, frame, session, peer);
    log_outcome(*log_, peer, o);
    activity_.request({session.id, peer, std::span<const std::uint8_t>(frame).first(std::min(o.consumed, frame.size())), request, o,
                       std::chrono::steady_clock::now() - started, std::nullopt});
    touched();
    co_return handled;
}

// Differential mode (docs/twin.md, "Compare"): the upstream's answer is the
// reference (the real PLC stays the truth for the client, who gets it), the
// twin's is this station's own, and the report says how they differ.
void Station::compare(std::span<const std::uint8_t> frame, protocol::DataCodePolicy policy, const protocol::Request& request,
                      const UpstreamAnswer& answer, protocol::Session& session, const protocol::Peer& peer,
                      std::optional<std::chrono::microseconds> modelled) {
    using Observed = protocol::differential::Observed;
    ComparedRequest compared;
    compared.at = std::chrono::system_clock::now();
    compared.connection = session.id;
    compared.peer = peer;
    compared.command = request.command;
    compared.subcommand = request.subcommand;
    compared.request.assign(frame.begin(), frame.begin() + static_cast<std::ptrdiff_t>(std::min(request.size, frame.size())));
    auto& up = compared.upstream;
    switch (answer.failed) {
        case UpstreamAnswer::Failed::No:
            up.bytes = answer.bytes;
            up.end_code = static_cast<std::uint16_t>(answer_end_code(answer.bytes, request));
            break;
        case UpstreamAnswer::Failed::NotAnAnswer:   // compared as the bytes they are, with no end code to read
            up.bytes = answer.bytes;
            up.end_code = 0xFFFF;
            break;
        case UpstreamAnswer::Failed::Silent: up.kind = Observed::Kind::Silence; break;
        case UpstreamAnswer::Failed::Unreachable:   // refused: as a port that closes
        case UpstreamAnswer::Failed::Closed: up.kind = Observed::Kind::Close; break;
    }
    up.time = answer.took;
    catch_up();   // the scans due while the upstream answered run first, as before any request here
    compared.twin = serve_twin(compared.request, policy, request, session, peer, modelled);
    // A difference is kept at the report's end: the event stream shows it as kept.
    if (!comparison_->add(std::move(compared)).same()) activity_.difference(comparison_->differences().back());
}

protocol::differential::Observed Station::serve_twin(std::span<const std::uint8_t> frame, protocol::DataCodePolicy policy,
                                                     const protocol::Request& request, protocol::Session& session,
                                                     const protocol::Peer& peer,
                                                     std::optional<std::chrono::microseconds> modelled) {
    using Observed = protocol::differential::Observed;
    session.file_owner = protocol::lock_owner(peer, session.id);
    const auto started = std::chrono::steady_clock::now();
    // Its own port decides what the frame is: a 1E frame on an iQ-R port is none.
    auto outcome = twin_engine_->execute(twin_engine_->decode(frame, policy, session.own, session.routed), session);
    const auto took = std::chrono::duration_cast<microseconds>(std::chrono::steady_clock::now() - started);
    Observed twin;
    switch (outcome.action) {
        case Outcome::Action::Respond:
            twin.bytes = std::move(outcome.response);
            twin.end_code = static_cast<std::uint16_t>(answer_end_code(twin.bytes, request));
            break;
        case Outcome::Action::Close:
        case Outcome::Action::Restart:   // a Remote RESET: its CPU restarted; the clients' connections are the upstream's
            twin.kind = Observed::Kind::Close;
            break;
        case Outcome::Action::Silent:
        case Outcome::Action::NeedMore:   // its port would wait for more bytes: silent
            twin.kind = Observed::Kind::Silence;
            break;
    }
    // model: the modelled time, which a client of this station alone would wait; else what serving took.
    twin.time = modelled.value_or(took);
    return twin;
}

StrandTask<Handled> Station::serve_routed(std::vector<std::uint8_t> frame, protocol::DataCodePolicy policy,
                                          std::optional<protocol::Session>& session, protocol::Peer peer) {
    if (!session) {
        config::PortConfig port;
        port.remote_password = false;   // the receiving port checked it (docs/plants.md)
        session = new_session(port);
        session->routed = true;
    }
    Handled handled;
    if (serves_at_once()) {
        handled = handle(frame, policy, *session, peer);
    } else {
        HeldDatagram held(*this, frame, policy, *session);
        if (co_await held.wait()) handled = held.serve(*session, peer);
        else handled.outcome.action = Outcome::Action::Silent;   // the station stopped meanwhile
    }
    if (handled.forward) handled = co_await forward(std::move(frame), policy, *session, std::move(peer));
    // A Remote RESET through a route restarts this CPU; the route gets no answer.
    if (handled.outcome.action == Outcome::Action::Restart) restart();
    co_return handled;
}

StrandTask<std::optional<Handled>> Station::pass_through(std::vector<std::uint8_t> frame, protocol::DataCodePolicy policy,
                                                         protocol::Peer peer, bool receiving) {
    if (!receiving && timing_mode_ == config::TimingMode::Model) {
        const bool ascii = engine_.frame(frame, policy).header.codec == protocol::Codec::Ascii;
        const std::chrono::duration<double, std::milli> ke(ascii ? timing_model_.ke_ascii_ms : timing_model_.ke_binary_ms);
        co_await wait_on_clock(std::chrono::duration_cast<std::chrono::microseconds>(ke));
    }
    if (!scenario_.active()) co_return std::nullopt;
    // Its faults match the request as it passes (a module reads only the header of another station's request).
    auto request = engine_.decode(frame, policy, {}, false);
    if (!request.complete() || !request.has_command) co_return std::nullopt;
    scenarios::Incoming incoming{std::move(request)};
    auto plan = scenario_.before(incoming, frame, passing_, peer);
    if (plan.pass()) {   // a delay holds it here (the plan's decision: its delivery is set only after an answer)
        const std::chrono::duration<double, std::milli> delay(plan.decision.delay_ms);
        if (delay.count() > 0) co_await wait_on_clock(std::chrono::duration_cast<std::chrono::microseconds>(delay));
        co_return std::nullopt;
    }
    Handled refused;
    refused.outcome = scenario_.answer(plan, incoming.request);
    scenario_.after(plan, refused, frame, passing_, peer);
    log_outcome(*log_, peer, refused.outcome);
    co_return refused;
}

StrandTask<> Station::wait_on_clock(std::chrono::microseconds timer, std::function<bool()> wanted) {
    if (!scan_) co_return;
    const auto until = scan_->clock().now() + timer;
    while (scan_->clock().now() < until && !scan_->stopped() && (!wanted || wanted()))
        co_await scan_->until_end_or(std::nullopt, until);
}

void Station::stop_waiting() {
    if (scan_) scan_->nudge();
}

Handled Station::serve(protocol::Request request, std::span<const std::uint8_t> input, protocol::Session& session,
                       const protocol::Peer& peer, const Service* service) {
    // A sleeping scan loop first runs the scans due by now; the request may
    // start a timer or change the state, so the loop looks again after it.
    catch_up();
    TouchedAtExit touch_after{*this};
    activity_.request_starting();
    session.file_owner = protocol::lock_owner(peer, session.id);   // UDP: each peer its own (docs/files.md)
    session.peer_ipv4 = protocol::peer_ipv4(peer);                 // the node commands' sender (docs/nodes.md)
    session.local_port = peer.local_port;
    auto started = std::chrono::steady_clock::now();
    // Decoded once (handle() or schedule()); the scenario hook sits between decode and execute.
    scenarios::Incoming incoming{std::move(request)};
    auto plan = scenario_.before(incoming, input, session, peer);
    Handled handled;
    std::optional<std::chrono::microseconds> modelled;
    if (service && plan.pass() && incoming.request.complete() && incoming.request.has_command) {
        modelled = service->modelled;
        if (service->timed_out)   // the port gave up waiting for the CPU (docs/timing.md)
            handled.outcome = timed_out(incoming.request, ResponseTiming::monitoring_timer(incoming.request, input));
    }
    if (handled.outcome.action == Outcome::Action::NeedMore)
        handled.outcome = plan.pass() ? engine_.execute(incoming.request, session) : scenario_.answer(plan, incoming.request);
    scenario_.after(plan, handled, input, session, peer);
    const auto& outcome = handled.outcome;
    if (outcome.action == Outcome::Action::NeedMore) return handled;
    log_outcome(*log_, peer, outcome);
    activity_.request({session.id, peer, input.first(outcome.consumed), incoming.request, outcome,
                       std::chrono::steady_clock::now() - started, modelled});
    return handled;
}

// Remote RESET (SLMP Reference Manual §5.6): the CPU has restarted; as on
// the real station every TCP connection drops and UDP sessions start afresh.
void Station::restart() {
    log_->info("Remote RESET: CPU restarted; closing every connection");
    pair_restarted(true);
    std::vector<std::uint64_t> ids;
    for (const auto& [id, _] : activity_.connections()) ids.push_back(id);
    for (auto id : ids) activity_.close(id, "Remote RESET: the CPU restarted");
    if (transports_) transports_->restart_sessions();
}


// The station's part in scenarios and recording (docs/scenarios.md): load the
// --scenario files before the CPU is built (their initial state is part of the
// configuration), then start them once the ports exist, driven by the scan cycle.
std::vector<scenarios::Scenario> Station::load_scenarios() {
    std::vector<scenarios::Scenario> list;
    for (const auto& file : config_.scenarios) {
        auto s = scenarios::load_scenario(file);
        if (!runs(s)) {   // a plant-wide list: the file names other stations
            log_->debug("scenario '{}' ({}) is for {}, not this station", s.name, s.source, fmt::join(s.stations, ", "));
            continue;
        }
        scenarios::apply_initial_state(s, config_);
        list.push_back(std::move(s));
    }
    scenarios::check_together(list);
    return list;
}

bool Station::runs(const scenarios::Scenario& s) const {
    return s.stations.empty() || config_.name.empty() || config::station_patterns_match(s.stations, config_.name);
}

void Station::start_scenarios(std::vector<scenarios::Scenario> list) {
    if (!config_.record_file.empty()) scenario_.record(config_.record_file, cpu_.profile().name);
    if (!config_.record_pcap_file.empty()) scenario_.record_pcap(config_.record_pcap_file, config_.bind);
    // With the HTTP API on, scenarios and recordings may start later (POST
    // /api/scenarios, /api/recording), so the hook is wired up even when idle.
    const bool later = config_.http.enabled;
    if (!list.empty() || later) {
        auto ondemand = [this](const scenarios::OndemandAction& action, const std::string& why) {
            try {
                this->ondemand(action, why);
            } catch (const config::ConfigError& e) {
                log_->warn("scenario: {}: Ondemand not sent: {}", why, e.what());
            }
        };
        ScenarioStation::Redundancy redundancy{[this](bool on) { powered(on); }, [this](const std::string& why) {
                                                   if (auto refused = system_switch(why); !refused.empty())
                                                       log_->warn("scenario: {}: no system switch: {}", why, refused);
                                               }};
        scenario_station_ =
            std::make_unique<ScenarioStation>(activity_, *transports_, ondemand, std::move(redundancy), *log_);
        scenario_.attach(cpu_, *scenario_station_);
        if (!list.empty()) scenario_.start(std::move(list), cpu_, *scenario_station_);
        scan_->after_scan([this](std::chrono::steady_clock::time_point now) { scenario_.scanned(now); });
    }
    if (scenario_.active() || later) activity_.add_observer(&scenario_);
}


// Ondemand 2101 (docs/timing.md): the station reads the devices now and sends
// their words, unasked, to the clients the action names, in each client's own
// frame shape (protocol/ondemand.hpp).
namespace {

bool wanted(const PushTarget& t, const std::string& to) {
    if (to == "all") return true;
    if (to == "tcp") return t.peer.transport == Transport::Tcp;
    if (to == "udp") return t.peer.transport == Transport::Udp;
    return t.peer.transport == Transport::Tcp && std::to_string(t.session) == to;
}

}  // namespace

std::vector<Station::Pushed> Station::ondemand(const scenarios::OndemandAction& action, const std::string& why) {
    catch_up();
    const auto& spec = *action.first.spec;
    const auto name = devicemodel::format_address(action.first, cpu_.profile().numbering);
    if (!cpu_.memory().contains(spec.area, action.first.number, action.points))
        throw config::ConfigError("ondemand: " + name + " with " + std::to_string(action.points) + " point(s) runs past the " +
                                  std::string(devicemodel::area_name(spec.area)) + " size of " +
                                  std::to_string(cpu_.memory().size(spec.area)) + "; name devices inside it");
    const auto& to = action.to;
    if (to != "all" && to != "tcp" && to != "udp" && (to.empty() || to.find_first_not_of("0123456789") != std::string::npos))
        throw config::ConfigError("ondemand: unknown target '" + to + "'; use \"all\", \"tcp\", \"udp\" or a TCP connection id");
    const std::size_t words = spec.unit == devicemodel::Unit::Bit ? (action.points + 15) / 16
                                                                  : std::size_t{action.points} * devicemodel::words_per_device(spec);
    if (words > protocol::kOndemandMaxWords)
        throw config::ConfigError("ondemand: " + std::to_string(words) + " words; at most 960 words (1920 bytes) go in one push");
    std::vector<std::uint16_t> data(words);
    cpu_.memory().read_words(spec, action.first.number, data);

    std::vector<Pushed> sent;
    if (!transports_) return sent;
    for (auto& target : transports_->push_targets()) {
        if (!wanted(target, to)) continue;
        auto frame = protocol::encode_ondemand(target.kind, target.codec, data);
        activity_.pushed({target.session, target.peer, frame, why});
        sent.push_back({target.session, target.peer, frame});
        target.send(std::move(frame));
    }
    log_->info("Ondemand 2101 ({}): {} word(s) from {} to {} client(s)", why, words, name, sent.size());
    return sent;
}


// When the end_of_scan and model timing modes serve a request
// (docs/timing.md). The inbox (station/inbox.hpp) holds the bytes; these say
// when to hand them to Station::handle() and whether the monitoring timer ran
// out first.

std::optional<Queued> Station::next_request(std::span<const std::uint8_t> input, protocol::DataCodePolicy policy) const {
    std::size_t offset = 0;
    while (offset < input.size()) {
        const auto rest = input.subspan(offset);
        const auto scan = engine_.frame(rest, policy);
        switch (scan.status) {
            case protocol::FrameScan::Status::NeedMore: return std::nullopt;
            case protocol::FrameScan::Status::Garbage: offset += std::max<std::size_t>(scan.size, 1); continue;
            case protocol::FrameScan::Status::TooLarge: return Queued{offset, offset + 1, {}, true};
            case protocol::FrameScan::Status::Complete: break;
        }
        return Queued{offset, offset + scan.size, ResponseTiming::monitoring_timer(scan.header, rest), false};
    }
    return std::nullopt;
}

Ticket Station::schedule(std::vector<std::uint8_t> frame, protocol::DataCodePolicy policy, const protocol::Session& session,
                         std::chrono::steady_clock::time_point arrival) {
    Ticket ticket;
    ticket.bytes = std::move(frame);
    ticket.policy = policy;
    ticket.request = engine_.decode(ticket.bytes, policy, session.own, session.routed);
    const auto& request = ticket.request;
    if (!timing_ || !scan_ || !request.complete() || !request.has_command) return ticket;
    // The next END after the arrival in CPU time: a running clock's scan covers period × speed of it.
    const auto next_end = scan_->last_end() + scan_->cpu_period();
    const auto scan_wait = next_end > arrival ? std::chrono::duration_cast<microseconds>(next_end - arrival) : microseconds{0};
    // A request a module passes on waits for no END here: its time is the passing on (docs/timing.md).
    const auto modelled = timing_->modelled(request, request.elsewhere ? microseconds{0} : scan_wait);
    const auto timer = ResponseTiming::monitoring_timer(request, ticket.bytes);
    // The port gives up when the timer runs out first (docs/timing.md).
    if (timer.count() > 0 && modelled > timer) ticket.service = Service{arrival + timer, true, timer};
    else ticket.service = Service{arrival + modelled, false, modelled};
    return ticket;
}

std::optional<Service> Station::end_of_scan_service(std::chrono::steady_clock::time_point arrival,
                                                    std::chrono::milliseconds timer,
                                                    std::chrono::steady_clock::time_point now, bool at_end) {
    // The END that serves it has come: in time unless it came after the timer.
    // Before it: only a timer that has run out answers now.
    const bool expired = timer.count() > 0 && now - arrival > timer;
    if (!at_end && !(timer.count() > 0 && now - arrival >= timer)) return std::nullopt;
    return Service{now, at_end ? expired : true, std::nullopt};
}

Outcome Station::timed_out(const protocol::Request& request, std::chrono::milliseconds timer) {
    // CF71, "processing aborted because of a timeout"; the CPU never ran the
    // request, so nothing is read or written.
    Outcome o;
    o.action = Outcome::Action::Respond;
    o.consumed = request.size;
    o.command = request.command;
    o.subcommand = request.subcommand;
    o.end_code = protocol::EndCode::RelayTimeout;
    o.response = protocol::encode_error_response(request.header, request.command, request.subcommand, o.end_code);
    o.note = "the monitoring timer (" + std::to_string(timer.count()) +
             " ms) ran out before the CPU served the request; answered CF71 when it did";
    return o;
}

}  // namespace slmp::station
