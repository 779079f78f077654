#include "scenarios/runner_set.hpp"

#include <algorithm>

#include "config/config_error.hpp"
#include "scenarios/loader.hpp"

namespace slmp::scenarios {

std::vector<Scenario> RunnerSet::all() const {
    std::vector<Scenario> list;
    for (const auto& r : runners_) list.insert(list.end(), r->scenarios().begin(), r->scenarios().end());
    return list;
}

void RunnerSet::add(std::vector<Scenario> list, devicemodel::Cpu& cpu, EventSink log, Station* station) {
    auto together = all();
    for (const auto& s : list)
        for (const auto& running : together)
            if (running.name == s.name)
                throw config::ConfigError(s.source + ": /name: a scenario named '" + s.name + "' is already running (" +
                                          running.source + "); stop that one first or give this one another \"name\"");
    together.insert(together.end(), list.begin(), list.end());
    check_together(together);   // ids unique across every running scenario
    runners_.push_back(std::make_unique<ScenarioRunner>(std::move(list), cpu, std::move(log), station));
}

bool RunnerSet::remove(const std::string& name, devicemodel::Cpu& cpu, EventSink log, Station* station) {
    auto named = [&](const Scenario& s) { return s.name == name; };
    auto holds = [&](const ScenarioRunner& r) { return std::any_of(r.scenarios().begin(), r.scenarios().end(), named); };
    if (std::none_of(runners_.begin(), runners_.end(), [&](const auto& r) { return holds(*r); })) return false;

    // The restarted runners first: should one throw, nothing has changed.
    std::vector<std::unique_ptr<ScenarioRunner>> restarted(runners_.size());
    for (std::size_t i = 0; i < runners_.size(); ++i) {
        if (!holds(*runners_[i])) continue;
        std::vector<Scenario> rest;
        const auto& list = runners_[i]->scenarios();
        std::copy_if(list.begin(), list.end(), std::back_inserter(rest), [&](const Scenario& s) { return !named(s); });
        if (!rest.empty()) restarted[i] = std::make_unique<ScenarioRunner>(std::move(rest), cpu, log, station);
    }
    std::vector<std::unique_ptr<ScenarioRunner>> kept;
    for (std::size_t i = 0; i < runners_.size(); ++i) {
        auto& r = runners_[i];
        if (!holds(*r)) {
            kept.push_back(std::move(r));
            continue;
        }
        // What the old runner did to the station ends with it.
        if (station && !r->powered()) station->power_on();
        if (station && r->refusing()) station->refuse_connections(false);
        if (restarted[i]) kept.push_back(std::move(restarted[i]));
    }
    runners_ = std::move(kept);
    consulted_.clear();
    return true;
}

std::vector<std::vector<Scenario>> RunnerSet::groups() const {
    std::vector<std::vector<Scenario>> list;
    for (const auto& r : runners_) list.push_back(r->scenarios());
    return list;
}

void RunnerSet::clear(Station* station) {
    for (const auto& r : runners_) {
        if (station && !r->powered()) station->power_on();
        if (station && r->refusing()) station->refuse_connections(false);
    }
    runners_.clear();
    consulted_.clear();
}

void RunnerSet::scan(TimePoint now) {
    for (auto& r : runners_) r->scan(now);
}

Plan RunnerSet::before(const Incoming& incoming, std::span<const std::uint8_t> input) {
    consulted_.clear();
    std::vector<std::string> fired;
    for (auto& r : runners_) {
        consulted_.push_back(r->before(incoming, input));
        const auto& plan = consulted_.back();
        fired.insert(fired.end(), plan.decision.fired.begin(), plan.decision.fired.end());
        if (!plan.pass()) break;
    }
    Plan merged;
    if (consulted_.empty()) merged.incoming = &incoming;
    else merged = consulted_.back();   // the deciding plan, or the last (passing) one
    merged.decision.fired = std::move(fired);
    return merged;
}

Plan RunnerSet::before_frontend(const Incoming& incoming) {
    auto plan = before(incoming, {});
    consulted_.clear();
    return plan;
}

void RunnerSet::after(Plan& plan, const protocol::Outcome& outcome, std::vector<std::uint8_t>& response) {
    for (std::size_t i = 0; i < consulted_.size() && i < runners_.size(); ++i) {
        runners_[i]->after(consulted_[i], outcome, response);
        if (plan.delivery.plain() && !consulted_[i].delivery.plain()) plan.delivery = consulted_[i].delivery;
    }
    consulted_.clear();
}

std::vector<RunnerSet::Running> RunnerSet::running() const {
    std::vector<Running> list;
    for (const auto& r : runners_)
        for (const auto& s : r->scenarios()) list.push_back({&s, r->now_ms()});
    return list;
}

std::vector<FaultStats> RunnerSet::fault_stats() const {
    std::vector<FaultStats> list;
    for (const auto& r : runners_) {
        auto stats = r->fault_stats();
        list.insert(list.end(), stats.begin(), stats.end());
    }
    return list;
}

bool RunnerSet::enable_fault(const std::string& name, bool on) {
    bool found = false;
    for (auto& r : runners_) found = r->enable_fault(name, on) || found;
    return found;
}

}  // namespace slmp::scenarios
