// The plant's own endpoints (docs/plants.md): health, the station list (a
// page at a time), the shards' map of the plant, and one /metrics for every
// station (or every profile). Each station is read on its own thread.
#include <algorithm>
#include <cctype>
#include <charconv>
#include <map>
#include <optional>

#include "config/config.hpp"
#include "config/shard.hpp"
#include "config/station_pattern.hpp"
#include "control/endpoints/station_side.hpp"
#include "station/network_map.hpp"
#include "station/scan_loop.hpp"

namespace slmp::control {

using nlohmann::json;

namespace {

// The network modules of `station`: each network's No., the module's station No.
// and whether it is the network's master (docs/plants.md, "Networks and routes").
json station_networks(const station::Station& station) {
    auto list = json::array();
    const auto* map = station.network_map();
    if (!map) return list;
    for (const auto& [number, members] : map->networks())
        for (const auto& member : members)
            if (member.station == &station)
                list.push_back({{"number", number}, {"station", member.number}, {"master", member.master}});
    return list;
}

// GET /api/networks: each network's stations, and the stations that relay
// between it and other networks (a module on each). The map is read-only
// once the plant runs, so the HTTP thread reads it without a hop.
json networks_overview(const station::NetworkMap& map) {
    std::map<const station::Station*, std::vector<std::uint16_t>> on;   // the networks each station is on
    for (const auto& [number, members] : map.networks())
        for (const auto& member : members) on[member.station].push_back(number);
    auto list = json::array();
    for (const auto& [number, members] : map.networks()) {
        auto stations = json::array();
        auto relays = json::array();
        for (const auto& member : members) {
            stations.push_back({{"name", member.name}, {"station", member.number}, {"master", member.master}});
            auto others = json::array();
            for (auto other : on[member.station])
                if (other != number) others.push_back(other);
            if (!others.empty()) relays.push_back({{"name", member.name}, {"to_networks", std::move(others)}});
        }
        list.push_back({{"number", number}, {"stations", std::move(stations)}, {"relays", std::move(relays)}});
    }
    return list;
}

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
            {"wakeups", scan ? scan->wakeups() : 0},
            {"networks", station_networks(side.station)}};
}

// ?offset=N, ?limit=N, ?shard=N: a whole number, else 400 naming it.
std::size_t count_param(const ApiRequest& request, const std::string& name, std::size_t fallback) {
    const auto* text = request.param(name);
    if (!text) return fallback;
    std::size_t value = 0;
    auto [end, error] = std::from_chars(text->data(), text->data() + text->size(), value);
    if (error != std::errc() || end != text->data() + text->size())
        throw ApiError{Status::bad_request, name + "=" + *text + ": give a whole number"};
    return value;
}

bool contains_any_case(std::string_view name, std::string_view text) {
    // std::search, not std::ranges::search: clang 14 (the sanitizer build) cannot compile libstdc++ 12's ranges.
    auto same = [](unsigned char a, unsigned char b) { return std::tolower(a) == std::tolower(b); };
    return std::search(name.begin(), name.end(), text.begin(), text.end(), same) != name.end() || text.empty();
}

// One station of the plant file: its shard and where a client reaches it.
json plant_station(const config::ShardLayout& layout, const config::PlantStation& station) {
    auto host = layout.host_pattern.empty() ? station.bind : config::shard_host(layout.host_pattern, station.shard);
    return {{"name", station.name}, {"shard", station.shard}, {"host", host}, {"tcp", station.tcp}, {"udp", station.udp}};
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
    // The overview, a page at a time: a 10 000-station plant's whole list is
    // 10 000 hops to the stations' strands; X-Total-Count says how many match.
    router.add(Verb::get, "/api/stations", {"filter", "offset", "limit"}, [&plant](const ApiRequest& request) {
        std::string filter = request.param("filter") ? *request.param("filter") : "";
        auto offset = count_param(request, "offset", 0);
        auto limit = count_param(request, "limit", plant.stations.size());
        std::vector<StationSide*> page;
        std::size_t matching = 0;
        for (auto& side : plant.stations)
            if (contains_any_case(side->name, filter) && matching++ >= offset && page.size() < limit)
                page.push_back(side.get());
        return deferred([page, matching]() -> boost::asio::awaitable<Reply> {
            auto lines = co_await on_stations(page, [](StationSide& side) { return summary(side); });
            auto reply = json_reply(json(std::move(lines)));
            reply.headers.emplace_back("X-Total-Count", std::to_string(matching));
            co_return reply;
        });
    });
    router.add(Verb::get, "/api/stations/{name}", {}, [&plant](const ApiRequest& request) {
        auto* side = plant.find(request.captures[0]);
        if (!side) throw ApiError{Status::not_found, "no station '" + request.captures[0] + "'; GET /api/stations lists them"};
        return deferred([side]() -> boost::asio::awaitable<Reply> {
            co_return json_reply(co_await on_station(*side, [side] { return summary(*side); }));
        });
    });
    // The plant's networks: who is which station No. where, who relays to whom.
    router.add(Verb::get, "/api/networks", {}, [&plant](const ApiRequest&) {
        const auto* map = plant.stations.empty() ? nullptr : plant.stations.front()->station.network_map();
        return json_reply(map ? networks_overview(*map) : json::array());
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
                    auto reply = side->router().route(Verb::post, "/api/scenarios", scenario);
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
                                auto reply = undo->router().route(Verb::delete_, "/api/scenarios/" + name, "");
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
                    auto reply = side->router().route(Verb::delete_, "/api/scenarios/" + name, "");
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
    // Which process serves which station of the plant file (docs/plants.md, "Shards").
    router.add(Verb::get, "/api/plant", {"shard"}, [&plant](const ApiRequest& request) {
        const auto& layout = *plant.layout;
        std::optional<std::size_t> only;
        if (request.param("shard")) only = count_param(request, "shard", 0);
        auto list = json::array();
        for (const auto& station : layout.stations)
            if (!only || station.shard == *only) list.push_back(plant_station(layout, station));
        return json_reply({{"shards", layout.count},
                           {"shard", layout.index},
                           {"station_count", layout.stations.size()},
                           {"stations", std::move(list)}});
    });
    router.add(Verb::get, "/api/plant/stations/{name}", {}, [&plant](const ApiRequest& request) {
        for (const auto& station : plant.layout->stations)
            if (station.name == request.captures[0]) return json_reply(plant_station(*plant.layout, station));
        throw ApiError{Status::not_found, "no station '" + request.captures[0] + "' in the plant; GET /api/plant lists them"};
    });
    // Per station (station="NAME" on every sample) or, for a plant too large
    // for that, summed per profile (docs/plants.md, "Metrics of a large plant").
    router.add(Verb::get, "/metrics", {"by"}, [&plant](const ApiRequest& request) {
        bool by_profile = plant.metrics_by_profile;
        if (const auto* by = request.param("by")) {
            if (*by != "station" && *by != "profile")
                throw ApiError{Status::bad_request, "by=" + *by + ": use by=station or by=profile"};
            by_profile = *by == "profile";
        }
        return deferred([&plant, by_profile]() -> boost::asio::awaitable<Reply> {
            std::vector<StationSide*> all;
            for (auto& side : plant.stations) all.push_back(side.get());
            auto texts = co_await on_stations(all, [by_profile](StationSide& side) {
                return std::pair{by_profile ? side.station.cpu().profile().name : side.name, side.metrics.render()};
            });
            Reply reply;
            reply.content_type = "text/plain; version=0.0.4; charset=utf-8";
            reply.body = by_profile ? sum_metrics(texts) : merge_metrics(texts);
            co_return reply;
        });
    });
}

}  // namespace slmp::control
