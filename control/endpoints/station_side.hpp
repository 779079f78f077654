// One station as the HTTP side serves it: its API objects (metrics, event hub,
// waits, the endpoints' Router), living on the station's strand. The HTTP
// server hands each request for the station to that strand (on_station), so
// the endpoints keep touching the station without a lock (docs/plants.md,
// "Threads").
#pragma once

#include <atomic>
#include <memory>
#include <string>
#include <string_view>
#include <type_traits>
#include <vector>

#include "station/asio.hpp"

#include "control/endpoints/api.hpp"
#include "control/http/router.hpp"
#include "control/observers/device_waits.hpp"
#include "control/observers/event_hub.hpp"
#include "control/observers/metrics.hpp"
#include "station/station.hpp"

namespace slmp::control {

// What the server gives the HTTP side of each station.
struct ServedStation {
    std::string name;                   // empty for a lone station
    station::Station& station;
    station::Home home;                 // the strand the station runs on
    PortList ports;
};

struct StationSide {
    StationSide(const ServedStation& served, std::uint16_t http_port);
    StationSide(const StationSide&) = delete;
    StationSide& operator=(const StationSide&) = delete;

    std::string name;
    station::Station& station;
    station::Home home;
    Metrics metrics;
    EventHub events;
    DeviceWaits waits;
    Api api;
    Router router;   // every station endpoint, as "/api/devices/{address}", ...
};

// Runs fn() on the station's strand, after the scans due by now
// (Station::catch_up), and resumes the caller with the result. A fn that
// changes the station calls Station::touched() itself.
template <class F>
boost::asio::awaitable<std::invoke_result_t<F>> on_station(StationSide& side, F fn) {
    return station::on_home(side.home, [station = &side.station, fn = std::move(fn)]() mutable {
        station->catch_up();
        return fn();
    });
}

// The stations of the process, for the plant endpoints.
struct Plant {
    std::vector<std::unique_ptr<StationSide>> stations;   // the first answers the routes without /api/stations/{name}
    bool named = false;                                    // a plant: station names in routes, metrics, lists
    std::atomic<bool> ready{false};                        // every station started (GET /readyz)

    StationSide* find(std::string_view name);
};

// GET /healthz, /readyz, /api/stations[/{name}], and for a plant /metrics with
// a station label (plant_endpoints.cpp).
void add_plant_endpoints(Router& router, Plant& plant);

}  // namespace slmp::control
