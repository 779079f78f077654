// What the JW-51CM writes into data memory on its own, against the real
// binary (docs/jw51cm.md): the command completion record (§11) after commands
// over TCP and UDP, and the connection status flag byte (§12) as TCP clients
// connect and leave; bad parameters refused at start, naming them.
#include <catch2/catch.hpp>

#include <netinet/in.h>

#include <chrono>
#include <thread>
#include <vector>

#include "http_client.hpp"
#include "jw51cm_link.hpp"
#include "sim_process.hpp"
#include "sockets.hpp"

using namespace slmp::test;

namespace {

using jw51cm::ask;
using jw51cm::jw_tcp;
using jw51cm::jw_udp;
using jw51cm::request;
using jw51cm::response;

// The record: 32 bytes at register 19000 (file 0 0o5000, D256-D271); the
// flags at register 09776 (file 0 0o4776, D255's low byte).
constexpr const char* kConfig = R"({"kind": "sharp-jw", "jw51cm": {"tcp_port": 0, "udp_port": 0, "parameters": {
    "3660": "00 0A 00 00 20 00 00 80",
    "3764": "FE 09 00 80"}}})";

SimOptions reporting() { return jw51cm::jw_station(kConfig); }

// `count` bytes of data memory from D`word`, low byte first.
Bytes data_memory(std::uint16_t http, unsigned word, unsigned words) {
    auto values = http_get(http, "/api/devices/D" + std::to_string(word) + "?count=" + std::to_string(words)).json()["values"];
    Bytes out;
    for (const auto& v : values) {
        auto w = v.get<std::uint16_t>();
        out.push_back(static_cast<std::uint8_t>(w & 0xFF));
        out.push_back(static_cast<std::uint8_t>(w >> 8));
    }
    return out;
}

std::uint16_t local_port(const Socket& socket) {
    sockaddr_in addr{};
    socklen_t len = sizeof addr;
    ::getsockname(socket.fd(), reinterpret_cast<sockaddr*>(&addr), &len);
    return ntohs(addr.sin_port);
}

std::uint8_t flags(std::uint16_t http) { return data_memory(http, 255, 1)[0]; }

bool flags_become(std::uint16_t http, std::uint8_t want) {
    auto deadline = std::chrono::steady_clock::now() + std::chrono::seconds(10);
    while (std::chrono::steady_clock::now() < deadline) {
        if (flags(http) == want) return true;
        std::this_thread::sleep_for(std::chrono::milliseconds(20));
    }
    return false;
}

}  // namespace

TEST_CASE("JW-51CM completion record and status flags over TCP and UDP", "[jw51cm][jw51cm-reports]") {
    SimProcess sim(reporting());
    auto http = sim.http_port();
    CHECK(flags(http) == 0x80);   // UDP (connection 7) from power-on
    auto first = TcpClient::open(jw_tcp(sim));
    CHECK(ask(first, {0xE9}, 45) == response({0xE9, 0x00, 0x00}));
    CHECK(flags(http) == 0x81);   // the first TCP client is connection 0
    auto record = data_memory(http, 256, 16);
    CHECK(Bytes(record.begin(), record.begin() + 4) == Bytes({127, 0, 0, 1}));
    CHECK(record[4] == (local_port(first) & 0xFF));
    CHECK(record[5] == (local_port(first) >> 8));
    Bytes rest(26, 0x00);   // +06 connection 0, +07 00, +10 RSLT 00, +11-+13 00, +14 on 47 00 E9, then zeros
    rest[6] = 0x47;
    rest[8] = 0xE9;
    CHECK(Bytes(record.begin() + 6, record.end()) == rest);

    auto second = TcpClient::open(jw_tcp(sim));
    // 34 in write mode 0: RSLT 10, recorded as connection 1's, the command cut at 32 bytes.
    Bytes write{0x34, 0x00, 0x00, 0x09, 0x18, 0x00};
    for (std::uint8_t i = 0; i < 0x18; ++i) write.push_back(i);
    CHECK(ask(second, write, 44) == response({0x34, 0x10}));
    CHECK(flags(http) == 0x83);
    record = data_memory(http, 256, 16);
    CHECK(record[6] == 0x01);
    CHECK(record[8] == 0x10);
    CHECK(Bytes(record.begin() + 12, record.end()) ==
          Bytes({0x47, 0x00, 0x34, 0x00, 0x00, 0x09, 0x18, 0x00, 0x00, 0x01, 0x02, 0x03, 0x04, 0x05, 0x06, 0x07, 0x08, 0x09, 0x0A, 0x0B}));
    CHECK(data_memory(http, 272, 1) == Bytes({0x00, 0x00}));   // nothing past the area

    first.close();
    CHECK(flags_become(http, 0x82));
    UdpClient udp;
    REQUIRE(udp.send_to(jw_udp(sim), request({0xE8})));
    CHECK(udp.receive() == response({0xE8, 0x00, 0x00}));
    record = data_memory(http, 256, 8);
    CHECK(record[6] == 0x07);   // UDP is connection 7
    CHECK(record[8] == 0x00);
    CHECK(record[14] == 0xE8);
    auto third = TcpClient::open(jw_tcp(sim));   // takes the free number 0 again
    CHECK(ask(third, {0xE9}, 45) == response({0xE9, 0x00, 0x00}));
    CHECK(flags(http) == 0x83);
    CHECK(data_memory(http, 256, 4)[6] == 0x00);
    second.close();
    third.close();
    CHECK(flags_become(http, 0x80));
}

TEST_CASE("JW-51CM report parameters: a bad one is refused at start, naming it and the fix", "[jw51cm][jw51cm-reports]") {
    TempDir dir;
    auto size = dir.write("size.json", R"({"kind": "sharp-jw", "jw51cm": {"parameters": {"3660": "00 0A 00 00 08 00 00 80"}}})");
    auto r = run_sim({"--check-config", size.string()});
    CHECK(r.exit_code == 2);
    CHECK(r.err.find("parameter 3664") != std::string::npos);
    CHECK(r.err.find("16-64") != std::string::npos);
    auto flag = dir.write("flag.json", R"({"kind": "sharp-jw", "jw51cm": {"parameters": {"3764": "E0 01 09 80"}}})");
    r = run_sim({"--check-config", flag.string()});
    CHECK(r.exit_code == 2);
    CHECK(r.err.find("parameter 3764") != std::string::npos);
    auto long_value = dir.write("long.json", R"({"kind": "sharp-jw", "jw51cm": {"parameters": {"3764": "E0 01 00 80 00"}}})");
    r = run_sim({"--check-config", long_value.string()});
    CHECK(r.exit_code == 2);
    CHECK(r.err.find("runs past parameter 3767") != std::string::npos);
    auto outside = dir.write("outside.json", R"({"kind": "sharp-jw", "jw51cm": {"parameters": {"3700": "00"}}})");
    r = run_sim({"--check-config", outside.string()});
    CHECK(r.exit_code == 2);
    CHECK(r.err.find("/jw51cm/parameters/3700") != std::string::npos);
    CHECK(r.err.find("3660-3667") != std::string::npos);
    auto good = dir.write("good.json", R"({"kind": "sharp-jw", "jw51cm": {"parameters": {"3660": "00 0A 00 00 40 00 00 80", "3764": "E0 01 00 80"}}})");
    CHECK(run_sim({"--check-config", good.string()}).exit_code == 0);
}
