// A plant's stations in its ready file: each station's entry and its first
// TCP and UDP port, for the plant and route tests.
#pragma once

#include <catch2/catch.hpp>

#include <cstdint>
#include <string>

#include "sim_process.hpp"

namespace slmp::test {

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
