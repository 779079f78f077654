// A plant for the plant and route tests: the options that start one from its
// configuration text, and each station's entry and first TCP and UDP port in
// its ready file.
#pragma once

#include <catch2/catch.hpp>

#include <cstdint>
#include <string>
#include <utility>
#include <vector>

#include "sim_process.hpp"

namespace slmp::test {

inline SimOptions plant_options(const std::string& config, std::vector<std::string> args = {}) {
    SimOptions options;
    options.plant = true;
    options.config_json = config;
    options.args = std::move(args);
    return options;
}

inline const nlohmann::json& station_in(const SimProcess& sim, const std::string& name) {
    for (const auto& s : sim.ready()["stations"])
        if (s["name"] == name) return s;
    FAIL("no station " << name << " in the ready file: " << sim.ready().dump());
    throw;
}

inline std::uint16_t tcp_of(const SimProcess& sim, const std::string& name) {
    return station_in(sim, name)["tcp"][0].get<std::uint16_t>();
}

inline std::uint16_t udp_of(const SimProcess& sim, const std::string& name) {
    return station_in(sim, name)["udp"][0].get<std::uint16_t>();
}

}  // namespace slmp::test
