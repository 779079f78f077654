#include "station/scenario_hook.hpp"

#include <spdlog/spdlog.h>

#include "config/config.hpp"
#include "station/capture/pcap_writer.hpp"
#include "station/capture/recording_writer.hpp"

namespace slmp::station {

using protocol::Outcome;

namespace {

std::string joined(const std::vector<std::string>& names) {
    std::string text;
    for (const auto& n : names) text += (text.empty() ? "'" : ", '") + n + "'";
    return text;
}

}  // namespace

ScenarioHook::~ScenarioHook() = default;

scenarios::EventSink ScenarioHook::event_sink() const {
    return [log = log_](scenarios::EventLevel level, const std::string& line) {
        switch (level) {
            case scenarios::EventLevel::Debug: log->debug("scenario: {}", line); break;
            case scenarios::EventLevel::Info: log->info("scenario: {}", line); break;
            case scenarios::EventLevel::Warn: log->warn("scenario: {}", line); break;
        }
    };
}

void ScenarioHook::start(std::vector<scenarios::Scenario> list, devicemodel::Cpu& cpu, scenarios::Station& station) {
    for (const auto& s : list)
        log_->info("scenario '{}' ({}): {} step(s), {} trigger(s), {} rung(s), {} fault(s){}", s.name, s.source,
                   s.timeline.steps.size(), s.triggers.size(), s.logic.rungs.size(), s.faults.size(),
                     s.replay ? ", replaying " + s.replay->file : "");
    attach(cpu, station);
    runners_.add(std::move(list), cpu, event_sink(), &station);
}

void ScenarioHook::attach(devicemodel::Cpu& cpu, scenarios::Station& station) {
    cpu_ = &cpu;
    station_ = &station;
}

void ScenarioHook::load(scenarios::Scenario s) {
    if (!cpu_) throw config::ConfigError("scenarios cannot be loaded before the server has started");
    // The password is part of the CPU's configuration; it cannot change under connected clients.
    if (s.initial.password)
        throw config::ConfigError(s.source + ": /initial/password: a remote password is set only at start; "
                                  "give this scenario with --scenario, or leave \"password\" out");
    auto initial = s.initial;
    auto summary = fmt::format("scenario '{}' ({}) loaded: {} step(s), {} trigger(s), {} rung(s), {} fault(s)", s.name,
                               s.source, s.timeline.steps.size(), s.triggers.size(), s.logic.rungs.size(), s.faults.size());
    std::vector<scenarios::Scenario> list;
    list.push_back(std::move(s));
    runners_.add(std::move(list), *cpu_, event_sink(), station_);
    log_->info("{}", summary);
    config::apply_initial_values(*cpu_, initial.devices);
    if (initial.run_switch) cpu_->runtime().set_switch(cpu_->memory(), *initial.run_switch);
    if (initial.error) cpu_->runtime().raise_error(cpu_->memory(), *initial.error);
}

void ScenarioHook::replace_scenarios(std::vector<std::vector<scenarios::Scenario>> groups) {
    runners_.clear(station_);
    if (!cpu_) return;
    for (auto& group : groups) runners_.add(std::move(group), *cpu_, event_sink(), station_);
}

bool ScenarioHook::stop(const std::string& name) {
    if (!cpu_ || !runners_.remove(name, *cpu_, event_sink(), station_)) return false;
    log_->info("scenario '{}' stopped", name);
    return true;
}

void ScenarioHook::record(const std::string& file, const std::string& profile) {
    if (recording_)
        throw config::ConfigError("already recording to " + recording_file_ + "; stop that recording first");
    recorders_.push_back(std::make_unique<RecordingWriter>(file, profile, std::chrono::steady_clock::now()));
    recording_ = recorders_.back().get();
    recording_file_ = file;
    log_->info("recording every request and response to {}", file);
}

bool ScenarioHook::stop_recording() {
    if (!recording_) return false;
    std::erase_if(recorders_, [&](const auto& r) { return r.get() == recording_; });   // closes the file
    log_->info("recording to {} stopped", recording_file_);
    recording_ = nullptr;
    recording_file_.clear();
    return true;
}

void ScenarioHook::record_pcap(const std::string& file, const std::string& bind) {
    recorders_.push_back(std::make_unique<PcapWriter>(file, bind, std::chrono::steady_clock::now(),
                                                                 std::chrono::system_clock::now()));
    log_->info("capturing every request and response to {} (pcap)", file);
}

scenarios::Plan ScenarioHook::before(scenarios::Incoming& incoming, std::span<const std::uint8_t> input,
                                     const protocol::Session& session, const protocol::Peer& peer) {
    if (runners_.empty()) return {};
    incoming.peer = peer;
    if (auto it = ordinals_.find(session.id); peer.transport == Transport::Tcp && it != ordinals_.end())
        incoming.connection = it->second;
    return runners_.before(incoming, input);
}

Outcome ScenarioHook::answer(scenarios::Plan& plan, const protocol::Request& request) const {
    Outcome outcome;
    outcome.consumed = request.size;
    outcome.command = request.command;
    outcome.subcommand = request.subcommand;
    const auto faults = plan.decision.fired.empty() ? std::string("replay") : "fault " + joined(plan.decision.fired);
    if (plan.answer) {
        outcome.action = Outcome::Action::Respond;
        outcome.response = std::move(*plan.answer);
        outcome.end_code = plan.decision.end_code.value_or(protocol::EndCode::Ok);
        if (plan.decision.end_code) outcome.note = "scenario " + faults + ": answered with an end code";
    } else {
        outcome.action = plan.close || plan.reset ? Outcome::Action::Close : Outcome::Action::Silent;
        outcome.note = "scenario " + faults + (plan.reset ? ": connection reset (RST)"
                                               : plan.close ? ": connection closed (FIN)"
                                                            : ": not answered");
    }
    return outcome;
}

void ScenarioHook::after(scenarios::Plan& plan, Handled& handled, std::span<const std::uint8_t> input,
                         const protocol::Session& session, const protocol::Peer& peer) {
    auto& outcome = handled.outcome;
    if (outcome.action == Outcome::Action::NeedMore) return;
    if (plan.incoming && plan.incoming->request.complete()) {   // a scenario saw the request
        runners_.after(plan, outcome, outcome.response);
        handled.delivery = plan.delivery;
        handled.reset = plan.reset;
    }
    if (recorders_.empty()) return;
    const RecordedLink at{session.id, peer.transport, peer.endpoint(), peer.local_port};
    for (auto& r : recorders_)
        r->exchange(std::chrono::steady_clock::now(), at, input.first(outcome.consumed),
                    outcome.action == Outcome::Action::Respond ? &outcome.response : nullptr, plan.decision.fired,
                    outcome.named);
}

scenarios::Plan ScenarioHook::frontend_before(scenarios::Incoming& incoming, std::uint64_t session) {
    if (runners_.empty()) return {};
    if (auto it = ordinals_.find(session); incoming.peer.transport == Transport::Tcp && it != ordinals_.end())
        incoming.connection = it->second;
    return runners_.before_frontend(incoming);
}

void ScenarioHook::frontend_recorded(const FrontEndRecord& f) {
    if (recorders_.empty()) return;
    const RecordedLink at{f.connection, f.peer.transport, f.peer.endpoint(), f.peer.local_port};
    const bool answered = !f.code.empty() || !f.response.empty();
    for (auto& r : recorders_)
        r->frontend_exchange(std::chrono::steady_clock::now(), at, f.protocol, f.command, f.code, f.request, f.response,
                             answered, f.faults);
}

void ScenarioHook::scanned(std::chrono::steady_clock::time_point now) {
    runners_.scan(now);
}

std::vector<scenarios::FaultStats> ScenarioHook::fault_stats() const {
    return runners_.fault_stats();
}

void ScenarioHook::log_summary() const {
    for (const auto& f : fault_stats())
        if (f.matched > 0) log_->info("scenario: fault '{}' ({}) matched {} request(s), fired {} time(s)", f.name, f.kind, f.matched, f.fired);
}

void ScenarioHook::on_opened(const Connection& c) {
    if (c.peer.transport == Transport::Tcp) ordinals_[c.id] = ++connections_;
    const RecordedLink at{c.id, c.peer.transport, c.peer.endpoint(), c.peer.local_port};
    for (auto& r : recorders_) r->opened(std::chrono::steady_clock::now(), at);
}

void ScenarioHook::on_pushed(const PushRecord& p) {
    if (recorders_.empty()) return;
    const RecordedLink at{p.connection, p.peer.transport, p.peer.endpoint(), p.peer.local_port};
    const std::vector<std::uint8_t> frame(p.frame.begin(), p.frame.end());
    for (auto& r : recorders_) r->pushed(std::chrono::steady_clock::now(), at, frame);
}

void ScenarioHook::on_closed(const Connection& c, std::string_view why) {
    ordinals_.erase(c.id);
    const RecordedLink at{c.id, c.peer.transport, c.peer.endpoint(), c.peer.local_port};
    for (auto& r : recorders_) r->closed(std::chrono::steady_clock::now(), at, std::string(why));
}

}  // namespace slmp::station
