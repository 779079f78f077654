#include "station/station.hpp"

#include <chrono>

#include <spdlog/spdlog.h>

#include "protocol/lock_owner.hpp"
#include "station/log_outcome.hpp"
#include "protocol/error_response.hpp"
#include "station/cpu_program.hpp"
#include "station/drive_state.hpp"
#include "station/persistence.hpp"
#include "station/response_timing.hpp"
#include "station/scan_loop.hpp"
#include "station/scenario_station.hpp"
#include "station/station_snapshot.hpp"

namespace slmp::station {

using protocol::Outcome;

Station::Station(config::Profile profile, protocol::EngineOptions options)
    : cpu_(std::move(profile.cpu)), engine_(cpu_, std::move(profile.port), options), timing_model_(profile.timing) {}

Station::Station(const station::Home& home, const config::ServerConfig& config)
    : Station(config::resolve_profile(config), protocol::EngineOptions{config.max_request_bytes}) {
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
    for (const auto& cpu : config_.cpus) {
        auto profile = config::resolve_profile(cpu);
        other_cpus_.push_back(std::make_unique<devicemodel::Cpu>(std::move(profile.cpu)));
        config::apply_initial_values(*other_cpus_.back(), cpu.devices);
        engine_.add_cpu(cpu.number, *other_cpus_.back(), std::move(profile.port));
    }
    start_cpu_runtime(home);
    timing_mode_ = config_.timing.mode;
    timing_model_ = config_.timing.model.over(timing_model_);
    if (timing_mode_ == config::TimingMode::Model)
        timing_ = std::make_unique<ResponseTiming>(timing_model_, config_.timing.jitter, config_.timing.seed);
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
    if (!config_.persistence.state_dir.empty()) {
        persistence_ = std::make_unique<Persistence>(home, cpu_, config_.persistence, *log_);
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

void Station::start() {
    if (scan_) scan_->start();
    if (persistence_) persistence_->start();
}

void Station::stop() {
    if (scan_) scan_->stop();
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
    return session;
}

Handled Station::handle(std::span<const std::uint8_t> input, protocol::DataCodePolicy policy, protocol::Session& session,
                        const protocol::Peer& peer, const Service* service) {
    return serve(engine_.decode(input, policy, session.own), input, session, peer, service);
}

Handled Station::handle(Ticket& ticket, protocol::Session& session, const protocol::Peer& peer) {
    return serve(std::move(ticket.request), ticket.bytes, session, peer, ticket.service ? &*ticket.service : nullptr);
}

Handled Station::serve(protocol::Request request, std::span<const std::uint8_t> input, protocol::Session& session,
                       const protocol::Peer& peer, const Service* service) {
    activity_.request_starting();
    session.file_owner = protocol::lock_owner(peer, session.id);   // UDP: each peer its own (docs/files.md)
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

// Remote RESET (slmp-labels-remote-misc.md §5.6): the CPU has restarted; as on
// the real station every TCP connection drops and UDP sessions start afresh.
void Station::restart() {
    log_->info("Remote RESET: CPU restarted; closing every connection");
    std::vector<std::uint64_t> ids;
    for (const auto& [id, _] : activity_.connections()) ids.push_back(id);
    for (auto id : ids) activity_.close(id, "Remote RESET: the CPU restarted");
    if (transports_) transports_->restart_sessions();
}

}  // namespace slmp::station
