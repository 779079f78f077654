// A plant's networks over HTTP (docs/api.md, "Plants"): GET /api/networks says
// which station is which station No. on which network and who relays between
// networks; GET /api/stations gives each station's network modules; a routed
// request's event names its route.
#include <catch2/catch.hpp>

#include "ask.hpp"
#include "frames.hpp"
#include "http_client.hpp"
#include "plant_ports.hpp"
#include "protocol/client_commands.hpp"
#include "sim_process.hpp"
#include "sockets.hpp"

using namespace slmp::test;
using nlohmann::json;
namespace client = slmp::protocol::client;

TEST_CASE("GET /api/networks and /api/stations show the plant's networks and who relays to whom", "[route][plant][http]") {
    SimProcess sim(plant_options(R"({"bind": "127.0.0.1", "http": {"port": 0}, "stations": [
        {"name": "gw", "profile": "RJ71EN71", "tcp_port": 0, "networks": [{"number": 1, "station": 1}]},
        {"name": "press", "profile": "R08CPU", "tcp_port": 0, "networks": [{"number": 1, "station": 2}]},
        {"name": "relay", "profile": "R08CPU", "tcp_port": 0,
         "networks": [{"number": 1, "station": 4, "master": true}, {"number": 2, "station": 1}]},
        {"name": "packer", "profile": "R04CPU", "tcp_port": 0, "networks": [{"number": 2, "station": 3}]},
        {"name": "island", "profile": "R04CPU", "tcp_port": 0}]})"));

    auto networks = http_get(sim.http_port(), "/api/networks").json();
    CHECK(networks == json::parse(R"([
        {"number": 1,
         "stations": [{"name": "gw", "station": 1, "master": false}, {"name": "press", "station": 2, "master": false},
                      {"name": "relay", "station": 4, "master": true}],
         "relays": [{"name": "relay", "to_networks": [2]}]},
        {"number": 2,
         "stations": [{"name": "relay", "station": 1, "master": false}, {"name": "packer", "station": 3, "master": false}],
         "relays": [{"name": "relay", "to_networks": [1]}]}])"));

    auto relay = http_get(sim.http_port(), "/api/stations/relay").json();
    CHECK(relay["networks"] == json::parse(R"([{"number": 1, "station": 4, "master": true},
                                              {"number": 2, "station": 1, "master": false}])"));
    auto list = http_get(sim.http_port(), "/api/stations").json();
    REQUIRE(list.size() == 5);
    CHECK(list[0]["networks"] == json::parse(R"([{"number": 1, "station": 1, "master": false}])"));
    CHECK(list[4]["name"] == "island");
    CHECK(list[4]["networks"] == json::array());
}

TEST_CASE("a request routed through the Ethernet module shows its route in the target's request event", "[route][plant][http][events]") {
    SimProcess sim(plant_options(R"({"bind": "127.0.0.1", "http": {"port": 0}, "stations": [
        {"name": "gw", "profile": "RJ71EN71", "tcp_port": 0, "networks": [{"number": 1, "station": 1}]},
        {"name": "press", "profile": "R08CPU", "tcp_port": 0, "networks": [{"number": 1, "station": 2}]}]})"));
    EventReader events(sim.http_port(), "", "/api/stations/press/events");

    client::FrameOptions routed;
    routed.route = slmp::protocol::Route{0x01, 0x02, 0x03FF, 0x00};
    auto gw = TcpClient::open(tcp_of(sim, "gw"));
    const auto answer = ask(gw, client::read_words(routed, addr("D100"), 1));
    REQUIRE(answer.size() == 13);
    CHECK(answer[9] == 0x00);   // end code 0000
    CHECK(answer[10] == 0x00);

    auto call = events.next_of("request").data;
    CHECK(call["command"] == "0401");
    CHECK(call["device"] == "D100");
    CHECK(call["route"] == json::parse(R"({"network": "01", "station": "02", "module_io": "03FF", "multidrop": "00"})"));

    // A request to press's own port names no route.
    auto press = TcpClient::open(tcp_of(sim, "press"));
    ask(press, client::read_words(client::FrameOptions{}, addr("D100"), 1));
    CHECK_FALSE(events.next_of("request").data.contains("route"));
}
