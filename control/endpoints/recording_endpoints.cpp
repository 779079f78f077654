// GET /api/recording — whether the JSON-lines recording runs, and its file.
// POST /api/recording {"file": "path"} — starts it (the file is truncated;
// the path is relative to the simulator's working directory), as --record does.
// DELETE /api/recording — stops it; the file is flushed and closed, ready to
// replay. A --record-pcap capture is not controlled here. docs/scenarios.md.
#include "config/config_error.hpp"
#include "control/endpoints/api.hpp"

namespace slmp::control {

using nlohmann::json;

namespace {

json recording_json(const station::ScenarioHook& hook) {
    const auto& file = hook.recording_file();
    return json{{"recording", !file.empty()}, {"file", file.empty() ? json(nullptr) : json(file)}};
}

Reply start_recording(Api& api, const ApiRequest& request) {
    auto body = json::parse(request.body, nullptr, false);
    if (body.is_discarded() || !body.is_object() || body.size() != 1 || !body.contains("file") ||
        !body["file"].is_string() || body["file"].get<std::string>().empty())
        return error_reply(Status::bad_request, "the body must be {\"file\": \"path/to/recording.jsonl\"}");
    auto& hook = api.station.scenario();
    if (!hook.recording_file().empty())
        return error_reply(Status::conflict, "already recording to " + hook.recording_file() +
                                                 "; DELETE /api/recording stops it first");
    try {
        hook.record(body["file"].get<std::string>(), api.station.cpu().profile().name);
    } catch (const config::ConfigError& e) {
        return error_reply(Status::bad_request, e.what());
    }
    return json_reply(recording_json(hook), Status::created);
}

Reply stop_recording(Api& api) {
    auto& hook = api.station.scenario();
    auto file = hook.recording_file();
    if (!hook.stop_recording())
        return error_reply(Status::conflict, "no recording is running; POST /api/recording {\"file\": \"...\"} starts one");
    return json_reply(json{{"recording", false}, {"file", file}});
}

}  // namespace

void add_recording_endpoints(Router& router, Api& api) {
    router.add(Verb::get, "/api/recording", {}, [&api](const ApiRequest&) { return json_reply(recording_json(api.station.scenario())); });
    router.add(Verb::post, "/api/recording", {}, [&api](const ApiRequest& request) { return start_recording(api, request); });
    router.add(Verb::delete_, "/api/recording", {}, [&api](const ApiRequest&) { return stop_recording(api); });
}

}  // namespace slmp::control
