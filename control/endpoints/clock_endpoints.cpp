// GET /api/clock, PUT /api/clock {"mode": "realtime", "speed": 10} or
// {"mode": "frozen"}, POST /api/clock/step {"scans": 5} or {"ms": 1500}.
// The CPU's virtual clock: station/virtual_clock.hpp; docs/api.md, "Clock".
#include <chrono>
#include <cmath>

#include "control/endpoints/api.hpp"
#include "control/observers/event_hub.hpp"
#include "station/scan_loop.hpp"

namespace slmp::control {

using nlohmann::json;

namespace {

constexpr std::uint64_t kMaxStepScans = 1000000;   // one request must not hold the thread for long

station::ScanLoop& scan_loop(Api& api) {
    auto* loop = api.station.scan_loop();
    if (!loop) fail(Status::conflict, "this station has no scan cycle, so it has no clock");
    return *loop;
}

json clock_json(const station::ScanLoop& loop) {
    const auto& clock = loop.clock();
    auto us = std::chrono::duration_cast<std::chrono::microseconds>(clock.elapsed()).count();
    return {{"mode", clock.frozen() ? "frozen" : "realtime"},
            {"speed", clock.speed()},
            {"clock_ms", static_cast<double>(us) / 1000.0},
            {"scan_time_ms", loop.period().count()}};
}

json object_body(const std::string& text, const std::string& example) {
    auto body = json::parse(text, nullptr, false);
    if (body.is_discarded() || !body.is_object()) fail(Status::bad_request, "the body must be a JSON object such as " + example);
    return body;
}

Reply put_clock(Api& api, const ApiRequest& request) {
    const std::string example = "{\"mode\": \"realtime\", \"speed\": 10} or {\"mode\": \"frozen\"}";
    auto body = object_body(request.body, example);
    for (const auto& [key, _] : body.items())
        if (key != "mode" && key != "speed") fail(Status::bad_request, "unknown key \"" + key + "\"; send " + example);
    if (!body.contains("mode") || !body["mode"].is_string() || (body["mode"] != "realtime" && body["mode"] != "frozen"))
        fail(Status::bad_request, "\"mode\" must be \"realtime\" or \"frozen\"; send " + example);
    auto& loop = scan_loop(api);
    if (body["mode"] == "frozen") {
        if (body.contains("speed")) fail(Status::bad_request, "a frozen clock has no speed; leave \"speed\" out");
        loop.freeze_clock();
    } else {
        double speed = loop.clock().speed();
        if (body.contains("speed")) {
            if (!body["speed"].is_number()) fail(Status::bad_request, "\"speed\" must be a number");
            speed = body["speed"].get<double>();
            if (!(speed >= config::kMinClockSpeed && speed <= config::kMaxClockSpeed))
                fail(Status::bad_request, "\"speed\" " + body["speed"].dump() + ": " + config::kClockSpeedFix);
        }
        loop.run_clock(speed);
    }
    return json_reply(clock_json(loop));
}

Reply step(Api& api, const ApiRequest& request) {
    const std::string example = "{\"scans\": 5} or {\"ms\": 1500}";
    auto body = object_body(request.body, example);
    for (const auto& [key, _] : body.items())
        if (key != "scans" && key != "ms") fail(Status::bad_request, "unknown key \"" + key + "\"; send " + example);
    if (body.contains("scans") == body.contains("ms")) fail(Status::bad_request, "give one of \"scans\" and \"ms\": " + example);
    auto& loop = scan_loop(api);
    if (!loop.clock().frozen())
        fail(Status::conflict, "the clock runs in real time; freeze it first (PUT /api/clock {\"mode\": \"frozen\"}) or "
                               "start with --clock frozen");
    const auto period_us = std::chrono::duration_cast<std::chrono::microseconds>(loop.period()).count();
    api.events.flush_writes("internal");
    if (body.contains("scans")) {
        const auto& n = body["scans"];
        if (!n.is_number_unsigned() || n.get<std::uint64_t>() < 1 || n.get<std::uint64_t>() > kMaxStepScans)
            fail(Status::bad_request, "\"scans\" must be a whole number from 1 to " + std::to_string(kMaxStepScans));
        loop.step_scans(n.get<std::uint64_t>());
    } else {
        const auto& ms = body["ms"];
        if (!ms.is_number() || !(ms.get<double>() > 0))
            fail(Status::bad_request, "\"ms\" must be a positive number of milliseconds (fractions to the microsecond)");
        auto us = static_cast<std::int64_t>(std::llround(ms.get<double>() * 1000));
        if (us < 1 || static_cast<std::uint64_t>((us + period_us - 1) / period_us) > kMaxStepScans)
            fail(Status::bad_request, "\"ms\" " + ms.dump() + " is more than " + std::to_string(kMaxStepScans) +
                                          " scans or less than 1 µs; step in smaller pieces");
        loop.step_time(std::chrono::microseconds(us));
    }
    api.events.flush_writes("internal");
    return json_reply(clock_json(loop));
}

}  // namespace

void add_clock_endpoints(Router& router, Api& api) {
    router.add(Verb::get, "/api/clock", {}, [&api](const ApiRequest&) { return json_reply(clock_json(scan_loop(api))); });
    router.add(Verb::put, "/api/clock", {}, [&api](const ApiRequest& request) { return put_clock(api, request); });
    router.add(Verb::post, "/api/clock/step", {}, [&api](const ApiRequest& request) { return step(api, request); });
}

}  // namespace slmp::control
