// What every listener shares: the CPU, the protocol engine in front of it, and
// the logging of request outcomes. Everything runs on one io_context thread,
// so none of this needs a lock (STYLE.md §6.19).
#pragma once

#include <cstdint>
#include <string>

#include "devicemodel/cpu.hpp"
#include "protocol/engine.hpp"

namespace slmp::server {

struct Core {
    Core(devicemodel::CpuProfile profile, protocol::EngineOptions options)
        : cpu(std::move(profile)), engine(cpu, options) {}

    devicemodel::Cpu cpu;
    protocol::Engine engine;
    std::uint64_t next_session_id = 1;
};

// Logs one handled frame: a debug line saying why for every rejected or
// ignored request (the "connects but times out" puzzle), a trace line otherwise.
void log_outcome(const std::string& peer, const protocol::Outcome& outcome);

}  // namespace slmp::server
