// GET /api/state — the operating state (RUN/STOP/PAUSE), why, the RUN/STOP
// switch, a remote STOP/PAUSE hold and a simulated CPU error.
// PUT /api/state {"switch": "RUN"|"STOP"} — moves the CPU's RUN/STOP switch, as
// a person at the PLC would; {"error": {"code": "3100", "stop": true}} raises a
// CPU error (as a scenario's "error" action); {"reset": true} is the RESET
// switch (docs/api.md, "Operating state"). Remote RUN/STOP/PAUSE stay SLMP operations
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

// {"code": "3100", "stop": true}: the error a scenario's "error" action raises.
std::optional<devicemodel::CpuError> error_of(const json& body) {
    const auto& e = body["error"];
    if (!e.is_object() || !e.contains("code") || !e["code"].is_string() || e["code"].get<std::string>().size() != 4 ||
        e["code"].get<std::string>().find_first_not_of("0123456789abcdefABCDEF") != std::string::npos)
        return std::nullopt;
    for (const auto& [key, _] : e.items())
        if (key != "code" && key != "stop") return std::nullopt;
    if (e.contains("stop") && !e["stop"].is_boolean()) return std::nullopt;
    devicemodel::CpuError error;
    error.code = static_cast<std::uint16_t>(std::stoul(e["code"].get<std::string>(), nullptr, 16));
    error.stop = e.value("stop", false);
    return error;
}

Reply put_state(Api& api, const ApiRequest& request) {
    auto body = json::parse(request.body, nullptr, false);
    const std::string example = "{\"switch\": \"STOP\"}, {\"error\": {\"code\": \"3100\", \"stop\": true}} or {\"reset\": true}";
    if (body.is_discarded() || !body.is_object() || body.empty())
        return error_reply(Status::bad_request, "the body must be a JSON object such as " + example);
    for (const auto& [key, _] : body.items())
        if (key != "switch" && key != "error" && key != "reset")
            return error_reply(Status::bad_request, "unknown key \"" + key + "\" in the body; use \"switch\", \"error\" or "
                                                    "\"reset\" (remote RUN/STOP/PAUSE/RESET are SLMP commands 1001/1002/1003/1006)");
    std::optional<RunSwitch> position;
    if (body.contains("switch")) {
        const auto& p = body["switch"];
        if (!p.is_string() || (p != "RUN" && p != "STOP")) return error_reply(Status::bad_request, "\"switch\" must be \"RUN\" or \"STOP\"");
        position = p == "RUN" ? RunSwitch::Run : RunSwitch::Stop;
    }
    std::optional<devicemodel::CpuError> error;
    if (body.contains("error") && !(error = error_of(body)))
        return error_reply(Status::bad_request, "\"error\" must be like {\"code\": \"3100\", \"stop\": true} (4 hex digits; stop "
                                                "true: a stop error, false: a continuation error)");
    const bool reset = body.contains("reset");
    if (reset && body["reset"] != true) return error_reply(Status::bad_request, "\"reset\": true is the only value");
    auto& cpu = api.station.cpu();
    api.events.flush_writes("internal");
    // In the order a person at the CPU would: the switch, then the error, then RESET.
    if (position) cpu.runtime().set_switch(cpu.memory(), *position);
    if (error) cpu.runtime().raise_error(cpu.memory(), *error);
    if (reset) {
        // The RESET switch: the CPU restarts whatever the "remote reset" parameter says
        // (that one is for Remote RESET 1006); every connection drops, as there.
        cpu.runtime().restart(cpu.memory());
        api.station.restart();
    }
    api.events.flush_writes("api");   // SD203 and friends
    return json_reply(state_json(cpu.runtime()));
}

}  // namespace

void add_state_endpoints(Router& router, Api& api) {
    router.add(Verb::get, "/api/state", {}, [&api](const ApiRequest&) { return json_reply(state_json(api.station.cpu().runtime())); });
    router.add(Verb::put, "/api/state", {}, [&api](const ApiRequest& request) { return put_state(api, request); });
}

}  // namespace slmp::control
