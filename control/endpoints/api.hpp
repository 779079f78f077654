// What the endpoints work on, and the functions that register them. Each
// endpoint family lives in its own file here; StationSide's constructor
// (station_side.cpp) registers a station's, and control/http/http_server.cpp
// the plant's own (add_plant_endpoints) and the web page (add_static_pages).
#pragma once

#include <chrono>
#include <cstdint>
#include <map>
#include <string>
#include <vector>

#include "control/http/router.hpp"
#include "station/station.hpp"
#include "station/station_snapshot.hpp"

namespace slmp::control {

class DeviceWaits;
class EventHub;
class Metrics;

// The ports the simulator serves, for GET /api/info.
struct PortList {
    std::string bind;
    std::vector<std::uint16_t> tcp;
    std::vector<std::uint16_t> udp;
    std::uint16_t http = 0;
};

struct Api {
    station::Station& station;
    EventHub& events;
    Metrics& metrics;
    DeviceWaits& waits;
    PortList ports;
    std::chrono::system_clock::time_point started;
    std::map<std::string, station::StationSnapshot> snapshots{};   // POST /api/snapshots, by name
};

void add_device_endpoints(Router& router, Api& api);       // /api/devices/{address}
void add_wait_endpoints(Router& router, Api& api);         // /api/devices/{address}/wait
void add_snapshot_endpoints(Router& router, Api& api);     // /api/snapshots[/{name}[/restore|/file]], /api/reset
void add_clock_endpoints(Router& router, Api& api);        // /api/clock[/step]
void add_label_endpoints(Router& router, Api& api);        // /api/labels[/{name}]
void add_buffer_endpoints(Router& router, Api& api);       // /api/buffer[/{module}/{address}]
void add_file_endpoints(Router& router, Api& api);         // /api/drives[/{drive}/files|file, /locks[/{pointer}]]
void add_scenario_endpoints(Router& router, Api& api);     // /api/scenarios[/{name}]
void add_fault_endpoints(Router& router, Api& api);        // /api/faults[/{name}]
void add_recording_endpoints(Router& router, Api& api);    // /api/recording
void add_compare_endpoints(Router& router, Api& api);      // /api/compare (differential mode)
void add_connection_endpoints(Router& router, Api& api);   // /api/connections[/{id}]
void add_info_endpoint(Router& router, Api& api);          // /api/info
void add_ondemand_endpoint(Router& router, Api& api);      // /api/ondemand
void add_state_endpoints(Router& router, Api& api);        // /api/state
void add_program_endpoints(Router& router, Api& api);      // /api/program[/source|/reload]
void add_event_endpoint(Router& router, Api& api);         // /api/events
void add_metrics_endpoint(Router& router, Api& api);       // /metrics
void add_redundant_endpoints(Router& router, Api& api);    // /api/redundant[/switch] (a redundant pair's CPU)
void add_face_endpoints(Router& router, Api& api);         // /api/<face>/...: each face's own resources (Face::api_routes)
void add_static_pages(Router& router);                     // / and its scripts and styles (control/web/)

// "RUN", "STOP", "PAUSE" (state_endpoints.cpp).
std::string_view run_state_name(devicemodel::RunState state);

}  // namespace slmp::control
