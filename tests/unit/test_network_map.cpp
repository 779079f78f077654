// The plant's network map (station/network_map.hpp; docs/plants.md, "Networks and
// routes"): who a network/station pair names, the relay stations on the way,
// and the codes of the refusals (docs/end-codes.md, "Routes through a module").
// And the decoder's half: a module's port leaves another station's request
// undecoded for the network map, a built-in port refuses it.
#include <catch2/catch.hpp>

#include <deque>

#include "config/config.hpp"
#include "protocol/engine.hpp"
#include "station/network_map.hpp"
#include "station/station.hpp"

using slmp::protocol::EndCode;
using slmp::station::NetworkMap;
using slmp::station::Station;

namespace {

slmp::config::NetworkConfig on(std::uint16_t network, std::uint16_t station, bool master = false) {
    slmp::config::NetworkConfig n;
    n.number = network;
    n.station = station;
    n.master = master;
    return n;
}

struct Plant {
    std::deque<Station> stations;
    NetworkMap map;
    Station& add(const std::string& name, std::vector<slmp::config::NetworkConfig> networks,
                 std::vector<slmp::config::RouteConfig> routes = {}) {
        auto& s = stations.emplace_back(slmp::config::load_profile("R08CPU"), slmp::protocol::EngineOptions{});
        map.add(s, name, networks, routes);
        return s;
    }
};

}  // namespace

TEST_CASE("network map: stations of the receiving module's network, the master, other networks through relay stations",
          "[route]") {
    Plant p;
    auto& gw = p.add("gw", {on(1, 1)});
    auto& press = p.add("press", {on(1, 2)});
    auto& welder = p.add("welder", {on(1, 3, true)});
    auto& relay = p.add("relay", {on(1, 4), on(2, 1)});
    auto& packer = p.add("packer", {on(2, 3)});

    auto found = p.map.find(gw, 1, 2);
    CHECK(found.error == EndCode::Ok);
    CHECK(found.relay.target == &press);
    CHECK(found.relay.hops == std::vector<Station*>{&gw});
    CHECK(p.map.find(gw, 1, 0x7D).relay.target == &welder);
    CHECK(p.map.find(gw, 1, 0x7E).relay.target == &welder);
    CHECK(p.map.find(gw, 1, 1).relay.target == &gw);
    CHECK(p.map.find(gw, 0, 0xFF).relay.target == &gw);

    found = p.map.find(gw, 2, 3);
    CHECK(found.error == EndCode::Ok);
    CHECK(found.relay.target == &packer);
    CHECK(found.relay.hops == std::vector<Station*>{&gw, &relay});
    // From the far side the same way back; 7D on network 2 is its lowest station No. (relay, 1).
    CHECK(p.map.find(packer, 1, 2).relay.hops == std::vector<Station*>{&packer, &relay});
    CHECK(p.map.find(packer, 2, 0x7D).relay.target == &relay);

    CHECK(p.map.find(gw, 3, 1).error == EndCode::RouteNetworkNotFound);
    CHECK(p.map.find(gw, 1, 9).error == EndCode::RouteStationNotFound);
    CHECK(p.map.find(gw, 0, 2).error == EndCode::RouteStationNotFound);
}

TEST_CASE("network map: a network no relay station links answers 4A01, more than 7 relay stations 4A03", "[route]") {
    Plant p;
    auto& gw = p.add("gw", {on(1, 1)});
    p.add("island", {on(5, 1)});
    CHECK(p.map.find(gw, 5, 1).error == EndCode::RouteNetworkNotFound);
    for (std::uint16_t k = 1; k <= 8; ++k) p.add("hop", {on(k, 2), on(static_cast<std::uint16_t>(k + 1), 3)});
    auto& end7 = p.add("end-7", {on(8, 9)});
    p.add("end-8", {on(9, 9)});
    auto seven = p.map.find(gw, 8, 9);
    CHECK(seven.error == EndCode::Ok);
    CHECK(seven.relay.target == &end7);
    CHECK(seven.relay.hops.size() == 1 + NetworkMap::kMaxRelayStations);
    CHECK(p.map.find(gw, 9, 9).error == EndCode::RouteTooManyRelays);
}

TEST_CASE("network map: routing parameters replace the derived way hop by hop, no way on is 4A01, a loop 4A03", "[route]") {
    Plant p;
    auto& gw = p.add("gw", {on(1, 1)}, {{2, 1, 3}, {3, 1, 2}, {4, 1, 2}});
    auto& other = p.add("other-gw", {on(1, 6)});
    auto& a = p.add("relay-a", {on(1, 2), on(2, 1)}, {{4, 1, 1}});
    auto& b = p.add("relay-b", {on(1, 3), on(2, 2)});
    auto& packer = p.add("packer", {on(2, 3)});
    p.add("island", {on(3, 1)});
    p.add("island-4", {on(4, 1)});
    // gw: by its parameter through relay-b; other-gw: derived, the first relay station (relay-a).
    auto found = p.map.find(gw, 2, 3);
    CHECK(found.relay.target == &packer);
    CHECK(found.relay.hops == std::vector<Station*>{&gw, &b});
    CHECK(p.map.find(other, 2, 3).relay.hops == std::vector<Station*>{&other, &a});
    // relay-a has no way to network 3; gw and relay-a send network 4 back and forth.
    CHECK(p.map.find(gw, 3, 1).error == EndCode::RouteNetworkNotFound);
    CHECK(p.map.find(gw, 4, 1).error == EndCode::RouteTooManyRelays);
    // A station on the target's network hands it over, whatever its parameters say.
    CHECK(p.map.find(a, 2, 3).relay.hops == std::vector<Station*>{&a});
}

TEST_CASE("network map: the extended station No. names stations 121-65534, 0000 the designated master", "[route]") {
    Plant p;
    auto& gw = p.add("gw", {on(1, 1)});
    auto& node = p.add("node", {on(1, 300, true)});
    auto& low = p.add("low", {on(1, 5)});
    CHECK(p.map.find(gw, 1, 300, true).relay.target == &node);
    CHECK(p.map.find(gw, 1, 0x0000, true).relay.target == &node);
    CHECK(p.map.find(gw, 1, 0x7D).relay.target == &node);
    CHECK(p.map.find(gw, 1, 5).relay.target == &low);
    CHECK(p.map.find(gw, 1, 5, true).error == EndCode::RouteStationNotFound);        // 1-120: the station No. field
    CHECK(p.map.find(gw, 1, 0x7D, true).error == EndCode::RouteStationNotFound);     // 125: no such station
    CHECK(p.map.find(gw, 1, 0xFFFF, true).error == EndCode::RouteStationNotFound);   // own station only at 00
    CHECK(p.map.find(gw, 1, 0x80).error == EndCode::RouteStationNotFound);           // station field past 78
}

TEST_CASE("network map: a module's port leaves another station's request undecoded, a built-in port refuses it", "[route]") {
    // 0401 D100 ×1 for network 1 station 2.
    const std::vector<std::uint8_t> request{0x50, 0x00, 0x01, 0x02, 0xFF, 0x03, 0x00, 0x0C, 0x00, 0x10, 0x00,
                                            0x01, 0x04, 0x00, 0x00, 0x64, 0x00, 0x00, 0xA8, 0x01, 0x00};
    auto module = slmp::config::load_profile("RJ71EN71");
    CHECK(module.port.relays);
    slmp::devicemodel::Cpu cpu(module.cpu);
    slmp::protocol::Engine engine(cpu, module.port);
    auto decoded = engine.decode(request, slmp::protocol::DataCodePolicy::Auto);
    CHECK(decoded.elsewhere);
    CHECK(decoded.operands.devices.empty());
    CHECK(decoded.route_error == EndCode::RouteNetworkNotFound);   // what it gets when no router takes it
    auto routed = engine.decode(request, slmp::protocol::DataCodePolicy::Auto, {}, true);
    CHECK(!routed.elsewhere);
    CHECK(routed.route_error == EndCode::Ok);
    CHECK(routed.operands.devices.size() == 1);

    auto builtin = slmp::config::load_profile("R08CPU");
    CHECK(!builtin.port.relays);
    slmp::devicemodel::Cpu cpu2(builtin.cpu);
    slmp::protocol::Engine refusing(cpu2, builtin.port);
    auto refused = refusing.decode(request, slmp::protocol::DataCodePolicy::Auto);
    CHECK(!refused.elsewhere);
    CHECK(refused.route_error == EndCode::RouteNetworkNotFound);
}

TEST_CASE("network map: a redundant pair's 03D0-03D3, its system switch, multidrop stations behind a serial module",
          "[route][redundant][multidrop]") {
    Plant p;
    auto& gw = p.add("gw", {on(1, 1)});
    auto& a = p.add("press-a", {on(1, 2)});
    auto& b = p.add("press-b", {on(1, 3)});
    auto& line = p.add("line", {on(1, 4)});
    auto& drop = p.add("drop", {});
    slmp::config::RedundantConfig pair;
    pair.pair = "press-a";
    pair.system = 'B';
    pair.switchover_ms = 0;   // a switch ends at once (a bare station has no clock to wait on)
    p.map.add_redundant(b, "press-b", pair);
    slmp::config::MultidropConfig md;
    md.via = "line";
    md.module_io = 0x0004;
    md.number = 3;
    p.map.add_multidrop(drop, "drop", md);
    p.map.link();

    CHECK(p.map.identity(a).redundant);
    CHECK(p.map.identity(drop).multidrop);
    CHECK(p.map.identity(drop).multidrop_io == 0x0004);
    CHECK_FALSE(p.map.identity(gw).redundant);
    auto* redundant = p.map.pair_of(a);
    REQUIRE(redundant == p.map.pair_of(b));
    CHECK(redundant->system_of(a) == 'A');
    CHECK(&redundant->control() == &a);

    auto through = [&](std::uint8_t station, std::uint16_t io, std::uint8_t multidrop = 0, bool file = false) {
        auto found = p.map.find(gw, 1, station);
        p.map.beyond(found, io, multidrop, file);
        return found;
    };
    // Reached at press-a (station 2): 03D0 is press-a itself, 03D1 press-b over the tracking cable.
    auto found = through(2, 0x03D0);
    CHECK(found.relay.target == &a);
    CHECK(found.relay.hops == std::vector<Station*>{&gw});
    found = through(2, 0x03D1);
    CHECK(found.relay.target == &b);
    CHECK(found.relay.hops == std::vector<Station*>{&gw, &a});
    CHECK(through(3, 0x03D2).relay.target == &a);
    CHECK(through(3, 0x03D3).relay.target == &b);
    // A file command by role is left to the CPU (which answers 4B02).
    CHECK(through(3, 0x03D0, 0, true).relay.target == &b);

    CHECK(redundant->switch_over("test", slmp::devicemodel::SwitchCause::Request).empty());
    CHECK(&redundant->control() == &b);
    CHECK_FALSE(redundant->switching());
    CHECK(through(2, 0x03D0).relay.target == &b);
    CHECK(through(2, 0x03D1).relay.target == &a);
    // The standby down: no switch; a route to it by role 4245.
    redundant->set_available(a, false);
    CHECK(redundant->switch_over("test", slmp::devicemodel::SwitchCause::Request) == "the standby system (press-a) is down");
    CHECK(through(3, 0x03D1).error == EndCode::OtherSystemError);

    // Multidrop station 3 behind line's serial module at 0040 (route module I/O 0004).
    found = through(4, 0x0004, 3);
    CHECK(found.error == EndCode::Ok);
    CHECK(found.relay.target == &drop);
    CHECK(found.relay.hops == std::vector<Station*>{&gw, &line});
    CHECK(through(4, 0x0004, 5).relay.target == &line);   // no such multidrop No.: line answers 4A02
    CHECK(through(4, 0x0004, 3, true).error == EndCode::RouteNotCpu);
}
