// The Sharp JW-51CM computer link against the real binary (docs/jw51cm.md):
// a "kind": "sharp-jw" station over TCP and UDP — round trips in files 0 and
// 1, relays, T/C, system memory, program, clock, run/stop; write-permission
// refusals, wrong lengths, split and coalesced TCP segments, garbage; and a
// MELSEC station serving SLMP and JW-51CM on one memory.
#include <catch2/catch.hpp>

#include <vector>

#include "frames.hpp"
#include "http_client.hpp"
#include "sim_process.hpp"
#include "sockets.hpp"
#include "jw51cm_link.hpp"

using namespace slmp::test;

namespace {

using jw51cm::request;
using jw51cm::response;

SimOptions sharp_jw() {
    return jw51cm::jw_station(R"({"kind": "sharp-jw", "jw51cm": {"tcp_port": 0, "udp_port": 0,
                              "timer_attributes": {"0000": "0008", "0001": "000A"}}})");
}

using jw51cm::ask;
using jw51cm::jw_tcp;
using jw51cm::jw_udp;

}  // namespace

TEST_CASE("JW-51CM over TCP: round trips, modes and the stop owner", "[jw51cm]") {
    SimProcess sim(sharp_jw());
    REQUIRE(sim.tcp_ports().empty());
    auto client = TcpClient::open(jw_tcp(sim));
    // Mode 0 at power-on: a register write is refused with RSLT 10 and writes nothing.
    CHECK(ask(client, {0xE9}, 45) == response({0xE9, 0x00, 0x00}));
    CHECK(ask(client, {0x34, 0x00, 0x00, 0x08, 0x02, 0x00, 0x12, 0x34}, 44) == response({0x34, 0x10}));
    CHECK(ask(client, {0xF9, 0x01}, 45) == response({0xF9, 0x00, 0x01}));
    CHECK(ask(client, {0x34, 0x00, 0x00, 0x08, 0x02, 0x00, 0x12, 0x34}, 49) == response({0x34, 0x00, 0x00, 0x00, 0x08, 0x02, 0x00}));
    CHECK(ask(client, {0x24, 0x00, 0x00, 0x08, 0x02, 0x00}, 51) == response({0x24, 0x00, 0x00, 0x00, 0x08, 0x02, 0x00, 0x12, 0x34}));
    // Register 09000 is D0, low byte at the lower address.
    CHECK(http_get(sim.http_port(), "/api/devices/D0").json()["values"] == nlohmann::json({0x3412}));
    // File 1 on ZR; relays on M (relay 04033 = M2075).
    CHECK(ask(client, {0x35, 0x01, 0x00, 0x30, 0x03, 0x00, 0x5A}, 49) == response({0x35, 0x00, 0x01, 0x00, 0x30, 0x03, 0x00}));
    CHECK(ask(client, {0x24, 0x01, 0xFF, 0x2F, 0x03, 0x00}, 52) ==
          response({0x24, 0x00, 0x01, 0xFF, 0x2F, 0x03, 0x00, 0x00, 0x5A, 0x5A}));
    CHECK(ask(client, {0x30, 0x00, 0x03, 0x01, 0x03, 0x01}, 48) == response({0x30, 0x00, 0x00, 0x03, 0x01, 0x03}));
    CHECK(ask(client, {0x20, 0x00, 0x03, 0x01, 0x03}, 49) == response({0x20, 0x00, 0x00, 0x03, 0x01, 0x03, 0x01}));
    CHECK(http_get(sim.http_port(), "/api/devices/M2075").json()["values"] == nlohmann::json({1}));
    // T/C: the values are the station's TN, with the configured attributes.
    REQUIRE(http_put(sim.http_port(), "/api/devices/TN0?as=words", R"({"values": [37428, 54904]})").status == 200);
    CHECK(ask(client, {0x23, 0x00, 0x00, 0x02, 0x00}, 54) ==
          response({0x23, 0x00, 0x00, 0x00, 0x02, 0x00, 0x34, 0x92, 0x78, 0xD6, 0x08, 0x0A}));
    CHECK(ask(client, {0x32, 0x02, 0x00, 0x01}, 46) == response({0x32, 0x00, 0x02, 0x00}));
    // Program and system memory need mode 2 and STOP.
    Bytes program{0x14, 0x08, 0x00, 0x00, 0x03, 0x00, 0x00, 0x80, 0x00, 0x91, 0x08, 0xB8};
    CHECK(ask(client, program, 44) == response({0x14, 0x10}));
    CHECK(ask(client, {0xF9, 0x02}, 45) == response({0xF9, 0x00, 0x02}));
    CHECK(ask(client, program, 44) == response({0x14, 0x06}));
    CHECK(ask(client, {0xF8, 0x01}, 45) == response({0xF8, 0x00, 0x01}));
    CHECK(ask(client, {0xE8}, 45) == response({0xE8, 0x00, 0x02}));
    CHECK(http_get(sim.http_port(), "/api/state").body.find("STOP") != std::string::npos);
    CHECK(ask(client, program, 49) == response({0x14, 0x00, 0x08, 0x00, 0x00, 0x03, 0x00}));
    CHECK(ask(client, {0x04, 0x08, 0x00, 0x00, 0x03, 0x00}, 55) ==
          response({0x04, 0x00, 0x08, 0x00, 0x00, 0x03, 0x00, 0x00, 0x80, 0x00, 0x91, 0x08, 0xB8}));
    CHECK(ask(client, {0x54, 0x08, 0x84, 0x00, 0x02, 0x00, 0x81, 0x00}, 49) == response({0x54, 0x00, 0x08, 0x84, 0x00, 0x02, 0x00}));
    CHECK(ask(client, {0x44, 0x08, 0x84, 0x00, 0x02, 0x00}, 51) == response({0x44, 0x00, 0x08, 0x84, 0x00, 0x02, 0x00, 0x81, 0x00}));
    CHECK(ask(client, {0x32, 0x02, 0x00, 0x00}, 44) == response({0x32, 0x13}));   // T/C while stopped
    CHECK(ask(client, {0xF8, 0x00}, 45) == response({0xF8, 0x00, 0x00}));
    CHECK(ask(client, {0xE8}, 45) == response({0xE8, 0x00, 0x00}));
    // Clock: stopped first (CTRL 01), so no second or midnight can tick over between set and read.
    CHECK(ask(client, {0xB3, 0x18, 0x10, 0x00, 0x01}, 44) == response({0xB3, 0x00}));
    CHECK(ask(client, {0xB2, 0x98, 0x01, 0x23, 0x05}, 44) == response({0xB2, 0x00}));
    CHECK(ask(client, {0xA2}, 48) == response({0xA2, 0x00, 0x98, 0x01, 0x23, 0x05}));
    CHECK(ask(client, {0xA3}, 47) == response({0xA3, 0x00, 0x18, 0x10, 0x00}));
}

TEST_CASE("JW-51CM over TCP: split and coalesced segments, errors, garbage", "[jw51cm]") {
    SimProcess sim(sharp_jw());
    auto client = TcpClient::open(jw_tcp(sim));
    auto read = request({0x24, 0x00, 0x00, 0x08, 0x02, 0x00});
    REQUIRE(client.send(std::span(read).first(20)));
    REQUIRE(client.send(std::span(read).subspan(20, 25)));
    REQUIRE(client.send(std::span(read).subspan(45)));
    CHECK(client.read_exactly(51) == response({0x24, 0x00, 0x00, 0x00, 0x08, 0x02, 0x00, 0x00, 0x00}));
    auto both = request({0xE9});
    auto more = request({0xA3});
    both.insert(both.end(), more.begin(), more.end());
    both.insert(both.end(), read.begin(), read.end());
    REQUIRE(client.send(both));
    CHECK(client.read_exactly(45) == response({0xE9, 0x00, 0x00}));
    auto time = client.read_exactly(47);
    CHECK(time.size() == 47);
    CHECK(client.read_exactly(51) == response({0x24, 0x00, 0x00, 0x00, 0x08, 0x02, 0x00, 0x00, 0x00}));
    CHECK(ask(client, {0x24, 0x00, 0xFF, 0x1F, 0x02, 0x00}, 44) == response({0x24, 0x01}));   // past file 0
    CHECK(ask(client, {0x24, 0x00, 0x00, 0x08, 0x01, 0x04}, 44) == response({0x24, 0x01}));   // 1025 bytes
    // Garbage (a wrong ID): 01, the buffer dropped, and the connection still serves.
    Bytes junk(43, 0xEE);
    REQUIRE(client.send(junk));
    auto refused = client.read_exactly(44);
    REQUIRE(refused.size() == 44);
    CHECK(refused[43] == 0x01);
    CHECK(ask(client, {0xE9}, 45) == response({0xE9, 0x00, 0x00}));
}

TEST_CASE("JW-51CM over UDP: one request per datagram, wrong lengths refused", "[jw51cm]") {
    SimProcess sim(sharp_jw());
    UdpClient udp;
    REQUIRE(udp.send_to(jw_udp(sim), request({0xF9, 0x01})));
    CHECK(udp.receive() == response({0xF9, 0x00, 0x01}));
    REQUIRE(udp.send_to(jw_udp(sim), request({0x34, 0x00, 0x10, 0x08, 0x01, 0x00, 0x77})));
    CHECK(udp.receive() == response({0x34, 0x00, 0x00, 0x10, 0x08, 0x01, 0x00}));
    REQUIRE(udp.send_to(jw_udp(sim), request({0x24, 0x00, 0x10, 0x08, 0x01, 0x00})));
    CHECK(udp.receive() == response({0x24, 0x00, 0x00, 0x10, 0x08, 0x01, 0x00, 0x77}));
    // The write mode is the unit's: TCP sees mode 1 too.
    auto client = TcpClient::open(jw_tcp(sim));
    CHECK(ask(client, {0xE9}, 45) == response({0xE9, 0x00, 0x01}));
    REQUIRE(udp.send_to(jw_udp(sim), request({0x24, 0x00, 0x10, 0x08, 0x01, 0x00, 0x00})));   // one byte too many
    CHECK(udp.receive() == response({0x24, 0x01}));
}

TEST_CASE("JW-51CM and SLMP on one MELSEC station", "[jw51cm]") {
    SimOptions options;
    options.udp_ports = 0;
    options.config_json = R"({"jw51cm": {"tcp_port": 0, "udp_port": null}})";
    SimProcess sim(options);
    REQUIRE(sim.ready().at("jw51cm").at("udp").empty());
    auto slmp = TcpClient::open(sim.tcp_port());
    auto jw = TcpClient::open(jw_tcp(sim));
    // SLMP 1401: D100 = 0x1234; JW reads register bytes 0o4000 + 200 (D100): 34 12.
    REQUIRE(slmp.send(hex("500000FFFF03000E00100001140000640000A801003412")));
    CHECK(slmp.read_exactly(11) == hex("D00000FFFF030002000000"));
    CHECK(ask(jw, {0x24, 0x00, 0xC8, 0x08, 0x02, 0x00}, 51) == response({0x24, 0x00, 0x00, 0xC8, 0x08, 0x02, 0x00, 0x34, 0x12}));
}
