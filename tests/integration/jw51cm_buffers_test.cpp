// The JW-51CM's designated and ring buffers against the real binary
// (docs/jw51cm.md): a "sharp-jw" station whose parameter image defines them,
// the PLC side played over HTTP (/api/devices, /api/jw51cm/rings), the host
// side over TCP and UDP with exact bytes; a bad parameter refused at start.
#include <catch2/catch.hpp>

#include <vector>

#include "http_client.hpp"
#include "sim_process.hpp"
#include "sockets.hpp"
#include "jw51cm_link.hpp"

using namespace slmp::test;

namespace {

using jw51cm::request;
using jw51cm::response;

// Designated buffer 01: 16 bytes at register 09100 (D32). Ring 01: the manual's,
// PLC -> host, 1 KB at register 29000, pointers at 09000 (D0, D1). Ring 02:
// host -> PLC, 256 bytes at file 0 0x1000, pointers at file 0 0x0900 (D128, D129).
constexpr const char* kConfig = R"({"kind": "sharp-jw", "jw51cm": {"tcp_port": 0, "udp_port": 0, "parameters": {
    "1010": "40 08 00 00 10 00 00 80",
    "1410": "00 08 00 01 0C 00 04 80",
    "1420": "00 09 00 81 10 00 01 80"}}})";

SimOptions buffered() { return jw51cm::jw_station(kConfig); }

using jw51cm::ask;
using jw51cm::jw_tcp;
using jw51cm::jw_udp;

HttpResponse post(std::uint16_t port, const std::string& target, const std::string& body = "") {
    return http(port, "POST", target, body);
}

}  // namespace

TEST_CASE("JW-51CM buffers over TCP: the manual's examples, the PLC side over HTTP", "[jw51cm][jw51cm-buffers]") {
    SimProcess sim(buffered());
    auto port = sim.http_port();
    auto client = TcpClient::open(jw_tcp(sim));
    // Vector 19: the buffer is device memory the PLC side writes (D32 = register 09100-09101).
    REQUIRE(http_put(port, "/api/devices/D32?as=words", R"({"values": [8721, 34884]})").status == 200);
    CHECK(ask(client, {0x28, 0x01, 0x01, 0x00, 0x00, 0x04, 0x00}, 54) ==
          response({0x28, 0x00, 0x01, 0x01, 0x00, 0x00, 0x04, 0x00, 0x11, 0x22, 0x44, 0x88}));
    CHECK(ask(client, {0x68, 0x01}, 55) == response({0x68, 0x00, 0x01, 0x01, 0x01, 0x00, 0x00, 0x00, 0x00, 0x40, 0x08, 0x10, 0x00}));
    CHECK(ask(client, {0x28, 0x02, 0x01, 0x00, 0x00, 0x04, 0x00}, 44) == response({0x28, 0x48}));
    CHECK(ask(client, {0x28, 0x01, 0x01, 0x0E, 0x00, 0x04, 0x00}, 44) == response({0x28, 0x4A}));
    CHECK(ask(client, {0x38, 0x01, 0x01, 0x00, 0x00, 0x01, 0x00, 0x99}, 44) == response({0x38, 0x10}));

    // Vector 23: the PLC puts 3 bytes, the host reads them (non-confirm), the PLC
    // puts 4 more, the host reads them with confirmation: RP 3, then 82 moves it.
    auto put = post(port, "/api/jw51cm/rings/1", R"({"data": "AABBCC"})");
    REQUIRE(put.status == 200);
    CHECK(put.json()["wp"] == 3);
    CHECK(put.json()["written"] == 3);
    CHECK(ask(client, {0x29, 0x01, 0x01, 0x01, 0x00, 0x00}, 54) ==
          response({0x29, 0x00, 0x01, 0x01, 0x00, 0x00, 0x03, 0x00, 0x00, 0xAA, 0xBB, 0xCC}));
    REQUIRE(post(port, "/api/jw51cm/rings/01", R"({"data": "12 34 56 78"})").status == 200);
    CHECK(ask(client, {0x29, 0x01, 0x81, 0x01, 0x04, 0x00}, 55) ==
          response({0x29, 0x00, 0x01, 0x01, 0x03, 0x00, 0x04, 0x00, 0x00, 0x12, 0x34, 0x56, 0x78}));
    auto ring = http_get(port, "/api/jw51cm/rings/1").json();
    CHECK(ring["rp"] == 3);
    CHECK(ring["awaiting_confirm"] == nlohmann::json({{"from", 3}, {"bytes", 4}}));
    CHECK(ask(client, {0x29, 0x01, 0x82, 0x01, 0x00, 0x00}, 51) == response({0x29, 0x00, 0x01, 0x01, 0x07, 0x00, 0x00, 0x00, 0x00}));
    ring = http_get(port, "/api/jw51cm/rings/1").json();
    CHECK(ring["rp"] == 7);
    CHECK(ring["unread"] == 0);
    CHECK(ring["direction"] == "plc-to-host");
    // The pointers are data memory: RP is D1.
    CHECK(http_get(port, "/api/devices/D1").json()["values"] == nlohmann::json({7}));

    // Vector 24's shape on ring 02 (host -> PLC): write with confirmation, confirm, and the PLC takes it.
    CHECK(ask(client, {0xF9, 0x01}, 45) == response({0xF9, 0x00, 0x01}));
    CHECK(ask(client, {0x39, 0x02, 0x81, 0x01, 0x04, 0x00, 0x01, 0x02, 0x03, 0x04}, 52) ==
          response({0x39, 0x00, 0x02, 0x01, 0x00, 0x00, 0x04, 0x00, 0xFB, 0x00}));
    auto nothing = post(port, "/api/jw51cm/rings/2/take");
    REQUIRE(nothing.status == 200);
    CHECK(nothing.json()["data"] == "");   // not confirmed yet
    CHECK(ask(client, {0x39, 0x02, 0x82, 0x01, 0x00, 0x00}, 52) ==
          response({0x39, 0x00, 0x02, 0x01, 0x04, 0x00, 0x00, 0x00, 0xFB, 0x00}));
    auto taken = post(port, "/api/jw51cm/rings/2/take", R"({"count": 3})");
    REQUIRE(taken.status == 200);
    CHECK(taken.json()["data"] == "010203");
    CHECK(taken.json()["rp"] == 3);
    CHECK(post(port, "/api/jw51cm/rings/2/take").json()["data"] == "04");
    // Ring 02 full: 43, and nothing moves.
    REQUIRE(http_put(port, "/api/devices/D128?as=words", R"({"values": [16, 17]})").status == 200);   // WP 16, RP 17
    CHECK(ask(client, {0x39, 0x02, 0x01, 0x01, 0x01, 0x00, 0xEE}, 44) == response({0x39, 0x43}));
    CHECK(ask(client, {0x29, 0x02, 0x01, 0x01, 0x00, 0x00}, 44) == response({0x29, 0x40}));   // the other direction
    CHECK(ask(client, {0x29, 0x03, 0x01, 0x01, 0x00, 0x00}, 44) == response({0x29, 0x40}));   // not defined
    // The parameters' ring 04 is not defined; 79 on it: 48.
    CHECK(ask(client, {0x79, 0x04, 0x01, 0x02, 0x03, 0x00, 0x00, 0x03, 0x00, 0x10, 0x00, 0x81, 0x00, 0x80}, 44) == response({0x79, 0x48}));
    // 79 on ring 01 (direct): WP and RP only.
    CHECK(ask(client, {0x79, 0x01, 0x01, 0x01, 0x00, 0x00, 0x00, 0x09, 0x00, 0x08, 0x00, 0x80, 0x00, 0x04}, 45) == response({0x79, 0x00, 0x01}));
    CHECK(http_get(port, "/api/devices/D0?count=2").json()["values"] == nlohmann::json({9, 8}));
}

TEST_CASE("JW-51CM ring buffers over UDP, and the HTTP resource's refusals", "[jw51cm][jw51cm-buffers]") {
    SimProcess sim(buffered());
    auto port = sim.http_port();
    UdpClient udp;
    REQUIRE(post(port, "/api/jw51cm/rings/1", R"({"data": "0102030405"})").status == 200);
    // Vector 25's shape: 69 on ring 01 (direct, info 09000, ring 29000, 1 KB; PLC -> host answers DIR 80).
    REQUIRE(udp.send_to(jw_udp(sim), request({0x69, 0x01})));
    CHECK(udp.receive() == response({0x69, 0x00, 0x01, 0x01, 0x01, 0x00, 0x00, 0x08, 0x00, 0x00, 0x0C, 0x05, 0x00, 0x00, 0x00, 0x80, 0x00, 0x04}));
    REQUIRE(udp.send_to(jw_udp(sim), request({0x29, 0x01, 0x01, 0x01, 0x02, 0x00})));
    CHECK(udp.receive() == response({0x29, 0x00, 0x01, 0x01, 0x00, 0x00, 0x02, 0x00, 0x01, 0x01, 0x02}));
    // A confirm over TCP counts for a read made over UDP: the confirm is the unit's.
    REQUIRE(udp.send_to(jw_udp(sim), request({0x29, 0x01, 0x81, 0x01, 0x00, 0x00})));
    CHECK(udp.receive() == response({0x29, 0x00, 0x01, 0x01, 0x02, 0x00, 0x03, 0x00, 0x00, 0x03, 0x04, 0x05}));
    auto client = TcpClient::open(jw_tcp(sim));
    CHECK(ask(client, {0x29, 0x01, 0x82, 0x01, 0x00, 0x00}, 51) == response({0x29, 0x00, 0x01, 0x01, 0x05, 0x00, 0x00, 0x00, 0x00}));
    REQUIRE(udp.send_to(jw_udp(sim), request({0x69, 0x10})));
    CHECK(udp.receive() == response({0x69, 0x01}));

    // The HTTP side refuses what the ladder could not do, naming the fix.
    auto wrong_way = post(port, "/api/jw51cm/rings/2", R"({"data": "01"})");
    CHECK(wrong_way.status == 409);
    CHECK(wrong_way.body.find("take") != std::string::npos);
    CHECK(post(port, "/api/jw51cm/rings/1/take").status == 409);
    auto undefined = post(port, "/api/jw51cm/rings/5", R"({"data": "01"})");
    CHECK(undefined.status == 404);
    CHECK(undefined.body.find("1450") != std::string::npos);
    CHECK(post(port, "/api/jw51cm/rings/1", R"({"data": "0G"})").status == 400);
    CHECK(post(port, "/api/jw51cm/rings/16", R"({"data": "01"})").status == 400);
    std::string too_much(2 * 1024, 'A');   // 1024 bytes; 1023 fit (WP never reaches RP)
    auto full = post(port, "/api/jw51cm/rings/1", R"({"data": ")" + too_much + R"("})");
    CHECK(full.status == 409);
    CHECK(full.body.find("1023 bytes free") != std::string::npos);
    auto list = http_get(port, "/api/jw51cm/rings").json()["rings"];
    REQUIRE(list.size() == 16);
    CHECK(list[1]["definition"] == "direct");
    CHECK(list[2]["direction"] == "host-to-plc");
    CHECK(list[3]["definition"] == "none");
}

TEST_CASE("JW-51CM buffer parameters: a bad one is refused at start, naming it", "[jw51cm][jw51cm-buffers]") {
    TempDir dir;
    auto bad = dir.write("bad.json", R"({"kind": "sharp-jw", "jw51cm": {"parameters": {"1410": "00 08 00 01 0D 00 04 80"}}})");
    auto r = run_sim({"--check-config", bad.string()});
    CHECK(r.exit_code == 2);
    CHECK(r.err.find("parameter 1413") != std::string::npos);
    auto address = dir.write("address.json", R"({"kind": "sharp-jw", "jw51cm": {"parameters": {"0000": "C0"}}})");
    r = run_sim({"--check-config", address.string()});
    CHECK(r.exit_code == 2);
    CHECK(r.err.find("/jw51cm/parameters/0000") != std::string::npos);
}
