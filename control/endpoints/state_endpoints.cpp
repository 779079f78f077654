// GET /api/state — the operating state (RUN/STOP/PAUSE), why, the RUN/STOP
// switch, a remote STOP/PAUSE hold and a simulated CPU error.
// PUT /api/state {"switch": "RUN"|"STOP"} — moves the CPU's RUN/STOP switch, as
// a person at the PLC would. Remote RUN/STOP/PAUSE stay SLMP operations
// (1001/1002/1003), which hold the state for the client that sent them.
// Behaviour of the state machine: docs/cpu-runtime.md.
#include "control/endpoints/api.hpp"
#include "control/observers/event_hub.hpp"
#include "devicemodel/hex.hpp"

namespace slmp::control {

using devicemodel::OperatingState;
using devicemodel::RunState;
using devicemodel::RunSwitch;
using devicemodel::StopCause;
using nlohmann::json;

std::string_view run_state_name(RunState state) {
    switch (state) {
        case RunState::Run: return "RUN";
        case RunState::Stop: return "STOP";
        case RunState::Pause: return "PAUSE";
    }
    return "?";
}

namespace {

std::string_view cause_name(StopCause cause) {
    switch (cause) {
        case StopCause::Switch: return "switch";
        case StopCause::Remote: return "remote";
        case StopCause::Instruction: return "program";
        case StopCause::Error: return "error";
    }
    return "?";
}

json state_json(const devicemodel::Runtime& runtime) {
    const auto& s = runtime.operating_state();
    json out{{"state", run_state_name(s.state())},
             {"switch", s.run_switch() == RunSwitch::Run ? "RUN" : "STOP"},
             {"cause", s.state() == RunState::Run ? json(nullptr) : json(cause_name(s.cause()))},
             {"remote_hold", nullptr},
             {"error", nullptr}};
    if (s.hold().kind != OperatingState::Hold::Kind::None)
        out["remote_hold"] = {{"kind", s.hold().kind == OperatingState::Hold::Kind::Stop ? "STOP" : "PAUSE"},
                              {"connection", s.hold().owner}};
    if (s.error()) {
        out["error"] = {{"code", devicemodel::hex4(s.error()->code)}, {"stop", s.error()->stop}};
    }
    return out;
}

Reply put_state(Api& api, const ApiRequest& request) {
    auto body = json::parse(request.body, nullptr, false);
    if (body.is_discarded() || !body.is_object())
        return error_reply(Status::bad_request, "the body must be a JSON object such as {\"switch\": \"STOP\"}");
    for (const auto& [key, _] : body.items())
        if (key != "switch")
            return error_reply(Status::bad_request, "unknown key \"" + key + "\" in the body; use \"switch\" (remote "
                                                    "RUN/STOP/PAUSE are SLMP commands 1001/1002/1003)");
    const auto& position = body.contains("switch") ? body["switch"] : json();
    if (!position.is_string() || (position != "RUN" && position != "STOP"))
        return error_reply(Status::bad_request, "\"switch\" must be \"RUN\" or \"STOP\"");
    auto& cpu = api.station.cpu();
    api.events.flush_writes("internal");
    cpu.runtime().set_switch(cpu.memory(), position == "RUN" ? RunSwitch::Run : RunSwitch::Stop);
    api.events.flush_writes("api");   // SD203 and friends
    return json_reply(state_json(cpu.runtime()));
}

}  // namespace

void add_state_endpoints(Router& router, Api& api) {
    router.add(Verb::get, "/api/state", {}, [&api](const ApiRequest&) { return json_reply(state_json(api.station.cpu().runtime())); });
    router.add(Verb::put, "/api/state", {}, [&api](const ApiRequest& request) { return put_state(api, request); });
}

}  // namespace slmp::control
