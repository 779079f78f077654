// GET /metrics — Prometheus text exposition format (metrics.hpp).
#include "control/endpoints/api.hpp"
#include "control/observers/metrics.hpp"

namespace slmp::control {

void add_metrics_endpoint(Router& router, Api& api) {
    router.add(Verb::get, "/metrics", {}, [&api](const ApiRequest&) {
        Reply reply;
        reply.content_type = "text/plain; version=0.0.4; charset=utf-8";
        reply.body = api.metrics.render();
        return reply;
    });
}

}  // namespace slmp::control
