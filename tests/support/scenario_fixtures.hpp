// Helpers for the scenario unit tests: a scenario from JSON text, a fake
// clock, device values by address text.
#pragma once

#include <catch2/catch.hpp>

#include <chrono>
#include <string>
#include <vector>

#include "config/config.hpp"
#include "devicemodel/cpu.hpp"
#include "scenarios/loader.hpp"
#include "scenarios/runner.hpp"

namespace slmp::test {

inline scenarios::Scenario scenario(const std::string& json) { return scenarios::parse_scenario(json, "test.json"); }

// Time points on a fake steady clock: at(0) is the first scan.
inline std::chrono::steady_clock::time_point at(double ms) {
    return std::chrono::steady_clock::time_point{} + std::chrono::hours(1) +
           std::chrono::microseconds(static_cast<std::int64_t>(ms * 1000));
}

inline devicemodel::DeviceAddress addr(const std::string& text) { return *devicemodel::parse_address(text); }

inline std::uint32_t value(const devicemodel::Cpu& cpu, const std::string& address) {
    auto a = addr(address);
    return cpu.memory().value(*a.spec, a.number);
}
inline void set(devicemodel::Cpu& cpu, const std::string& address, std::uint32_t v) {
    auto a = addr(address);
    cpu.memory().set_value(*a.spec, a.number, v);
}

// A CPU, a runner over it and the events it logged. The CPU's own scan runs
// before the runner's, as in the server's scan loop.
struct ScenarioRig {
    // `config_json`: a configuration whose "labels" (and "structures") the CPU declares first.
    explicit ScenarioRig(const std::string& json, const std::string& profile = "R08CPU", const std::string& config_json = "")
        : cpu(config::load_profile(profile).cpu) {
        if (!config_json.empty()) config::declare_labels(cpu, config::parse_server_config(config_json, "config.json").labels);
        std::vector<scenarios::Scenario> list;
        list.push_back(scenario(json));
        runner = std::make_unique<scenarios::ScenarioRunner>(
            std::move(list), cpu, [this](scenarios::EventLevel, const std::string& line) { events.push_back(line); });
    }
    void scan(double ms) {
        cpu.runtime().scan(cpu.memory(), at(ms), {});
        runner->scan(at(ms));
    }
    // Scans every `step` ms from `from` to `to` (inclusive).
    void scan_through(double from, double to, double step = 10) {
        for (double t = from; t <= to + 1e-9; t += step) scan(t);
    }
    std::uint32_t operator[](const std::string& address) const { return value(cpu, address); }

    devicemodel::Cpu cpu;
    std::vector<std::string> events;
    std::unique_ptr<scenarios::ScenarioRunner> runner;
};

}  // namespace slmp::test
