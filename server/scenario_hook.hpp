// The one hook between the listeners and the engine (STYLE.md §6.21): every
// request, TCP or UDP, goes through ScenarioHook::process(), which asks the
// scenarios what to do before the engine (forced end code, recorded answer,
// no response, close, reset, power cut), runs the engine, and asks again
// after it (corruption, delay, split, coalesce), and records the exchange
// when --record is on. With no scenario and no recording it is one branch
// in front of Engine::process().
#pragma once

#include <chrono>
#include <map>
#include <memory>
#include <span>
#include <string>
#include <vector>

#include "protocol/engine.hpp"
#include "scenarios/faults.hpp"
#include "scenarios/recording.hpp"
#include "scenarios/runner.hpp"
#include "server/activity.hpp"

namespace slmp::server {

// Who sent a request.
struct Link {
    Transport transport = Transport::Tcp;
    std::string_view peer;   // "tcp:127.0.0.1:50312"
};

// What a listener does with one frame.
struct Handled {
    protocol::Outcome outcome;
    scenarios::Delivery delivery;   // how to send outcome.response
    bool reset = false;             // close with RST (SO_LINGER 0) instead of FIN
};

class ScenarioHook : public ActivityObserver {
public:
    ScenarioHook() = default;
    ~ScenarioHook();

    // Scenarios start running against `cpu` (checks their devices; throws config::ConfigError).
    void start(std::vector<scenarios::Scenario> scenarios, devicemodel::Cpu& cpu, scenarios::Station& station);
    // Records every exchange to `file` from now on (throws config::ConfigError).
    void record(const std::string& file, const std::string& profile);

    Handled process(protocol::Engine& engine, std::span<const std::uint8_t> input, protocol::DataCodePolicy policy,
                    protocol::Session& session, const Link& link);
    // After every CPU scan (server/scan_loop.cpp).
    void scanned(std::chrono::steady_clock::time_point now);

    bool active() const { return runner_ || recorder_; }
    // Every fault: how often it matched and fired (for logs and the HTTP API).
    std::vector<scenarios::FaultStats> fault_stats() const;
    // One log line per fault that fired, at shutdown.
    void log_summary() const;

    void on_opened(const Connection& connection) override;
    void on_closed(const Connection& connection, std::string_view why) override;

private:
    std::unique_ptr<scenarios::ScenarioRunner> runner_;
    std::unique_ptr<scenarios::RecordingWriter> recorder_;
    std::map<std::uint64_t, std::uint64_t> ordinals_;   // TCP connection id -> n-th connection since start
    std::uint64_t connections_ = 0;
};

// A peer text "tcp:127.0.0.1:50312" without its transport: "127.0.0.1:50312".
std::string_view peer_address(std::string_view peer);

}  // namespace slmp::server
