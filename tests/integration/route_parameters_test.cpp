// Routes beyond the derived ones (docs/plants.md): routing parameters given
// by hand, the monitoring timer counted over the whole way (on the frozen
// clock, stepped through the HTTP API), the station-number-extended frame's
// station 7C through a route, and node search by broadcast on loopback
// (docs/nodes.md). Byte-exact over real sockets.
#include <catch2/catch.hpp>

#include <netinet/in.h>
#include <sys/socket.h>

#include <set>

#include "ask.hpp"
#include "cli_support.hpp"
#include "frames.hpp"
#include "http_client.hpp"
#include "plant_ports.hpp"
#include "sim_process.hpp"
#include "sockets.hpp"

using namespace slmp::test;

namespace {

// 0401 D100 ×1 to network 2 station 3, 3E binary and 3E ASCII.
const char* kReadBinary = "50 00 02 03 FF 03 00 0C 00 01 00 01 04 00 00 64 00 00 A8 01 00";
const std::string kReadAscii = "500002" "03" "03FF00" "0018" "0001" "0401" "0000" "D*000100" "0001";

// gw reaches network 2 by the derived way (relay-a, the first relay station of
// network 1); gw-routed by its routing parameter through relay-b, whose faults
// refuse everything it passes on with CF70; network 3 is an island; network 4
// has a loop of routing parameters between gw-routed and relay-a.
std::string routed_plant(const std::string& relay_b_faults) {
    return R"({"bind": "127.0.0.1", "http": {"enabled": false}, "stations": [
        {"name": "gw", "profile": "RJ71EN71", "tcp_port": 0, "udp_port": 0, "networks": [{"number": 1, "station": 1}]},
        {"name": "gw-routed", "profile": "RJ71EN71", "tcp_port": 0, "udp_port": 0, "networks": [{"number": 1, "station": 5}],
         "routes": [{"network": 2, "via_network": 1, "via_station": 3},
                    {"network": 3, "via_network": 1, "via_station": 2},
                    {"network": 4, "via_network": 1, "via_station": 2}]},
        {"name": "relay-a", "profile": "R08CPU", "tcp_port": 0, "networks": [{"number": 1, "station": 2}, {"number": 2, "station": 1}],
         "routes": [{"network": 4, "via_network": 1, "via_station": 5}]},
        {"name": "relay-b", "profile": "R08CPU", "tcp_port": 0, "networks": [{"number": 1, "station": 3}, {"number": 2, "station": 2}],
         "scenarios": [")" + relay_b_faults + R"("]},
        {"name": "packer", "profile": "R08CPU", "tcp_port": 0, "networks": [{"number": 2, "station": 3}], "devices": {"D100": 4660}},
        {"name": "island", "profile": "R08CPU", "tcp_port": 0, "networks": [{"number": 3, "station": 1}]},
        {"name": "island-4", "profile": "R08CPU", "tcp_port": 0, "networks": [{"number": 4, "station": 1}]}]})";
}

Bytes ascii(const std::string& text) { return Bytes(text.begin(), text.end()); }

}  // namespace

TEST_CASE("routing parameters: a station's route by hand is taken instead of the derived one, TCP and UDP, binary and ASCII",
          "[route][plant]") {
    TempDir dir;
    const auto faults = dir.write("relay-b.json", R"({"stations": "relay-b", "faults": [{"do": "end_code", "end_code": "CF70"}]})");
    SimProcess sim(plant_options(routed_plant(faults.string())));
    for (const bool udp : {false, true}) {
        INFO((udp ? "UDP" : "TCP"));
        auto via = [&](const std::string& station, const Bytes& request) {
            if (!udp) {
                auto c = TcpClient::open(tcp_of(sim, station));
                return ask(c, request);
            }
            UdpClient u;
            return ask(u, udp_of(sim, station), request);
        };
        // The derived way: through relay-a, packer's D100 (4660 = 1234H).
        CHECK(show(via("gw", hex(kReadBinary))) == show(hex("D0 00 02 03 FF 03 00 04 00 00 00 34 12")));
        CHECK(show(via("gw", ascii(kReadAscii))) == show(ascii("D00002" "03" "03FF00" "0008" "0000" "1234")));
        // gw-routed's routing parameter sends it through relay-b, which refuses it.
        CHECK(show(via("gw-routed", hex(kReadBinary))) ==
              show(hex("D0 00 02 03 FF 03 00 0B 00 70 CF 02 03 FF 03 00 01 04 00 00")));
        CHECK(show(via("gw-routed", ascii(kReadAscii))) ==
              show(ascii("D00002" "03" "03FF00" "0016" "CF70" "02" "03" "03FF00" "0401" "0000")));
        // Network 3: the routing parameter names relay-a, which has no way on: 4A01.
        CHECK(show(via("gw-routed", hex("50 00 03 01 FF 03 00 0C 00 01 00 01 04 00 00 64 00 00 A8 01 00"))) ==
              show(hex("D0 00 03 01 FF 03 00 0B 00 01 4A 03 01 FF 03 00 01 04 00 00")));
        // Network 4: gw-routed and relay-a send it to each other: past 7 relay stations, 4A03.
        CHECK(show(via("gw-routed", hex("50 00 04 01 FF 03 00 0C 00 01 00 01 04 00 00 64 00 00 A8 01 00"))) ==
              show(hex("D0 00 04 01 FF 03 00 0B 00 03 4A 04 01 FF 03 00 01 04 00 00")));
        // gw's derived way to network 3: none (4A01); to network 4 none either.
        CHECK(show(via("gw", hex("50 00 03 01 FF 03 00 0C 00 01 00 01 04 00 00 64 00 00 A8 01 00"))) ==
              show(hex("D0 00 03 01 FF 03 00 0B 00 01 4A 03 01 FF 03 00 01 04 00 00")));
    }
}

TEST_CASE("routing parameters: bad ones are refused at start with a message that says what to fix", "[route][plant][config]") {
    auto refused = [](const std::string& stations) {
        TempDir dir;
        const auto file = dir.write("plant.json", R"({"bind": "127.0.0.1", "http": {"enabled": false}, "stations": [)" + stations + "]}");
        auto r = run_sim({"--check-config", file.string()});
        CHECK(r.exit_code != 0);
        return r.out + r.err;
    };
    const std::string relay = R"({"name": "relay", "profile": "R08CPU", "tcp_port": 0, "networks": [{"number": 1, "station": 2}, {"number": 2, "station": 1}]})";
    CHECK_THAT(refused(R"({"name": "gw", "profile": "RJ71EN71", "tcp_port": 0, "networks": [{"number": 1, "station": 1}],
                           "routes": [{"network": 2, "via_network": 1, "via_station": 9}]}, )" + relay),
               Catch::Contains("station 'gw': /routes/0/via_station: network 1 has no station No. 9"));
    CHECK_THAT(refused(R"({"name": "gw", "profile": "RJ71EN71", "tcp_port": 0, "networks": [{"number": 1, "station": 1}],
                           "routes": [{"network": 2, "via_network": 7, "via_station": 2}]}, )" + relay),
               Catch::Contains("/routes/0/via_network: this station has no module with a station No. on network 7"));
    CHECK_THAT(refused(R"({"name": "gw", "profile": "RJ71EN71", "tcp_port": 0, "networks": [{"number": 1, "station": 1}],
                           "routes": [{"network": 1, "via_network": 1, "via_station": 2}]}, )" + relay),
               Catch::Contains("/routes/0/network: this station is on network 1 itself"));
    CHECK_THAT(refused(R"({"name": "gw", "profile": "RJ71EN71", "tcp_port": 0, "networks": [{"number": 1, "station": 1}],
                           "routes": [{"network": 2, "via_network": 1, "via_station": 2},
                                      {"network": 2, "via_network": 1, "via_station": 2}]}, )" + relay),
               Catch::Contains("/routes/1/network: network 2 has a routing parameter already"));
    CHECK_THAT(refused(R"({"name": "gw", "profile": "RJ71EN71", "tcp_port": 0, "networks": [{"number": 1, "station": 1}],
                           "routes": [{"network": 2, "via_network": 1, "via_station": 1}]}, )" + relay),
               Catch::Contains("station No. 1 of network 1 is this station"));
    CHECK_THAT(refused(R"({"name": "gw", "profile": "RJ71EN71", "tcp_port": 0, "networks": [{"number": 1, "station": 1}],
                           "routes": [{"network": 240, "via_network": 1, "via_station": 2}]}, )" + relay),
               Catch::Contains("/routes/0/network: value 240 is larger than 239"));
}

namespace {

HttpResponse post(std::uint16_t port, const std::string& target, const std::string& body) {
    return http(port, "POST", target, body);
}

// Waits (bounded) until `n` waits are parked on the station's clock.
void await_waiting(std::uint16_t http_port, const std::string& station, std::size_t n) {
    const auto deadline = std::chrono::steady_clock::now() + std::chrono::seconds(10);
    for (;;) {
        auto timing = http_get(http_port, "/api/stations/" + station + "/info").json()["timing"];
        if (timing["waiting"] == n) return;
        if (std::chrono::steady_clock::now() > deadline) FAIL(station << ": waiting on the clock: " << timing.dump() << ", expected " << n);
    }
}

void step(std::uint16_t http_port, const std::string& station, const std::string& body) {
    REQUIRE(post(http_port, "/api/stations/" + station + "/clock/step", body).status == 200);
}

}  // namespace

TEST_CASE("the monitoring timer counts the whole way: a relay station that delays past it gets CF71 from the module",
          "[route][plant][timing]") {
    // relay holds every request it passes on 1000 ms (its clock); the request's
    // timer is 1 × 250 ms on gw's clock. gw answers CF71 when its clock passes
    // 250 ms; the request goes on when relay's clock passes 1000 ms and packer
    // executes it, its answer dropped (the module gave up on it).
    TempDir dir;
    const auto delay = dir.write("relay.json", R"({"stations": "relay", "faults": [{"do": "delay", "delay_ms": 1000}]})");
    SimProcess sim(plant_options(R"({"bind": "127.0.0.1", "http": {"enabled": true, "port": 0}, "stations": [
        {"name": "gw", "profile": "RJ71EN71", "tcp_port": 0, "udp_port": 0, "networks": [{"number": 1, "station": 1}]},
        {"name": "relay", "profile": "R08CPU", "tcp_port": 0, "networks": [{"number": 1, "station": 4}, {"number": 2, "station": 1}],
         "scenarios": [")" + delay.string() + R"("]},
        {"name": "packer", "profile": "R08CPU", "tcp_port": 0, "networks": [{"number": 2, "station": 3}]}]})",
                                 {"--clock", "frozen"}));
    const auto api = sim.http_port();
    auto packer = TcpClient::open(tcp_of(sim, "packer"));
    const auto read_packer = hex("50 00 00 FF FF 03 00 0C 00 01 00 01 04 00 00 64 00 00 A8 01 00");
    for (const bool udp : {false, true}) {
        INFO((udp ? "UDP" : "TCP"));
        const std::uint16_t value = udp ? 0x5678 : 0x1234;
        // 1401 D100 := value, timer 0001, to network 2 station 3.
        const auto write = hex("50 00 02 03 FF 03 00 0E 00 01 00 01 14 00 00 64 00 00 A8 01 00 " + hex_digits(value & 0xFF, 2) +
                               " " + hex_digits(value >> 8, 2));
        const auto cf71 = show(hex("D0 00 02 03 FF 03 00 0B 00 71 CF 02 03 FF 03 00 01 14 00 00"));
        auto gw = TcpClient::open(tcp_of(sim, "gw"));
        UdpClient gw_udp;
        REQUIRE((udp ? gw_udp.send_to(udp_of(sim, "gw"), write) : gw.send(write)));
        await_waiting(api, "gw", 1);      // the monitoring timer
        await_waiting(api, "relay", 1);   // the delay
        step(api, "gw", R"({"ms": 249})");
        await_waiting(api, "gw", 1);
        if (udp) CHECK_FALSE(gw_udp.receive(std::chrono::milliseconds(0)));
        else CHECK(gw.recv_some(std::chrono::milliseconds(0)).status == RecvStatus::Timeout);
        step(api, "gw", R"({"ms": 1})");
        if (udp) {
            auto answer = gw_udp.receive();
            REQUIRE(answer);
            CHECK(show(*answer) == cf71);
        } else {
            Bytes frame;
            REQUIRE(gw.response(&frame));
            CHECK(show(frame) == cf71);
        }
        await_waiting(api, "gw", 0);   // the timer is done
        // Not yet at packer; once relay's delay is over it is executed there.
        step(api, "relay", R"({"ms": 1000})");
        await_waiting(api, "relay", 0);
        const auto deadline = std::chrono::steady_clock::now() + std::chrono::seconds(5);
        std::string seen;
        const auto want = show(hex("D0 00 00 FF FF 03 00 04 00 00 00 " + hex_digits(value & 0xFF, 2) + " " + hex_digits(value >> 8, 2)));
        while ((seen = show(ask(packer, read_packer))) != want && std::chrono::steady_clock::now() < deadline) {
        }
        CHECK(seen == want);
        // The dropped late answer never reaches the client.
        if (udp) CHECK_FALSE(gw_udp.receive(std::chrono::milliseconds(0)));
        else CHECK(gw.recv_some(std::chrono::milliseconds(0)).status == RecvStatus::Timeout);
    }
}

TEST_CASE("station 7C of the station-number-extended frame through a route: the extended station No. names the station",
          "[route][plant][extended]") {
    // CC-Link IE TSN network 1: tsn-gw (1), tsn-node (300, the master), cpu (200,
    // an R08CPU whose port does not take the frame).
    SimProcess sim(plant_options(R"({"bind": "127.0.0.1", "http": {"enabled": false}, "stations": [
        {"name": "tsn-gw", "profile": "RJ71GN11-T2", "tcp_port": 0, "udp_port": 0, "networks": [{"number": 1, "station": 1}]},
        {"name": "tsn-node", "profile": "RJ71GN11-T2", "tcp_port": 0, "networks": [{"number": 1, "station": 300, "master": true}],
         "devices": {"D100": 8738}},
        {"name": "cpu", "profile": "R08CPU", "tcp_port": 0, "networks": [{"number": 1, "station": 200}]}]})"));
    for (const bool udp : {false, true}) {
        INFO((udp ? "UDP" : "TCP"));
        auto gw = TcpClient::open(tcp_of(sim, "tsn-gw"));
        UdpClient gw_udp;
        auto via = [&](const std::string& request) {
            return show(udp ? ask(gw_udp, udp_of(sim, "tsn-gw"), hex(request)) : ask(gw, hex(request)));
        };
        // Extended station No. 012C (300): tsn-node's D100 (8738 = 2222H), the extended No. echoed.
        CHECK(via("68 00 01 00 00 00 01 7C FF 03 00 00 2C 01 12 00 10 00 01 04 00 00 00 00 00 00 00 00 64 00 00 A8 01 00") ==
              show(hex("E8 00 01 00 00 00 01 7C FF 03 00 00 2C 01 0E 00 00 00 01 04 00 00 00 00 00 00 00 00 22 22")));
        // 0000: the network's designated master, tsn-node.
        CHECK(via("68 00 02 00 00 00 01 7C FF 03 00 00 00 00 12 00 10 00 01 04 00 00 00 00 00 00 00 00 64 00 00 A8 01 00") ==
              show(hex("E8 00 02 00 00 00 01 7C FF 03 00 00 00 00 0E 00 00 00 01 04 00 00 00 00 00 00 00 00 22 22")));
        // A write through the route lands at tsn-node.
        CHECK(via("68 00 03 00 00 00 01 7C FF 03 00 00 2C 01 14 00 10 00 01 14 00 00 00 00 00 00 00 00 64 00 00 A8 01 00 99 00") ==
              show(hex("E8 00 03 00 00 00 01 7C FF 03 00 00 2C 01 0C 00 00 00 01 14 00 00 00 00 00 00 00 00")));
        CHECK(via("68 00 04 00 00 00 01 7C FF 03 00 00 2C 01 12 00 10 00 01 04 00 00 00 00 00 00 00 00 64 00 00 A8 01 00") ==
              show(hex("E8 00 04 00 00 00 01 7C FF 03 00 00 2C 01 0E 00 00 00 01 04 00 00 00 00 00 00 00 00 99 00")));
        CHECK(via("68 00 01 00 00 00 01 7C FF 03 00 00 2C 01 14 00 10 00 01 14 00 00 00 00 00 00 00 00 64 00 00 A8 01 00 22 22") ==
              show(hex("E8 00 01 00 00 00 01 7C FF 03 00 00 2C 01 0C 00 00 00 01 14 00 00 00 00 00 00 00 00")));
        // 00C8 (200): an R08CPU's port takes no extended frame (§2.3): 4A02 from tsn-gw.
        CHECK(via("68 00 05 00 00 00 01 7C FF 03 00 00 C8 00 12 00 10 00 01 04 00 00 00 00 00 00 00 00 64 00 00 A8 01 00") ==
              show(hex("E8 00 05 00 00 00 01 7C FF 03 00 00 C8 00 14 00 02 4A 01 04 00 00 00 00 00 00 00 00 "
                       "01 7C FF 03 00 00 C8 00")));
        // 0005: station Nos. 1-120 go in the station No. field, not the extended one: 4A02.
        CHECK(via("68 00 06 00 00 00 01 7C FF 03 00 00 05 00 12 00 10 00 01 04 00 00 00 00 00 00 00 00 64 00 00 A8 01 00") ==
              show(hex("E8 00 06 00 00 00 01 7C FF 03 00 00 05 00 14 00 02 4A 01 04 00 00 00 00 00 00 00 00 "
                       "01 7C FF 03 00 00 05 00")));
        // 0190 (400): no such station on network 1: 4A02.
        CHECK(via("68 00 07 00 00 00 01 7C FF 03 00 00 90 01 12 00 10 00 01 04 00 00 00 00 00 00 00 00 64 00 00 A8 01 00") ==
              show(hex("E8 00 07 00 00 00 01 7C FF 03 00 00 90 01 14 00 02 4A 01 04 00 00 00 00 00 00 00 00 "
                       "01 7C FF 03 00 00 90 01")));
    }
}

namespace {

// A UDP port free on the loopback broadcast address now (the stations bind it next).
std::uint16_t free_search_port() {
    Socket s(::socket(AF_INET, SOCK_DGRAM | SOCK_CLOEXEC, 0));
    sockaddr_in addr{};
    addr.sin_family = AF_INET;
    addr.sin_addr.s_addr = htonl(0x7FFFFFFF);   // 127.255.255.255
    addr.sin_port = 0;
    REQUIRE(::bind(s.fd(), reinterpret_cast<sockaddr*>(&addr), sizeof addr) == 0);
    socklen_t len = sizeof addr;
    ::getsockname(s.fd(), reinterpret_cast<sockaddr*>(&addr), &len);
    return ntohs(addr.sin_port);
}

std::string node_plant(const TempDir& dir, std::uint16_t search_port, unsigned max_delay_ms, bool http) {
    auto profile = dir.write("node-profile.json", R"({"name": "R08CPU-NODE", "extends": "R08CPU", "node_commands": true,
        "description": "an SLMP-compatible device"})");
    const auto search = R"({"port": )" + std::to_string(search_port) + R"(, "max_delay_ms": )" + std::to_string(max_delay_ms) + "}";
    return R"({"bind": "127.0.0.1", "http": {"enabled": )" + std::string(http ? "true, \"port\": 0" : "false") +
           R"(}, "stations": [
        {"template": {"profile": ")" + profile.string() + R"(", "node_search": )" + search +
           R"(}, "count": 3, "name": "cam-{i}", "tcp_port": 0, "udp_port": 0},
        {"name": "press", "profile": "R08CPU", "tcp_port": 0, "udp_port": 0, "node_search": )" + search + "}]}";
}

// 0E30, 3E binary, client MAC and IP zeros (as slmp nodes sends it).
const char* kNodeSearch = "50 00 00 FF FF 03 00 11 00 10 00 30 0E 00 00 00 00 00 00 00 00 04 00 00 00 00";

}  // namespace

TEST_CASE("node search by broadcast: every node station of a plant answers after its random delay on its clock",
          "[node][plant][udp]") {
    TempDir dir;
    const auto port = free_search_port();
    SimProcess sim(plant_options(node_plant(dir, port, 1500, true), {"--clock", "frozen"}));
    const auto api = sim.http_port();
    UdpClient client;
    const int on = 1;
    REQUIRE(::setsockopt(client.fd(), SOL_SOCKET, SO_BROADCAST, &on, sizeof on) == 0);
    const std::string ascii_search = "500000FF03FF000022" "0010" "0E30" "0000" "000000000000" "04" "00000000";
    for (const auto& request : {hex(kNodeSearch), Bytes(ascii_search.begin(), ascii_search.end())}) {
        INFO(show(request));
        REQUIRE(client.send_to(port, request, "127.255.255.255"));
        // Each node waits its delay on its own clock (press, no node, ignores it).
        for (const auto* name : {"cam-1", "cam-2", "cam-3"}) await_waiting(api, name, 1);
        CHECK_FALSE(client.receive(std::chrono::milliseconds(0)));
        for (const auto* name : {"cam-1", "cam-2", "cam-3"}) step(api, name, R"({"ms": 1500})");
        std::set<std::string> broadcast;
        for (int i = 0; i < 3; ++i) {
            std::uint16_t from = 0;
            auto answer = client.receive(kReplyTimeout, &from);
            REQUIRE(answer);
            CHECK(from == port);
            broadcast.insert(show(*answer));
        }
        CHECK_FALSE(client.receive(std::chrono::milliseconds(200)));   // press is no node: no fourth answer
        // Each answer is byte for byte the one the station gives on its own UDP port.
        std::set<std::string> directed;
        for (const auto* name : {"cam-1", "cam-2", "cam-3"}) {
            UdpClient own;
            directed.insert(show(ask(own, udp_of(sim, name), request)));
        }
        CHECK(broadcast == directed);
    }
}

TEST_CASE("slmp nodes --broadcast finds every node station of a plant", "[cli][node][plant]") {
    TempDir dir;
    const auto port = free_search_port();
    SimProcess sim(plant_options(node_plant(dir, port, 100, false)));
    auto r = run_cli({"--host", "127.255.255.255", "--port", std::to_string(port), "--udp", "--timeout", "2s", "--json",
                      "nodes", "--broadcast"});
    INFO(r.err);
    REQUIRE(r.exit_code == 0);
    auto list = json_of(r);
    REQUIRE(list.size() == 3);
    for (std::size_t i = 0; i < 3; ++i) {
        const auto name = "cam-" + std::to_string(i + 1);
        CHECK(list[i]["station"] == name);
        CHECK(list[i]["ip"] == "127.0.0.1");
        CHECK(list[i]["port"] == udp_of(sim, name));
    }
    auto table = run_cli({"--host", "127.255.255.255", "--port", std::to_string(port), "--udp", "--timeout", "2s", "nodes",
                          "--broadcast"});
    REQUIRE(table.exit_code == 0);
    CHECK(lines_of(table.out).size() == 4);   // the header and three nodes
}

TEST_CASE("model timing: the module's Ke, each relay's Ke and the target's time all count against the monitoring timer",
          "[route][plant][timing]") {
    // Every station: model timing, Ke 100 ms, nothing else. The request's timer
    // is 250 ms. gw holds it 100 ms (its Ke), then 150 ms remain on gw's clock;
    // relay passes it on after its Ke, packer answers after its Ke: 300 ms in
    // all, so gw answers CF71 at 250 ms unless packer's clock is stepped first.
    const std::string timing = R"("timing": {"mode": "model", "ke_ms": 100, "kdt_ms": 0, "scan_wait": false})";
    SimProcess sim(plant_options(R"({"bind": "127.0.0.1", "http": {"enabled": true, "port": 0}, "stations": [
        {"name": "gw", "profile": "RJ71EN71", "tcp_port": 0, "networks": [{"number": 1, "station": 1}], )" + timing + R"(},
        {"name": "relay", "profile": "R08CPU", "tcp_port": 0, "networks": [{"number": 1, "station": 4}, {"number": 2, "station": 1}], )" +
                                     timing + R"(},
        {"name": "packer", "profile": "R08CPU", "tcp_port": 0, "networks": [{"number": 2, "station": 3}], "devices": {"D100": 4660}, )" +
                                     timing + "}]}",
                                 {"--clock", "frozen"}));
    const auto api = sim.http_port();
    auto gw = TcpClient::open(tcp_of(sim, "gw"));
    const auto read = hex("50 00 02 03 FF 03 00 0C 00 01 00 01 04 00 00 64 00 00 A8 01 00");
    auto quiet = [&] { return gw.recv_some(std::chrono::milliseconds(0)).status == RecvStatus::Timeout; };
    auto answer = [&] {
        Bytes frame;
        REQUIRE(gw.response(&frame));
        return show(frame);
    };
    // In time: 100 + 100 + 100 ms, packer stepped before gw's timer runs out.
    REQUIRE(gw.send(read));
    await_waiting(api, "gw", 1);   // held for its Ke
    step(api, "gw", R"({"ms": 100})");
    await_waiting(api, "relay", 1);
    step(api, "relay", R"({"ms": 100})");
    await_waiting(api, "packer", 1);
    step(api, "packer", R"({"ms": 100})");
    CHECK(answer() == show(hex("D0 00 02 03 FF 03 00 04 00 00 00 34 12")));
    await_waiting(api, "gw", 0);   // its timer gave up waiting once the answer was in
    // Too late: gw's clock reaches 250 ms (its 100 ms Ke + 150) while packer still holds it.
    REQUIRE(gw.send(read));
    await_waiting(api, "gw", 1);
    step(api, "gw", R"({"ms": 100})");
    await_waiting(api, "relay", 1);
    step(api, "relay", R"({"ms": 100})");
    await_waiting(api, "packer", 1);
    step(api, "gw", R"({"ms": 149})");
    await_waiting(api, "gw", 1);
    CHECK(quiet());
    step(api, "gw", R"({"ms": 1})");
    CHECK(answer() == show(hex("D0 00 02 03 FF 03 00 0B 00 71 CF 02 03 FF 03 00 01 04 00 00")));
    step(api, "packer", R"({"ms": 100})");   // served then; its answer is dropped
    await_waiting(api, "packer", 0);
    CHECK(quiet());
}
