// A plant's networks over HTTP (docs/api.md, "Plants"): GET /api/networks says
// which station is which station No. on which network and who relays between
// networks; GET /api/stations gives each station's network modules.
#include <catch2/catch.hpp>

#include "http_client.hpp"
#include "sim_process.hpp"

using namespace slmp::test;
using nlohmann::json;

TEST_CASE("GET /api/networks and /api/stations show the plant's networks and who relays to whom", "[route][plant][http]") {
    SimOptions options;
    options.plant = true;
    options.config_json = R"({"bind": "127.0.0.1", "http": {"port": 0}, "stations": [
        {"name": "gw", "profile": "RJ71EN71", "tcp_port": 0, "networks": [{"number": 1, "station": 1}]},
        {"name": "press", "profile": "R08CPU", "tcp_port": 0, "networks": [{"number": 1, "station": 2}]},
        {"name": "relay", "profile": "R08CPU", "tcp_port": 0,
         "networks": [{"number": 1, "station": 4, "master": true}, {"number": 2, "station": 1}]},
        {"name": "packer", "profile": "R04CPU", "tcp_port": 0, "networks": [{"number": 2, "station": 3}]},
        {"name": "island", "profile": "R04CPU", "tcp_port": 0}]})";
    SimProcess sim(options);

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
