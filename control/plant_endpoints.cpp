// The plant's own endpoints (docs/plants.md): health, the station list, and
// one /metrics for every station. Each station is read on its own thread.
#include "config/config.hpp"
#include "control/station_side.hpp"

namespace slmp::control {

using nlohmann::json;

namespace {

// One line of the plant overview; runs on the station's thread.
json summary(StationSide& side) {
    const auto& profile = side.station.cpu().profile();
    auto totals = side.metrics.totals();
    return {{"name", side.name},
            {"profile", profile.name},
            {"type_name", profile.type_name},
            {"family", config::family_name(profile.family)},
            {"state", run_state_name(side.station.cpu().runtime().operating_state().state())},
            {"bind", side.api.ports.bind},
            {"tcp", side.api.ports.tcp},
            {"udp", side.api.ports.udp},
            {"connections", side.station.activity().connections().size()},
            {"requests", totals.requests},
            {"errors", totals.errors}};
}

Reply deferred(std::function<boost::asio::awaitable<Reply>()> later) {
    Reply reply;
    reply.deferred = std::move(later);
    return reply;
}

}  // namespace

StationSide* Plant::find(std::string_view name) {
    for (auto& side : stations)
        if (side->name == name) return side.get();
    return nullptr;
}

void add_plant_endpoints(Router& router, Plant& plant) {
    // Liveness: the process answers HTTP.
    router.add(Verb::get, "/healthz", {}, [](const ApiRequest&) { return json_reply({{"status", "ok"}}); });
    // Readiness: every station is listening (Kubernetes' readinessProbe).
    router.add(Verb::get, "/readyz", {}, [&plant](const ApiRequest&) {
        json body{{"ready", plant.ready.load()}, {"stations", plant.stations.size()}};
        return json_reply(body, plant.ready ? Status::ok : Status::service_unavailable);
    });
    router.add(Verb::get, "/api/stations", {"filter"}, [&plant](const ApiRequest& request) {
        std::string filter = request.param("filter") ? *request.param("filter") : "";
        return deferred([&plant, filter]() -> boost::asio::awaitable<Reply> {
            auto list = json::array();
            for (auto& side : plant.stations)
                if (side->name.find(filter) != std::string::npos)
                    list.push_back(co_await on_station(*side, [&side] { return summary(*side); }));
            co_return json_reply(list);
        });
    });
    router.add(Verb::get, "/api/stations/{name}", {}, [&plant](const ApiRequest& request) {
        auto* side = plant.find(request.captures[0]);
        if (!side) throw ApiError{Status::not_found, "no station '" + request.captures[0] + "'; GET /api/stations lists them"};
        return deferred([side]() -> boost::asio::awaitable<Reply> {
            co_return json_reply(co_await on_station(*side, [side] { return summary(*side); }));
        });
    });
    if (!plant.named) return;   // one station: its own /metrics, without a station label
    router.add(Verb::get, "/metrics", {}, [&plant](const ApiRequest&) {
        return deferred([&plant]() -> boost::asio::awaitable<Reply> {
            std::vector<std::pair<std::string, std::string>> texts;
            for (auto& side : plant.stations)
                texts.emplace_back(side->name, co_await on_station(*side, [&side] { return side->metrics.render(); }));
            Reply reply;
            reply.content_type = "text/plain; version=0.0.4; charset=utf-8";
            reply.body = merge_metrics(texts);
            co_return reply;
        });
    });
}

}  // namespace slmp::control
