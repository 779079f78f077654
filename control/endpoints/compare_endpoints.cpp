// GET /api/compare — differential mode's report (slmp-sim --upstream HOST:PORT
// --compare; docs/twin.md, "Compare"): how many requests both sides served,
// how many answered the same, the differences by kind, and the last
// station::Comparison::kKept differences (the oldest first), each with the
// request, both answers and how they differ (scenarios/difference_json.hpp).
// DELETE /api/compare — counting starts afresh.
// A station without --compare answers 404 naming the option.
#include "control/endpoints/api.hpp"
#include "control/observers/activity_json.hpp"
#include "control/http/timestamp.hpp"
#include "devicemodel/hex.hpp"
#include "scenarios/difference_json.hpp"
#include "station/comparison.hpp"
#include "station/upstream.hpp"

namespace slmp::control {

using nlohmann::json;

namespace {

Reply not_comparing() {
    return error_reply(Status::not_found, "this station does not compare: start it with --upstream HOST:PORT --compare "
                                          "(a plant station: \"upstream\" and \"compare\": true; docs/twin.md)");
}

Reply report(Api& api) {
    auto* comparison = api.station.comparison();
    if (!comparison) return not_comparing();
    auto differences = json::array();
    for (const auto& c : comparison->differences()) differences.push_back(compared_json(c));
    return json_reply(json{
        {"upstream", api.station.upstream()->address().text()},
        {"slack_ms", std::chrono::duration<double, std::milli>(comparison->slack()).count()},
        {"compared", comparison->compared()},
        {"same", comparison->same()},
        {"different", comparison->different()},
        {"kinds", scenarios::kinds_json([&](auto kind) { return comparison->count(kind); })},
        {"kept", station::Comparison::kKept},
        {"differences", std::move(differences)},
    });
}

}  // namespace

void add_compare_endpoints(Router& router, Api& api) {
    router.add(Verb::get, "/api/compare", {}, [&api](const ApiRequest&) { return report(api); });
    router.add(Verb::delete_, "/api/compare", {}, [&api](const ApiRequest&) {
        auto* comparison = api.station.comparison();
        if (!comparison) return not_comparing();
        comparison->clear();
        return report(api);
    });
}

}  // namespace slmp::control
