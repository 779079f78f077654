// POST /api/ondemand {"data": "D100-D109", "to": "all"} — the CPU sends the
// devices' words now as an Ondemand 2101 push (docs/timing.md) to every
// connected client, or to "tcp", "udp" or one TCP connection id. docs/api.md,
// "Ondemand".
#include "config/config_error.hpp"
#include "control/endpoints/api.hpp"
#include "scenarios/recording.hpp"
#include "scenarios/scenario.hpp"

namespace slmp::control {

using nlohmann::json;

namespace {

Reply ondemand(Api& api, const ApiRequest& request) {
    const std::string example = "{\"data\": \"D100-D109\", \"to\": \"all\"}";
    auto body = json::parse(request.body, nullptr, false);
    if (body.is_discarded() || !body.is_object()) fail(Status::bad_request, "the body must be a JSON object such as " + example);
    for (const auto& item : body.items())
        if (item.key() != "data" && item.key() != "to") fail(Status::bad_request, "unknown key \"" + item.key() + "\"; send " + example);
    if (!body.contains("data") || !body["data"].is_string()) fail(Status::bad_request, "\"data\" must be a device range; send " + example);
    std::string to = "all";
    if (body.contains("to")) {
        if (body["to"].is_number_unsigned()) to = std::to_string(body["to"].get<std::uint64_t>());
        else if (body["to"].is_string()) to = body["to"].get<std::string>();
        else fail(Status::bad_request, "\"to\" must be \"all\", \"tcp\", \"udp\" or a TCP connection id");
    }
    std::string error;
    devicemodel::NumberingScope numbering(api.station.cpu().profile().numbering);   // FX5: X/Y in octal
    auto action = scenarios::parse_ondemand(body["data"].get<std::string>(), to, &error);
    if (!action) fail(Status::bad_request, "\"data\": " + error + "; write a device range such as \"D100-D109\" (at most 960 words)");
    std::vector<station::Station::Pushed> sent;
    try {
        sent = api.station.ondemand(*action, "POST /api/ondemand");
    } catch (const config::ConfigError& e) {
        fail(Status::bad_request, e.what());
    }
    auto list = json::array();
    for (const auto& s : sent)
        list.push_back({{"connection", s.connection},
                        {"transport", station::to_string(s.peer.transport)},
                        {"peer", s.peer.endpoint()},
                        {"frame", scenarios::to_hex(s.frame)}});
    return json_reply(json{{"sent", std::move(list)}});
}

}  // namespace

void add_ondemand_endpoint(Router& router, Api& api) {
    router.add(Verb::post, "/api/ondemand", {}, [&api](const ApiRequest& request) { return ondemand(api, request); });
}

}  // namespace slmp::control
