// What every listener shares: the CPU, the protocol engine in front of it, and
// the logging of request outcomes. Everything runs on one io_context thread,
// so none of this needs a lock (STYLE.md §6.19).
#pragma once

#include <cstdint>
#include <functional>
#include <memory>
#include <vector>
#include <string>

#include "devicemodel/cpu.hpp"
#include "protocol/engine.hpp"
#include "server/activity.hpp"
#include "server/scenario_hook.hpp"

namespace slmp::server {

struct Core {
    Core(config::Profile profile, protocol::EngineOptions options)
        : cpu(std::move(profile.cpu)), engine(cpu, std::move(profile.port), options) {}

    devicemodel::Cpu cpu;
    protocol::Engine engine;
    std::vector<std::unique_ptr<devicemodel::Cpu>> other_cpus;   // CPU No.2–4 of a multi-CPU system
    std::uint64_t next_session_id = 1;
    Activity activity;   // requests and connections, for metrics and the HTTP API
    // Scenarios and recording: the one hook around the engine (server/scenario_hook.hpp).
    ScenarioHook scenario;
    // Called by a listener after a Remote RESET (Outcome::Action::Restart): the CPU
    // has restarted; the server closes every connection (server.cpp).
    std::function<void()> on_restart;
};

// Logs one handled frame: a debug line saying why for every rejected or
// ignored request (the "connects but times out" puzzle), a trace line otherwise.
void log_outcome(const std::string& peer, const protocol::Outcome& outcome);

}  // namespace slmp::server
