// GET /api/scenarios — the running scenarios, in load order.
// POST /api/scenarios — loads one: {"file": "path"} (relative to the
// simulator's working directory) or the scenario itself as the body (then
// its source is "request body (<name>)"). It is checked exactly as --scenario
// checks a file, and a mistake comes back as 400 with the loader's message
// (file or "request body", JSON pointer, fix).
// DELETE /api/scenarios/{name} — stops it; its devices keep their values.
// How several scenarios run side by side: scenarios/runner_set.hpp.
#include "config/config_error.hpp"
#include "control/endpoints/api.hpp"
#include "control/observers/event_hub.hpp"
#include "scenarios/loader.hpp"

namespace slmp::control {

using nlohmann::json;

namespace {

// The source name of a scenario given in the body, as a file name would be.
constexpr const char* kBodySource = "request body";

json scenario_json(const scenarios::Scenario& s, double clock_ms) {
    auto faults = json::array();
    for (const auto& f : s.faults) faults.push_back(f.id.empty() ? s.source + "#" + f.pointer : f.id);
    return json{{"name", s.name},
                {"source", s.source},
                {"description", s.description},
                {"clock_ms", clock_ms},
                {"steps", s.timeline.steps.size()},
                {"triggers", s.triggers.size()},
                {"rungs", s.logic.rungs.size()},
                {"faults", std::move(faults)},
                {"replay", s.replay ? json(s.replay->file) : json(nullptr)}};
}

Reply list_scenarios(Api& api) {
    auto list = json::array();
    for (const auto& r : api.station.scenario().scenarios()) list.push_back(scenario_json(*r.scenario, r.clock_ms));
    return json_reply(json{{"scenarios", std::move(list)}});
}

scenarios::Scenario parse(const std::string& body) {
    auto parsed = json::parse(body, nullptr, false);
    if (!parsed.is_discarded() && parsed.is_object() && parsed.contains("file")) {
        if (parsed.size() != 1 || !parsed["file"].is_string())
            throw ApiError{Status::bad_request, "send {\"file\": \"path/to/scenario.json\"} alone, or the scenario "
                                                "itself as the body (a scenario has no \"file\" key)"};
        return scenarios::load_scenario(parsed["file"].get<std::string>());
    }
    auto s = scenarios::parse_scenario(body, kBodySource);
    if (!parsed.contains("name"))
        throw ApiError{Status::bad_request, std::string(kBodySource) + ": /name: a scenario sent as the body needs a "
                                            "\"name\"; DELETE /api/scenarios/{name} stops it by that name"};
    // Named from here on, so two such scenarios tell apart in messages and in
    // the names of faults without an id ("request body (x)#/faults/0").
    s.source = std::string(kBodySource) + " (" + s.name + ")";
    return s;
}

Reply load_scenario(Api& api, const ApiRequest& request) {
    devicemodel::NumberingScope numbering(api.station.cpu().profile().numbering);   // FX5: X/Y in octal
    try {
        auto s = parse(request.body);
        if (!api.station.runs(s))
            return error_reply(Status::bad_request, s.source + ": /stations: the scenario is for " +
                                                        json(s.stations).dump() + ", not this station; post it to one "
                                                        "of those, or to /api/plant/scenarios");
        for (const auto& r : api.station.scenario().scenarios())
            if (r.scenario->name == s.name)
                return error_reply(Status::conflict, "a scenario named '" + s.name + "' is already running (" +
                                                         r.scenario->source + "); DELETE /api/scenarios/" + s.name +
                                                         " first, or give this one another \"name\"");
        auto name = s.name;
        api.events.flush_writes("internal");
        api.station.scenario().load(std::move(s));
        api.events.flush_writes("api");   // its initial devices, written on the API's request
        for (const auto& r : api.station.scenario().scenarios())
            if (r.scenario->name == name) return json_reply(scenario_json(*r.scenario, r.clock_ms), Status::created);
        return error_reply(Status::internal_server_error, "the scenario '" + name + "' did not start; see the log");
    } catch (const config::ConfigError& e) {
        return error_reply(Status::bad_request, e.what());
    }
}

Reply stop_scenario(Api& api, const ApiRequest& request) {
    const auto& name = request.captures.at(0);
    if (!api.station.scenario().stop(name)) {
        std::string running;
        for (const auto& r : api.station.scenario().scenarios()) running += (running.empty() ? "" : ", ") + r.scenario->name;
        return error_reply(Status::not_found, "no running scenario '" + name + "'; " +
                                                  (running.empty() ? std::string("none is running")
                                                                   : "the running ones are " + running));
    }
    return json_reply(json{{"stopped", name}});
}

}  // namespace

void add_scenario_endpoints(Router& router, Api& api) {
    router.add(Verb::get, "/api/scenarios", {}, [&api](const ApiRequest&) { return list_scenarios(api); });
    router.add(Verb::post, "/api/scenarios", {}, [&api](const ApiRequest& request) { return load_scenario(api, request); });
    router.add(Verb::delete_, "/api/scenarios/{name}", {},
               [&api](const ApiRequest& request) { return stop_scenario(api, request); });
}

}  // namespace slmp::control
