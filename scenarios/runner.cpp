#include "scenarios/runner.hpp"

#include <algorithm>

#include "config/config_error.hpp"
#include "devicemodel/drives.hpp"
#include "devicemodel/hex.hpp"
#include "devicemodel/overloaded.hpp"
#include "protocol/error_response.hpp"
#include "scenarios/bind_labels.hpp"
#include "scenarios/check_devices.hpp"
#include "scenarios/device_values.hpp"
#include "scenarios/loader.hpp"

namespace slmp::scenarios {
namespace {

using devicemodel::overloaded;

// A "drive" action must name a drive the CPU has (its family's table, docs/files.md).
void check_drives(const Scenario& s, const devicemodel::Cpu& cpu) {
    for (const auto& t : s.triggers)
        for (const auto& action : t.actions)
            if (const auto* d = std::get_if<DriveAction>(&action); d && !cpu.drives().exists(d->number))
                throw config::ConfigError(s.source + ": " + d->pointer + "/number: " + cpu.profile().name +
                                          " has no drive " + std::to_string(d->number) +
                                          "; name one of its drives (GET /api/drives lists them)");
}

std::chrono::microseconds micros(double ms) { return std::chrono::microseconds(static_cast<std::int64_t>(ms * 1000)); }

}  // namespace

ScenarioRunner::ScenarioRunner(std::vector<Scenario> scenarios, devicemodel::Cpu& cpu, EventSink log, Station* station)
    : scenarios_(std::move(scenarios)), cpu_(cpu), log_(std::move(log)), station_(station) {
    check_together(scenarios_);
    devicemodel::NumberingScope numbering(cpu_.profile().numbering);   // messages name FX5 X/Y in octal
    for (auto& s : scenarios_) {
        bind_labels(s, cpu_.labels());
        check_devices(s, cpu_.memory(), cpu_.profile().name);
        check_drives(s, cpu_);
        timelines_.push_back(std::make_unique<TimelineRunner>(s.timeline, s.seed, station_));
        logic_.push_back(std::make_unique<LogicRunner>(s.logic, s.source, cpu_));
        for (const auto& t : s.triggers) triggers_.add(t);
        for (std::size_t i = 0; i < s.faults.size(); ++i) faults_.add(s.faults[i], s.source, Rng::stream(s.seed, i), s.name);
        if (s.replay) {
            try {
                replays_.push_back(std::make_unique<ReplayBook>(read_recording(s.replay->file)));
            } catch (const config::ConfigError& e) {
                throw config::ConfigError(s.source + ": /replay/file: " + e.what());
            }
            info("replay: " + std::to_string(replays_.back()->size()) + " distinct request(s) from " + s.replay->file);
        } else {
            replays_.push_back(nullptr);
        }
    }
    corruption_rng_ = Rng(Rng::stream(scenarios_.empty() ? 1 : scenarios_.front().seed, 999));
}

ScenarioRunner::~ScenarioRunner() = default;

void ScenarioRunner::scan(TimePoint now) {
    if (!started_) {
        started_ = true;
        start_ = last_scan_ = now;
    }
    auto elapsed = std::chrono::duration_cast<std::chrono::microseconds>(std::max(now - last_scan_, TimePoint::duration::zero()));
    last_scan_ = now;
    now_ms_ = std::chrono::duration<double, std::milli>(now - start_).count();
    auto& memory = cpu_.memory();

    if (!powered_ && now_ms_ >= power_on_at_) {
        powered_ = true;
        cpu_.runtime().restart(memory);   // non-latched devices cleared, state from the switch
        cpu_.drives().clear_locks();      // file locks do not survive a power cycle (SLMP Reference Manual §5.8)
        for (auto& l : logic_) l->stopped();
        if (station_) station_->power_on();
        info("power restored: the CPU restarted");
    }
    if (refusing_ && now_ms_ >= refuse_until_) {
        refusing_ = false;
        if (station_) station_->refuse_connections(false);
        info("accepting connections again");
    }
    std::erase_if(pulses_, [&](const Pulse& p) {
        if (now_ms_ < p.until_ms) return false;
        memory.set_bit(*p.device.spec, p.device.number, false);
        return true;
    });

    for (auto& t : timelines_) t->advance(memory, now_ms_, log_);
    if (!powered_) return;   // no program, no conditions while the CPU is off
    const bool running = cpu_.runtime().state() == devicemodel::RunState::Run;
    for (auto& l : logic_) {
        if (!running) {
            l->stopped();
        } else if (auto problem = l->scan(memory, elapsed); problem && log_) {
            log_(EventLevel::Warn, "logic: " + *problem);
        }
    }

    std::vector<const Trigger*> fired;
    triggers_.scan(memory, now_ms_, fired);
    for (const auto* t : fired) run(*t);
}

Plan ScenarioRunner::before(const Incoming& incoming, std::span<const std::uint8_t> input) {
    Plan plan;
    plan.incoming = &incoming;
    const auto& r = incoming.request;
    if (!incoming.frontend() && !r.complete()) return plan;
    if (!powered_) {   // UDP while the power is off (TCP ports are closed)
        plan.silent = true;
        return plan;
    }
    plan.decision = faults_.decide(incoming, now_ms_, log_);
    auto& d = plan.decision;
    if (d.power_cycle_ms) {   // the power fails before the CPU sees the request
        power_cycle(*d.power_cycle_ms, "fault");
        plan.silent = true;
        return plan;
    }
    if (d.refuse_ms) refuse(*d.refuse_ms, "fault");
    switch (d.drop) {
        case FaultDecision::Drop::None: break;
        case FaultDecision::Drop::NoResponse: plan.silent = true; break;
        case FaultDecision::Drop::Close: plan.silent = plan.close = true; break;
        case FaultDecision::Drop::Reset: plan.silent = plan.reset = true; break;
    }
    if (plan.silent) return plan;
    if (incoming.frontend()) {   // no replay for front ends; the delay is the caller's (decision.delay_ms)
        plan.frontend_code = d.frontend_code;
        return plan;
    }
    if (d.end_code) {
        plan.answer = protocol::encode_error_response(r.header, r.command, r.subcommand, *d.end_code);
        return plan;
    }
    replay(plan, input.first(r.size));
    return plan;
}

// The first scenario with a recording that holds the request answers it; a
// miss goes by that scenario's on_miss.
void ScenarioRunner::replay(Plan& plan, std::span<const std::uint8_t> frame) {
    const auto& r = plan.incoming->request;
    for (std::size_t i = 0; i < replays_.size(); ++i) {
        if (!replays_[i]) continue;
        auto a = replays_[i]->answer(frame, r.header);
        if (a.found) {
            if (a.response) plan.answer = std::move(*a.response);
            else plan.silent = true;   // the recorded PLC did not answer either
            return;
        }
    }
    for (std::size_t i = 0; i < replays_.size(); ++i) {
        if (!replays_[i]) continue;
        const auto& spec = *scenarios_[i].replay;
        auto what = r.has_command ? devicemodel::hex4(r.command) + "/" + devicemodel::hex4(r.subcommand) : std::string("request");
        if (log_)
            log_(EventLevel::Warn, "replay: the recording holds no " + what + " like this one" +
                                       plan.incoming->from() + "; " +
                                       (spec.on_miss == ReplaySpec::Miss::Simulate ? "the simulator answers it"
                                        : spec.on_miss == ReplaySpec::Miss::EndCode ? "answered with " + devicemodel::hex4(protocol::raw(spec.miss_code))
                                                                                    : "not answered"));
        if (spec.on_miss == ReplaySpec::Miss::EndCode)
            plan.answer = protocol::encode_error_response(r.header, r.command, r.subcommand, spec.miss_code);
        else if (spec.on_miss == ReplaySpec::Miss::NoResponse)
            plan.silent = true;
        return;
    }
}

void ScenarioRunner::after(Plan& plan, const protocol::Outcome& outcome, std::vector<std::uint8_t>& response) {
    const auto& d = plan.decision;
    if (plan.pass()) {
        std::vector<const Trigger*> fired;
        triggers_.request(*plan.incoming, outcome.end_code, fired);
        for (const auto* t : fired) run(*t);
    }
    for (const auto& c : d.corruptions) corrupt(response, plan.incoming->request.header, c, corruption_rng_);
    plan.delivery.delay = micros(d.delay_ms);
    if (d.split) {
        plan.delivery.pieces = split_sizes(response.size(), *d.split);
        plan.delivery.pause = micros(d.split->pause_ms);
    }
    if (d.coalesce) {
        plan.delivery.coalesce = d.coalesce->responses;
        plan.delivery.hold = micros(d.coalesce->hold_ms);
    }
}

void ScenarioRunner::run(const Trigger& trigger) {
    auto name = trigger.id.empty() ? trigger.pointer : "'" + trigger.id + "'";
    info("trigger " + name + " fired");
    auto& memory = cpu_.memory();
    auto& runtime = cpu_.runtime();
    for (const auto& action : trigger.actions)
        std::visit(overloaded{
                       [&](const SetAction& a) { apply_values(memory, a.values, a.labels); },
                       [&](const IncrementAction& a) { write_number(memory, a.device, read_number(memory, a.device) + a.by); },
                       [&](const PulseAction& a) {
                           memory.set_bit(*a.device.spec, a.device.number, true);
                           pulses_.push_back({a.device, now_ms_ + a.ms});
                       },
                       [&](const SwitchAction& a) {
                           runtime.set_switch(memory, a.position);
                           info(std::string("RUN/STOP switch set to ") + (a.position == devicemodel::RunSwitch::Run ? "RUN" : "STOP"));
                       },
                       [&](const ErrorAction& a) {
                           runtime.raise_error(memory, a.error);
                           info("CPU error " + devicemodel::hex4(a.error.code) + (a.error.stop ? " (stop error)" : " (continuation error)"));
                       },
                       [&](const ClearErrorAction&) {
                           // As Clear Error 1617: a stop error stays until a power cycle or Remote RESET.
                           if (runtime.clear_error(memory) != devicemodel::RemoteRefusal::None)
                               info("clear_error: the stop error stays (a power cycle or Remote RESET clears it)");
                       },
                       [&](const FaultSwitchAction& a) {
                           faults_.enable(a.fault, a.enable);
                           info("fault '" + a.fault + "' " + (a.enable ? "started" : "stopped"));
                       },
                       [&](const PowerCycleAction& a) { power_cycle(a.off_ms, "trigger " + name); },
                       [&](const OndemandAction& a) {
                           if (station_) station_->ondemand(a, "trigger " + name);
                       },
                       [&](const DriveAction& a) {
                           auto& drives = cpu_.drives();
                           if (a.present) drives.set_present(a.number, *a.present);
                           if (a.write_protect) drives.set_write_protect(a.number, *a.write_protect);
                           info("drive " + std::to_string(a.number) +
                                (a.present ? (*a.present ? ": card inserted" : ": card removed") : "") +
                                (a.write_protect ? (*a.write_protect ? ": LOCK on" : ": LOCK off") : ""));
                       },
                       [&](const RefuseAction& a) { refuse(a.for_ms, "trigger " + name); },
                       [&](const LogAction& a) { info(a.text); },
                       [&](const SystemSwitchAction&) {
                           if (station_) station_->system_switch("trigger " + name);
                       },
                   },
                   action);
}

void ScenarioRunner::power_cycle(double off_ms, const std::string& why) {
    if (!powered_) return;
    powered_ = false;
    power_on_at_ = now_ms_ + off_ms;
    info("power cycle (" + why + "): power off for " + std::to_string(static_cast<long long>(off_ms)) + " ms");
    if (station_) station_->power_off();
}

void ScenarioRunner::refuse(double for_ms, const std::string& why) {
    refuse_until_ = std::max(refuse_until_, now_ms_ + for_ms);
    if (refusing_) return;
    refusing_ = true;
    info("refusing new connections for " + std::to_string(static_cast<long long>(for_ms)) + " ms (" + why + ")");
    if (station_) station_->refuse_connections(true);
}

}  // namespace slmp::scenarios
