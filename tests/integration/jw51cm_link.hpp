// A JW-51CM face of a running slmp-sim, for the integration tests: its ports
// from the ready file and one request/answer over TCP.
#pragma once

#include <catch2/catch.hpp>

#include <cstdint>

#include "sim_process.hpp"
#include "sockets.hpp"
#include "support/jw51cm_frames.hpp"

namespace slmp::test::jw51cm {

// A JW-51CM-only simulator (no SLMP ports) with this configuration.
inline SimOptions jw_station(const char* config_json) {
    SimOptions options;
    options.tcp_ports = 0;
    options.udp_ports = 0;
    options.config_json = config_json;
    return options;
}

inline std::uint16_t jw_tcp(const SimProcess& sim) { return sim.ready().at("jw51cm").at("tcp").at(0).get<std::uint16_t>(); }
inline std::uint16_t jw_udp(const SimProcess& sim) { return sim.ready().at("jw51cm").at("udp").at(0).get<std::uint16_t>(); }

// Sends a request (what follows the ID byte) and reads an answer of `answer_bytes`.
inline Bytes ask(TcpClient& client, const Bytes& after_id, std::size_t answer_bytes) {
    REQUIRE(client.send(request(after_id)));
    return client.read_exactly(answer_bytes);
}

}  // namespace slmp::test::jw51cm
