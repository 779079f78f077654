// GET /api/devices/{address}?count=N&as=bits|words|dwords|string
// PUT /api/devices/{address}?as=...  with {"values": [...]} or {"string": "..."}
// The views and their checks: device_view.hpp. docs/api.md, "Devices".
#include "control/endpoints/api.hpp"
#include "control/endpoints/device_names.hpp"
#include "control/endpoints/device_view.hpp"
#include "control/endpoints/value_body.hpp"
#include "control/observers/event_hub.hpp"

namespace slmp::control {

using nlohmann::json;

namespace {

View view_of(const ApiRequest& request, const NamedDevice& named) {
    const auto* as = request.param("as");
    if (!as) return named.view.value_or(default_view(*named.start.spec));
    auto view = parse_view(*as);
    if (!view) bad("as=" + *as + " is not a view; use bits, words, dwords or string");
    return *view;
}

Reply get_devices(Api& api, const ApiRequest& request) {
    auto named = parse_station_device(api.station, request.captures.at(0));
    auto run = make_run(api.station.cpu(), named.start, view_of(request, named), count_param(request));
    return json_reply(read_run(api.station.cpu().memory(), run));
}

Reply put_devices(Api& api, const ApiRequest& request) {
    auto named = parse_station_device(api.station, request.captures.at(0));
    auto start = named.start;
    auto body = parse_value_body(request.body);
    auto view = body.contains("string") ? View::String : view_of(request, named);
    if (body.contains("string") && request.param("as") && view_of(request, named) != View::String)
        bad("{\"string\": ...} writes as=string; drop as=" + *request.param("as") + " or send \"values\"");

    std::vector<std::uint32_t> values;
    if (view == View::String) {
        if (!body["string"].is_string()) bad("\"string\" must be a JSON string");
        auto words = pack_string(body["string"].get<std::string>());
        values.assign(words.begin(), words.end());
    } else {
        values = parse_values(body["values"], view);
    }
    // Every check is done before the first write: a rejected request changes nothing.
    auto run = make_run(api.station.cpu(), start, view, values.size());
    auto& memory = api.station.cpu().memory();
    api.events.flush_writes("internal");   // what changed before this write is not the API's
    write_run(memory, run, values);
    api.events.flush_writes("api");
    return json_reply(read_run(memory, run));
}

}  // namespace

void add_device_endpoints(Router& router, Api& api) {
    router.add(Verb::get, "/api/devices/{address}", {"count", "as"},
               [&api](const ApiRequest& request) { return get_devices(api, request); });
    router.add(Verb::put, "/api/devices/{address}", {"as"},
               [&api](const ApiRequest& request) { return put_devices(api, request); });
}

}  // namespace slmp::control
