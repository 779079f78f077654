// GET /api/info — what is being simulated and where: the profile, the device
// sizes (as configured, so clients can build their address catalogue) and
// the ports. docs/api.md, "Info".
#include "config/config.hpp"
#include "control/endpoints/api.hpp"
#include "control/http/timestamp.hpp"
#include "control/observers/device_waits.hpp"
#include "devicemodel/hex.hpp"
#include "station/comparison.hpp"
#include "station/scan_loop.hpp"
#include "station/upstream.hpp"

namespace slmp::control {

using nlohmann::json;

namespace {

// The timing mode (docs/timing.md), its model's constants, and how many
// answers wait for the clock now (what a test checks instead of sleeping).
json timing(station::Station& station) {
    const auto& m = station.timing_model();
    auto* scan = station.scan_loop();
    return {{"mode", config::to_string(station.timing_mode())},
            {"ke_ms", m.ke_binary_ms},
            {"ke_ascii_ms", m.ke_ascii_ms},
            {"kdt_ms", m.kdt_binary_ms},
            {"kdt_ascii_ms", m.kdt_ascii_ms},
            {"scan_wait", m.scan_wait},
            {"waiting", scan ? scan->waiting() : 0},
            {"scans", scan ? scan->scans() : 0},
            {"wakeups", scan ? scan->wakeups() : 0}};
}

// Who answers the clients (docs/twin.md): this station's own memory
// ("serve"), the upstream alone ("proxy"), or the upstream with this station
// serving beside it for the report ("compare").
const char* serving_mode(station::Station& station) {
    if (!station.upstream()) return "serve";
    return station.comparison() ? "compare" : "proxy";
}

json upstream(station::Station& station) {
    auto* upstream = station.upstream();
    if (!upstream) return nullptr;
    json entry{{"address", upstream->address().text()},
               {"timeout_ms", upstream->timeout().count()},
               {"compare", station.comparison() != nullptr}};
    if (auto* comparison = station.comparison())
        entry["compare_slack_ms"] = std::chrono::duration<double, std::milli>(comparison->slack()).count();
    return entry;
}

Reply info(Api& api) {
    const auto& profile = api.station.cpu().profile();
    const auto& memory = api.station.cpu().memory();
    auto sizes = json::object();
    for (std::size_t i = 0; i < static_cast<std::size_t>(devicemodel::Area::Count); ++i) {
        auto area = static_cast<devicemodel::Area>(i);
        sizes[std::string(devicemodel::area_name(area))] = memory.size(area);
    }
    // The device symbols the API accepts, so a client (the web monitor) can
    // parse and number addresses the way the simulator does.
    auto devices = json::array();
    for (const auto& spec : devicemodel::all_devices()) {
        if (spec.extension_only) continue;
        devices.push_back({{"symbol", spec.symbol},
                           {"unit", spec.unit == devicemodel::Unit::Bit    ? "bit"
                                    : spec.unit == devicemodel::Unit::Word ? "word"
                                                                           : "dword"},
                           {"radix", static_cast<int>(devicemodel::radix_of(spec, profile.numbering))},
                           {"name", spec.name}});
    }
    return json_reply(json{
        {"version", "0.1.0"},
        {"started", iso_time(api.started)},
        {"profile", {{"name", profile.name}, {"type_name", profile.type_name}, {"model_code", devicemodel::hex4(profile.model_code)},
                     {"family", config::family_name(profile.family)}}},
        {"device_sizes", std::move(sizes)},
        {"devices", std::move(devices)},
        {"timing", timing(api.station)},
        {"mode", serving_mode(api.station)},
        {"upstream", upstream(api.station)},
        {"waits", api.waits.pending()},
        {"ports", {{"bind", api.ports.bind}, {"tcp", api.ports.tcp}, {"udp", api.ports.udp}, {"http", api.ports.http}}},
    });
}

}  // namespace

void add_info_endpoint(Router& router, Api& api) {
    router.add(Verb::get, "/api/info", {}, [&api](const ApiRequest&) { return info(api); });
}

}  // namespace slmp::control
