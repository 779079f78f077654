// The plant's own endpoints (docs/plants.md): health, the station list, and
// one /metrics for every station. Each station is read on its own thread.
#include "config/config.hpp"
#include "config/station_pattern.hpp"
#include "control/endpoints/station_side.hpp"
#include "station/scan_loop.hpp"

namespace slmp::control {

using nlohmann::json;

namespace {

// One line of the plant overview; runs on the station's thread.
json summary(StationSide& side) {
    const auto& profile = side.station.cpu().profile();
    auto totals = side.metrics.totals();
    auto* scan = side.station.scan_loop();
    return {{"name", side.name},
            {"profile", profile.name},
            {"type_name", profile.type_name},
            {"family", config::family_name(profile.family)},
            {"xy_radix", static_cast<int>(profile.numbering.xy)},
            {"state", run_state_name(side.station.cpu().runtime().operating_state().state())},
            {"bind", side.api.ports.bind},
            {"tcp", side.api.ports.tcp},
            {"udp", side.api.ports.udp},
            {"connections", side.station.activity().connections().size()},
            {"requests", totals.requests},
            {"errors", totals.errors},
            {"scans", scan ? scan->scans() : 0},
            {"wakeups", scan ? scan->wakeups() : 0}};
}

Reply deferred(std::function<boost::asio::awaitable<Reply>()> later) {
    Reply reply;
    reply.deferred = std::move(later);
    return reply;
}

// The stations a group request names: "stations": "press-*" or a list of
// names and patterns; without it, the scenario's own "stations".
std::vector<StationSide*> group(Plant& plant, const json& body) {
    const bool scenario = body.is_object() && body.contains("scenario") && body["scenario"].is_object();
    if (!scenario || !(body.contains("stations") || body["scenario"].contains("stations")))
        throw ApiError{Status::bad_request, "send {\"stations\": \"press-*\" (or a list of names), \"scenario\": {...}}, "
                                            "or a scenario that names its \"stations\""};
    const auto& stations = body.contains("stations") ? body["stations"] : body["scenario"]["stations"];
    std::vector<std::string> patterns;
    try {
        patterns = config::parse_station_patterns(config::JsonAt(stations, "request body"));
    } catch (const config::ConfigError&) {
        throw ApiError{Status::bad_request, "\"stations\": give a name, a pattern such as \"press-*\", or a list of them"};
    }
    std::vector<StationSide*> chosen;
    for (auto& side : plant.stations)
        if (config::station_patterns_match(patterns, side->name)) chosen.push_back(side.get());
    if (chosen.empty())
        throw ApiError{Status::not_found, "no station matches " + stations.dump() + "; GET /api/stations lists them"};
    return chosen;
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
    // A scenario (faults, triggers) on a group of stations at once, all or
    // nothing: a partition of press-7 for 10 s, a power cycle of a line.
    router.add(Verb::post, "/api/plant/scenarios", {}, [&plant](const ApiRequest& request) {
        auto body = json::parse(request.body, nullptr, false);
        auto chosen = group(plant, body);
        auto scenario = body["scenario"].dump();
        auto name = body["scenario"].value("name", std::string());
        return deferred([chosen, scenario, name]() -> boost::asio::awaitable<Reply> {
            auto started = json::array();
            for (auto* side : chosen) {
                auto reply = co_await on_station(*side, [side, &scenario] {
                    auto reply = side->router.route(Verb::post, "/api/scenarios", scenario);
                    side->station.touched();   // a scenario runs every scan
                    return reply;
                });
                if (reply.status == Status::created) {
                    started.push_back(side->name);
                    continue;
                }
                for (const auto& done : started)   // all or nothing
                    for (auto* undo : chosen)
                        if (undo->name == done)
                            co_await on_station(*undo, [undo, &name] {
                                auto reply = undo->router.route(Verb::delete_, "/api/scenarios/" + name, "");
                                undo->station.touched();
                                return reply;
                            });
                auto error = json::parse(reply.body, nullptr, false);
                auto message = error.is_object() ? error.value("error", reply.body) : reply.body;
                co_return error_reply(reply.status, "station " + side->name + ": " + message +
                                                        " (no station of the group started it)");
            }
            co_return json_reply(json{{"name", name}, {"stations", started}}, Status::created);
        });
    });
    router.add(Verb::delete_, "/api/plant/scenarios/{name}", {}, [&plant](const ApiRequest& request) {
        auto name = request.captures[0];
        return deferred([&plant, name]() -> boost::asio::awaitable<Reply> {
            auto stopped = json::array();
            for (auto& side : plant.stations) {
                auto reply = co_await on_station(*side, [&side, &name] {
                    auto reply = side->router.route(Verb::delete_, "/api/scenarios/" + name, "");
                    side->station.touched();
                    return reply;
                });
                if (reply.status == Status::ok) stopped.push_back(side->name);
            }
            if (stopped.empty())
                co_return error_reply(Status::not_found, "no station runs a scenario '" + name + "'");
            co_return json_reply(json{{"stopped", name}, {"stations", stopped}});
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
