#include "control/endpoints/station_side.hpp"

namespace slmp::control {

StationSide::StationSide(const ServedStation& served, std::uint16_t http_port)
    : name(served.name),
      station(served.station),
      home(served.home),
      metrics(served.station),
      events(served.home, served.station),
      waits(served.home, events),
      api{served.station, events, metrics, waits, served.ports, std::chrono::system_clock::now()} {
    api.ports.http = http_port;
}

Router& StationSide::router() {
    if (router_) return *router_;
    router_ = std::make_unique<Router>();
    auto& router = *router_;
    add_device_endpoints(router, api);
    add_wait_endpoints(router, api);
    add_snapshot_endpoints(router, api);
    add_clock_endpoints(router, api);
    add_buffer_endpoints(router, api);
    add_file_endpoints(router, api);
    add_label_endpoints(router, api);
    add_scenario_endpoints(router, api);
    add_fault_endpoints(router, api);
    add_recording_endpoints(router, api);
    add_compare_endpoints(router, api);
    add_connection_endpoints(router, api);
    add_info_endpoint(router, api);
    add_ondemand_endpoint(router, api);
    add_state_endpoints(router, api);
    add_program_endpoints(router, api);
    add_event_endpoint(router, api);
    add_metrics_endpoint(router, api);
    add_redundant_endpoints(router, api);
    add_face_endpoints(router, api);
    return router;
}

}  // namespace slmp::control
