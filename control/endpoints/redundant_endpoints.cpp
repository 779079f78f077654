// A redundant pair's state and its system switch (docs/api.md, "Redundant
// pairs"; docs/plants.md): GET /api/redundant, POST /api/redundant/switch.
// The roles are the pair's atomics (station/redundant_pair.hpp), read here on
// the station's strand.
#include "control/endpoints/api.hpp"
#include "station/network_map.hpp"

namespace slmp::control {

using nlohmann::json;

namespace {

station::RedundantPair& pair_of(Api& api) {
    const auto* map = api.station.network_map();
    auto* pair = map ? map->pair_of(api.station) : nullptr;
    if (!pair)
        fail(Status::not_found, "this station is no CPU of a redundant pair; give it \"redundant\": {\"pair\": NAME, "
                                "\"system\": \"A\"} in the plant file");
    return *pair;
}

json state(const station::Station& self, const station::RedundantPair& pair) {
    auto& control = pair.control();
    auto& standby = pair.standby();
    auto& partner = pair.partner(self);
    return json{{"system", std::string(1, pair.system_of(self))},
                {"role", pair.is_control(self) ? "control" : "standby"},
                {"pair", pair.name_of(partner)},
                {"control", pair.name_of(control)},
                {"standby", pair.name_of(standby)},
                {"switching", pair.switching()},
                {"switches", pair.switches()},
                {"switchover_ms", pair.switchover().count()},
                {"up", {{pair.name_of(self), pair.available(self)}, {pair.name_of(partner), pair.available(partner)}}}};
}

}  // namespace

void add_redundant_endpoints(Router& router, Api& api) {
    router.add(Verb::get, "/api/redundant", {}, [&api](const ApiRequest&) {
        return json_reply(state(api.station, pair_of(api)));
    });
    router.add(Verb::post, "/api/redundant/switch", {}, [&api](const ApiRequest&) {
        auto& pair = pair_of(api);
        if (auto refused = api.station.system_switch("POST /api/redundant/switch"); !refused.empty())
            fail(Status::conflict, "no system switch: " + refused);
        return json_reply(state(api.station, pair));
    });
}

}  // namespace slmp::control
