// Per-port settings of a real module against the real binary (issue 14): two
// TCP ports of one CPU with a remote password — the first guarded by it, the
// second not and with online change disabled — and UDP likewise. Bytes are
// built from the manual's layout (frames.hpp), independent of the encoder.
#include <catch2/catch.hpp>

#include "frames.hpp"
#include "link.hpp"
#include "sim_process.hpp"
#include "sockets.hpp"

using namespace slmp::test;

namespace {

const Wire kBin3{FrameKind::E3, Codec::Binary, 0};

// Timer 0010, then command, subcommand and data (binary).
Bytes body(std::uint16_t command, const Bytes& data) {
    return concat({{0x10, 0x00, std::uint8_t(command & 0xFF), std::uint8_t(command >> 8), 0x00, 0x00}, data});
}
const Bytes kReadD0 = body(0x0401, {0x00, 0x00, 0x00, 0xA8, 0x01, 0x00});
Bytes write_d0(std::uint16_t value) {
    return body(0x1401, {0x00, 0x00, 0x00, 0xA8, 0x01, 0x00, std::uint8_t(value & 0xFF), std::uint8_t(value >> 8)});
}
const Bytes kStop = body(0x1002, {0x01, 0x00});

// The 9-byte error information of an own-station request.
Bytes error_info(std::uint16_t command) {
    return {0x00, 0xFF, 0xFF, 0x03, 0x00, std::uint8_t(command & 0xFF), std::uint8_t(command >> 8), 0x00, 0x00};
}

Bytes round_trip(TcpClient& client, const Bytes& request_body) {
    REQUIRE(client.send(request_frame(kBin3, request_body)));
    Bytes frame;
    REQUIRE(client.response(&frame));
    return frame;
}

}  // namespace

TEST_CASE("remote password and online change per port, over TCP", "[port_settings][tcp][config]") {
    SimOptions options;
    options.tcp_ports = 0;
    options.udp_ports = 0;
    options.config_json = R"({"cpu": {"password": "secret1"}, "ports": [
        {"transport": "tcp", "port": 0},
        {"transport": "tcp", "port": 0, "remote_password": false, "online_change": false}]})";
    SimProcess sim(options);
    auto guarded = TcpClient::open(sim.tcp_port(0));
    auto open = TcpClient::open(sim.tcp_port(1));

    // The first port starts locked: C201.
    CHECK(round_trip(guarded, kReadD0) == expected_response(kBin3, error_info(0x0401), 0xC201));
    // The second serves reads without Unlock, and refuses writes while the CPU is in RUN: 0055.
    CHECK(round_trip(open, kReadD0) == expected_response(kBin3, word_data(kBin3, {0})));
    CHECK(round_trip(open, write_d0(5)) == expected_response(kBin3, error_info(0x1401), 0x0055));
    CHECK(round_trip(open, kReadD0) == expected_response(kBin3, word_data(kBin3, {0})));
    // In STOP the write is served there.
    CHECK(round_trip(open, kStop) == expected_response(kBin3, Bytes{}));
    CHECK(round_trip(open, write_d0(5)) == expected_response(kBin3, Bytes{}));
    CHECK(round_trip(open, kReadD0) == expected_response(kBin3, word_data(kBin3, {5})));
    // The guarded port is still locked.
    CHECK(round_trip(guarded, kReadD0) == expected_response(kBin3, error_info(0x0401), 0xC201));
}

TEST_CASE("system protect from the configuration refuses writes over the wire: 4004", "[port_settings][tcp][config]") {
    SimOptions options;
    options.config_json = R"({"cpu": {"system_protect": true}})";
    SimProcess sim(options);
    auto client = TcpClient::open(sim.tcp_port());
    CHECK(round_trip(client, write_d0(5)) == expected_response(kBin3, error_info(0x1401), 0x4004));
    CHECK(round_trip(client, kStop) == expected_response(kBin3, error_info(0x1002), 0x4004));
    CHECK(round_trip(client, kReadD0) == expected_response(kBin3, word_data(kBin3, {0})));
}
