// The JW-51CM's SEND/RECEIVE, data-memory start method (docs/jw51cm.md): a
// plant of JW stations on 127.0.0.1 whose units move data memory between them
// as the control block asks — SEND and RECEIVE over TCP (opened and closed
// with ADR_B 177777/177776) and over UDP, FLAGS and the status flag byte as
// they go, and a partner that is not there: FLAGS 60 when the timer runs
// out on the station's frozen clock, stepped over HTTP.
#include <catch2/catch.hpp>

#include <netinet/in.h>

#include <chrono>
#include <string>
#include <thread>

#include "http_client.hpp"
#include "jw51cm_link.hpp"
#include "plant_ports.hpp"
#include "sim_process.hpp"
#include "sockets.hpp"

using namespace slmp::test;

namespace {

using jw51cm::ask;
using jw51cm::request;
using jw51cm::response;

// A port nothing listens on now, on 127.0.0.1 (`udp`: a UDP one).
std::uint16_t free_port(bool udp = false) {
    int fd = ::socket(AF_INET, udp ? SOCK_DGRAM : SOCK_STREAM, 0);
    auto addr = loopback(0, "127.0.0.1");
    REQUIRE(::bind(fd, reinterpret_cast<sockaddr*>(&addr), sizeof addr) == 0);
    socklen_t len = sizeof addr;
    ::getsockname(fd, reinterpret_cast<sockaddr*>(&addr), &len);
    ::close(fd);
    return ntohs(addr.sin_port);
}

std::string port_bytes(std::uint16_t port) {
    char text[8];
    std::snprintf(text, sizeof text, "%02X %02X", port & 0xFF, port >> 8);
    return text;
}

// A station table entry: valid, station, port, 127.0.0.1.
std::string entry(const char* station, std::uint16_t port) { return std::string("01 ") + station + " " + port_bytes(port) + " 7F 00 00 01"; }

std::string devices(const std::string& station, const std::string& device) {
    return "/api/stations/" + station + "/devices/" + device;
}

std::vector<std::uint16_t> words(std::uint16_t api, const std::string& station, const std::string& device, unsigned count) {
    auto values = http_get(api, devices(station, device) + "?count=" + std::to_string(count)).json()["values"];
    std::vector<std::uint16_t> out;
    for (const auto& v : values) out.push_back(v.get<std::uint16_t>());
    return out;
}

void put_words(std::uint16_t api, const std::string& station, const std::string& device, const std::vector<std::uint16_t>& values) {
    nlohmann::json body{{"values", values}};
    REQUIRE(http_put(api, devices(station, device) + "?as=words", body.dump()).status == 200);
}

// The control block at file 0 0o5400 = D384-D391: FLAGS|TIMER, G/TYPE|ST1, -, n, ADR_A, SEG_A, ADR_B, SEG_B.
void start(std::uint16_t api, const std::string& station, std::uint8_t timer, std::uint8_t type, std::uint8_t st,
           std::uint16_t n, std::uint16_t own, std::uint16_t theirs, std::uint16_t seg_b = 0) {
    put_words(api, station, "D384",
              {static_cast<std::uint16_t>(timer << 8), static_cast<std::uint16_t>((0x80 | type) | st << 8), 0, n, own, 0, theirs, seg_b});
}

std::uint8_t flags_of(std::uint16_t api, const std::string& station) { return words(api, station, "D384", 1)[0] & 0xFF; }

// Waits for FLAGS to leave 00/90 (the transfer runs on the unit's time, not the test's).
std::uint8_t end_flags(std::uint16_t api, const std::string& station) {
    auto deadline = std::chrono::steady_clock::now() + std::chrono::seconds(10);
    std::uint8_t flags = 0;
    while (std::chrono::steady_clock::now() < deadline) {
        flags = flags_of(api, station);
        if (flags != 0x00 && flags != 0x90) return flags;
        std::this_thread::sleep_for(std::chrono::milliseconds(10));
    }
    return flags;
}

std::uint8_t status_flags(std::uint16_t api, const std::string& station) { return words(api, station, "D255", 1)[0] & 0xFF; }

}  // namespace

TEST_CASE("JW-51CM SEND/RECEIVE between two stations of a plant over TCP and UDP", "[jw51cm][jw51cm-send-receive]") {
    const auto b_tcp = free_port(), b_udp = free_port(true), absent_tcp = free_port(), absent_udp = free_port(true);
    // a: TCP_Active on connection 1; u: UDP on connection 0; b: the partner (stations 13 and 15, octal).
    const std::string config = R"({"bind": "127.0.0.1", "http": {"port": 0}, "stations": [
        {"name": "a", "kind": "sharp-jw", "jw51cm": {"tcp_port": 0, "udp_port": 0, "parameters": {
            "0104": "80 00 08 60", "0400": "02",
            "0410": ")" + entry("0B", b_tcp) + R"(", "0420": ")" + entry("0C", absent_tcp) + R"(",
            "3764": "FE 09 00 80", "3770": "00 0B 00 80"}}},
        {"name": "u", "kind": "sharp-jw", "jw51cm": {"tcp_port": 0, "udp_port": 0, "parameters": {
            "0100": "01 00 08 60", "0400": "02",
            "0410": ")" + entry("0D", b_udp) + R"(", "0420": ")" + entry("0E", absent_udp) + R"(",
            "3764": "FE 09 00 80", "3770": "00 0B 00 80"}}},
        {"name": "b", "kind": "sharp-jw", "jw51cm": {"tcp_port": )" + std::to_string(b_tcp) +
                               R"(, "udp_port": )" + std::to_string(b_udp) + R"(}}]})";
    SimProcess sim(plant_options(config));
    const auto api = sim.http_port();
    // b accepts writes as from any host: write-permission mode 1.
    auto host = TcpClient::open(b_tcp);
    REQUIRE(ask(host, {0xF9, 0x01}, 45) == response({0xF9, 0x00, 0x01}));
    host.close();

    CHECK(status_flags(api, "a") == 0x80);   // its UDP port (7); the TCP_Active connection 1 is not open
    CHECK(status_flags(api, "u") == 0x81);   // the UDP channel (0) is on from power-on

    SECTION("TCP: open, SEND, RECEIVE, an error response, close") {
        start(api, "a", 0, 0x00, 013, 0, 0, 0xFFFF);
        CHECK(end_flags(api, "a") == 0x40);
        CHECK(status_flags(api, "a") == 0x82);
        CHECK(words(api, "a", "D384", 2)[1] == 0x0B00);   // the start bit was taken
        // SEND 4 bytes from a's register 09000 (file 0 0x0800, D0) to b's 09100 (0x0840, D32).
        put_words(api, "a", "D0", {0x2211, 0x4433});
        start(api, "a", 0, 0x00, 013, 4, 0x0800, 0x0840);
        CHECK(end_flags(api, "a") == 0x40);
        CHECK(words(api, "b", "D32", 2) == std::vector<std::uint16_t>{0x2211, 0x4433});
        // RECEIVE 6 bytes from b's 0x0850 (D40) into a's 0x0810 (D8).
        put_words(api, "b", "D40", {0xBBAA, 0xDDCC, 0xFFEE});
        start(api, "a", 0, 0x02, 013, 6, 0x0810, 0x0850);
        CHECK(end_flags(api, "a") == 0x40);
        CHECK(words(api, "a", "D8", 3) == std::vector<std::uint16_t>{0xBBAA, 0xDDCC, 0xFFEE});
        // A RECEIVE past b's file 0 (8 KB): b answers 01, FLAGS E0, a's memory untouched.
        start(api, "a", 0, 0x02, 013, 4, 0x0810, 0x1FFE);
        CHECK(end_flags(api, "a") == 0xE0);
        CHECK(words(api, "a", "D8", 1)[0] == 0xBBAA);
        // A station without a table entry: E0 without sending.
        start(api, "a", 0, 0x00, 017, 4, 0x0800, 0x0840);
        CHECK(end_flags(api, "a") == 0xE0);
        // b drops the connection (its HTTP API, as a power cut or a reset would): a's bit goes, a SEND is E0, an open opens again.
        auto connections = http_get(api, "/api/stations/b/connections").json()["connections"];
        REQUIRE(connections.size() == 1);
        const auto id = connections[0]["id"].get<std::uint64_t>();
        REQUIRE(http(api, "DELETE", "/api/stations/b/connections/" + std::to_string(id)).status == 200);
        auto deadline = std::chrono::steady_clock::now() + std::chrono::seconds(10);
        while (status_flags(api, "a") != 0x80 && std::chrono::steady_clock::now() < deadline)
            std::this_thread::sleep_for(std::chrono::milliseconds(10));
        CHECK(status_flags(api, "a") == 0x80);
        start(api, "a", 0, 0x00, 013, 4, 0x0800, 0x0840);
        CHECK(end_flags(api, "a") == 0xE0);
        start(api, "a", 0, 0x00, 013, 0, 0, 0xFFFF);
        CHECK(end_flags(api, "a") == 0x40);
        CHECK(status_flags(api, "a") == 0x82);
        start(api, "a", 0, 0x00, 013, 0, 0, 0xFFFE);
        CHECK(end_flags(api, "a") == 0x40);
        CHECK(status_flags(api, "a") == 0x80);
        // Closed: a SEND is an error.
        start(api, "a", 0, 0x00, 013, 4, 0x0800, 0x0840);
        CHECK(end_flags(api, "a") == 0xE0);
    }

    SECTION("UDP: SEND and RECEIVE without open") {
        put_words(api, "u", "D0", {0x0201, 0x0403, 0x0605});
        start(api, "u", 0, 0x00, 015, 5, 0x0800, 0x0860);
        CHECK(end_flags(api, "u") == 0x40);
        CHECK(words(api, "b", "D48", 3) == std::vector<std::uint16_t>{0x0201, 0x0403, 0x0005});
        put_words(api, "b", "D64", {0x1110, 0x1312});
        start(api, "u", 0, 0x02, 015, 4, 0x0820, 0x0880);
        CHECK(end_flags(api, "u") == 0x40);
        CHECK(words(api, "u", "D16", 2) == std::vector<std::uint16_t>{0x1110, 0x1312});
        start(api, "u", 0, 0x00, 015, 0, 0, 0xFFFF);   // nothing to open over UDP
        CHECK(end_flags(api, "u") == 0x40);
        CHECK(status_flags(api, "u") == 0x81);
    }

    SECTION("a partner that is not there: FLAGS 60 when the timer runs out on the station's clock") {
        REQUIRE(http(api, "PUT", "/api/stations/a/clock", R"({"mode": "frozen"})").status == 200);
        REQUIRE(http(api, "PUT", "/api/stations/u/clock", R"({"mode": "frozen"})").status == 200);
        // TCP open to station 14, default timer 2 minutes.
        start(api, "a", 0, 0x00, 014, 0, 0, 0xFFFF);
        REQUIRE(http(api, "POST", "/api/stations/a/clock/step", R"({"scans": 1})").status == 200);
        CHECK(flags_of(api, "a") == 0x90);
        REQUIRE(http(api, "POST", "/api/stations/a/clock/step", R"({"ms": 119000})").status == 200);
        std::this_thread::sleep_for(std::chrono::milliseconds(100));   // nothing may end it before its time
        CHECK(flags_of(api, "a") == 0x90);
        REQUIRE(http(api, "POST", "/api/stations/a/clock/step", R"({"ms": 1000})").status == 200);
        CHECK(end_flags(api, "a") == 0x60);
        CHECK(status_flags(api, "a") == 0x80);
        // UDP SEND to station 16, TIMER 5 (500 ms).
        start(api, "u", 5, 0x00, 016, 2, 0x0800, 0x0840);
        REQUIRE(http(api, "POST", "/api/stations/u/clock/step", R"({"scans": 1})").status == 200);
        CHECK(flags_of(api, "u") == 0x90);
        REQUIRE(http(api, "POST", "/api/stations/u/clock/step", R"({"ms": 400})").status == 200);
        std::this_thread::sleep_for(std::chrono::milliseconds(100));
        CHECK(flags_of(api, "u") == 0x90);
        REQUIRE(http(api, "POST", "/api/stations/u/clock/step", R"({"ms": 100})").status == 200);
        CHECK(end_flags(api, "u") == 0x60);
    }
}

TEST_CASE("JW-51CM SEND/RECEIVE parameters: a bad one is refused at start, naming it and the fix", "[jw51cm][jw51cm-send-receive]") {
    TempDir dir;
    auto refused = [&](const std::string& parameters, const std::string& named) {
        auto file = dir.write("bad.json", R"({"kind": "sharp-jw", "jw51cm": {"parameters": )" + parameters + "}}");
        auto r = run_sim({"--check-config", file.string()});
        CHECK(r.exit_code == 2);
        CHECK(r.err.find(named) != std::string::npos);
        return r.err;
    };
    CHECK(refused(R"({"0100": "00 00 B8 0B"})", "parameter 0100").find("tcp_port") != std::string::npos);
    CHECK(refused(R"({"0400": "01"})", "parameter 0400").find("use 02") != std::string::npos);
    CHECK(refused(R"({"3770": "00 0B 00 80"})", "parameter 3773").find("6008") != std::string::npos);
    refused(R"({"0104": "80 00 08 60", "3770": "00 0B 00 80"})", "set 0400 to 02");
    refused(R"({"0410": "01 0B 00 00 7F 00 00 01"})", "not 1-65534");
    refused(R"({"0410": "01 0B 88 13 7F 00 00 01", "0420": "01 0B 89 13 7F 00 00 01"})", "has an entry already");
    refused(R"({"0134": "01 00 08 60"})", "connection 7 is the unit's UDP port");
    refused(R"({"0104": "80 00 08 60", "0400": "02", "3770": "F8 1F 00 80"})", "control block");
    refused(R"({"0020": "00 01"})", "/jw51cm/parameters/0020");
    auto good = dir.write("good.json", R"({"kind": "sharp-jw", "jw51cm": {"parameters": {"0104": "80 00 08 60", "0400": "02",
        "0410": "01 0B 88 13 7F 00 00 01", "3770": "00 0B 00 80"}}})");
    CHECK(run_sim({"--check-config", good.string()}).exit_code == 0);
}
