#include "server/scenario_hook.hpp"

#include <spdlog/spdlog.h>

#include "scenarios/request_view.hpp"

namespace slmp::server {

using protocol::Outcome;

namespace {

void log_event(scenarios::EventLevel level, const std::string& line) {
    switch (level) {
        case scenarios::EventLevel::Debug: spdlog::debug("scenario: {}", line); break;
        case scenarios::EventLevel::Info: spdlog::info("scenario: {}", line); break;
        case scenarios::EventLevel::Warn: spdlog::warn("scenario: {}", line); break;
    }
}

std::string joined(const std::vector<std::string>& names) {
    std::string text;
    for (const auto& n : names) text += (text.empty() ? "'" : ", '") + n + "'";
    return text;
}

}  // namespace

std::string_view peer_address(std::string_view peer) {
    auto colon = peer.find(':');
    return colon == std::string_view::npos ? peer : peer.substr(colon + 1);
}

ScenarioHook::~ScenarioHook() = default;

void ScenarioHook::start(std::vector<scenarios::Scenario> list, devicemodel::Cpu& cpu, scenarios::Station& station) {
    for (const auto& s : list)
        spdlog::info("scenario '{}' ({}): {} step(s), {} trigger(s), {} rung(s), {} fault(s){}", s.name, s.source,
                     s.timeline.steps.size(), s.triggers.size(), s.logic.rungs.size(), s.faults.size(),
                     s.replay ? ", replaying " + s.replay->file : "");
    runner_ = std::make_unique<scenarios::ScenarioRunner>(std::move(list), cpu, log_event, &station);
}

void ScenarioHook::record(const std::string& file, const std::string& profile) {
    recorder_ = std::make_unique<scenarios::RecordingWriter>(file, profile, std::chrono::steady_clock::now());
    spdlog::info("recording every request and response to {}", file);
}

Handled ScenarioHook::process(protocol::Engine& engine, std::span<const std::uint8_t> input,
                              protocol::DataCodePolicy policy, protocol::Session& session, const Link& link) {
    Handled handled;
    if (!active()) {
        handled.outcome = engine.process(input, policy, session);
        return handled;
    }
    scenarios::Plan plan;
    if (runner_) {
        auto view = scenarios::view_request(input, policy, engine.options().max_frame_bytes, engine.cpu().profile());
        view.transport = link.transport;
        view.peer = std::string(link.peer);
        view.client = std::string(peer_address(link.peer).substr(0, peer_address(link.peer).rfind(':')));
        if (auto it = ordinals_.find(session.id); link.transport == Transport::Tcp && it != ordinals_.end())
            view.connection = it->second;
        plan = runner_->before(std::move(view), input);
    }
    auto& outcome = handled.outcome;
    const auto& request = plan.request;
    if (!runner_ || !request.complete || plan.pass()) {
        outcome = engine.process(input, policy, session);
    } else {
        // The scenario answers (or not) instead of the CPU.
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
    }
    if (runner_ && request.complete && outcome.action != Outcome::Action::NeedMore) runner_->after(plan, outcome, outcome.response);
    handled.delivery = plan.delivery;
    handled.reset = plan.reset;
    if (recorder_ && outcome.action != Outcome::Action::NeedMore)
        recorder_->exchange(std::chrono::steady_clock::now(), session.id, link.transport, std::string(peer_address(link.peer)),
                            input.first(outcome.consumed),
                            outcome.action == Outcome::Action::Respond ? &outcome.response : nullptr, plan.decision.fired);
    return handled;
}

void ScenarioHook::scanned(std::chrono::steady_clock::time_point now) {
    if (runner_) runner_->scan(now);
}

std::vector<scenarios::FaultStats> ScenarioHook::fault_stats() const {
    return runner_ ? runner_->fault_stats() : std::vector<scenarios::FaultStats>{};
}

void ScenarioHook::log_summary() const {
    for (const auto& f : fault_stats())
        if (f.matched > 0) spdlog::info("scenario: fault '{}' ({}) matched {} request(s), fired {} time(s)", f.name, f.kind, f.matched, f.fired);
}

void ScenarioHook::on_opened(const Connection& c) {
    if (c.transport == Transport::Tcp) ordinals_[c.id] = ++connections_;
    if (recorder_) recorder_->opened(std::chrono::steady_clock::now(), c.id, c.transport, std::string(peer_address(c.peer)));
}

void ScenarioHook::on_closed(const Connection& c, std::string_view why) {
    ordinals_.erase(c.id);
    if (recorder_) recorder_->closed(std::chrono::steady_clock::now(), c.id, c.transport, std::string(peer_address(c.peer)), std::string(why));
}

}  // namespace slmp::server
