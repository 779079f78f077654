// GET /api/connections — the open TCP connections of every SLMP port.
// DELETE /api/connections/{id} — closes one, as a cable pull would look to the
// client (the socket is closed; the port accepts again if it was full).
// UDP has no connections; its traffic shows in /metrics and /api/events.
#include <charconv>

#include "control/endpoints/api.hpp"
#include "control/observers/activity_json.hpp"

namespace slmp::control {

using nlohmann::json;

namespace {

Reply list_connections(Api& api) {
    auto list = json::array();
    for (const auto& [_, connection] : api.station.activity().connections()) list.push_back(connection_json(connection));
    return json_reply(json{{"connections", std::move(list)}});
}

Reply close_connection(Api& api, const ApiRequest& request) {
    const auto& text = request.captures.at(0);
    std::uint64_t id = 0;
    auto [ptr, ec] = std::from_chars(text.data(), text.data() + text.size(), id);
    if (ec != std::errc{} || ptr != text.data() + text.size())
        return error_reply(Status::bad_request, "connection id '" + text + "' is not a number; take the id from GET /api/connections");
    if (!api.station.activity().close(id, "closed through the HTTP API"))
        return error_reply(Status::not_found, "no open connection " + text + "; GET /api/connections lists the open ones");
    return json_reply(json{{"closed", id}});
}

}  // namespace

void add_connection_endpoints(Router& router, Api& api) {
    router.add(Verb::get, "/api/connections", {}, [&api](const ApiRequest&) { return list_connections(api); });
    router.add(Verb::delete_, "/api/connections/{id}", {},
               [&api](const ApiRequest& request) { return close_connection(api, request); });
}

}  // namespace slmp::control
