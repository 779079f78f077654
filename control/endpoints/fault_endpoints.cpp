// GET /api/faults — every fault of the running scenarios: its id, scenario,
// kind, whether it is on, and how often it matched a request and fired.
// PUT /api/faults/{id} {"enabled": false} — turns one off (or on), as a
// trigger's start_fault/stop_fault would. A fault without an "id" is named
// "<file>#/faults/N"; percent-encode it in the path (%23 for '#', %2F for '/').
#include "control/endpoints/api.hpp"

namespace slmp::control {

using nlohmann::json;

namespace {

json fault_json(const scenarios::FaultStats& f) {
    return json{{"id", f.name},          {"scenario", f.scenario}, {"kind", f.kind},
                {"enabled", f.enabled},  {"matched", f.matched},   {"fired", f.fired}};
}

Reply list_faults(Api& api) {
    auto list = json::array();
    for (const auto& f : api.station.scenario().fault_stats()) list.push_back(fault_json(f));
    return json_reply(json{{"faults", std::move(list)}});
}

Reply switch_fault(Api& api, const ApiRequest& request) {
    const auto& id = request.captures.at(0);
    auto body = json::parse(request.body, nullptr, false);
    if (body.is_discarded() || !body.is_object() || body.size() != 1 || !body.contains("enabled") ||
        !body["enabled"].is_boolean())
        return error_reply(Status::bad_request, "the body must be {\"enabled\": true} or {\"enabled\": false}");
    if (!api.station.scenario().enable_fault(id, body["enabled"].get<bool>())) {
        std::string ids;
        for (const auto& f : api.station.scenario().fault_stats()) ids += (ids.empty() ? "" : ", ") + f.name;
        return error_reply(Status::not_found, "no fault '" + id + "'; " +
                                                  (ids.empty() ? std::string("no scenario with faults is running")
                                                               : "the faults are " + ids));
    }
    for (const auto& f : api.station.scenario().fault_stats())
        if (f.name == id) return json_reply(fault_json(f));
    return json_reply(json{{"id", id}});
}

}  // namespace

void add_fault_endpoints(Router& router, Api& api) {
    router.add(Verb::get, "/api/faults", {}, [&api](const ApiRequest&) { return list_faults(api); });
    router.add(Verb::put, "/api/faults/{id}", {}, [&api](const ApiRequest& request) { return switch_fault(api, request); });
}

}  // namespace slmp::control
