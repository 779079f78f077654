// One station as the HTTP side serves it: its API objects (metrics, event hub,
// waits, the endpoints' Router), living on the station's strand. The HTTP
// server hands each request for the station to that strand (on_station), so
// the endpoints keep touching the station without a lock (docs/plants.md,
// "Threads").
#pragma once

#include <atomic>
#include <exception>
#include <memory>
#include <string>
#include <string_view>
#include <type_traits>
#include <vector>

#include "station/asio.hpp"

#include "config/plant_config.hpp"
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

    // Every station endpoint, as "/api/devices/{address}", ...; made on the
    // station's first HTTP request (on its strand): the routes of 10 000
    // stations were a tenth of a plant's start, and most are never asked.
    Router& router();

private:
    std::unique_ptr<Router> router_;
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

// Runs fn(side) on the strand of every station at once and resumes the caller
// (on its strand) with the results in the stations' order. One round of the
// stations' queues instead of one per station: a 10 000-station plant's
// /metrics or overview page no longer waits behind each station in turn.
template <class F>
boost::asio::awaitable<std::vector<std::invoke_result_t<F, StationSide&>>> on_stations(std::vector<StationSide*> sides, F fn) {
    using Result = std::invoke_result_t<F, StationSide&>;
    struct Gather {
        std::vector<Result> results;
        std::vector<std::exception_ptr> errors;
        std::atomic<std::size_t> left;
        boost::asio::steady_timer done;
        // A constructor, not aggregate init: clang 14 (the sanitizer build) has no parenthesized aggregate init.
        Gather(std::size_t count, const boost::asio::any_io_executor& executor)
            : results(count), errors(count), left(count), done(executor) {}
    };
    auto executor = co_await boost::asio::this_coro::executor;
    auto gather = std::make_shared<Gather>(sides.size(), executor);
    gather->done.expires_at(boost::asio::steady_timer::time_point::max());
    for (std::size_t k = 0; k < sides.size(); ++k)
        boost::asio::post(sides[k]->home, [gather, side = sides[k], k, fn, executor] {
            try {
                gather->results[k] = fn(*side);
            } catch (...) {
                gather->errors[k] = std::current_exception();
            }
            // The last one wakes the caller; it is suspended by then (it runs on `executor` until it waits).
            if (gather->left.fetch_sub(1, std::memory_order_acq_rel) == 1)
                boost::asio::post(executor, [gather] { gather->done.cancel(); });
        });
    if (!sides.empty()) {
        boost::system::error_code ignored;
        co_await gather->done.async_wait(boost::asio::redirect_error(boost::asio::use_awaitable, ignored));
    }
    for (auto& error : gather->errors)
        if (error) std::rethrow_exception(error);
    co_return std::move(gather->results);
}

// The stations of the process, for the plant endpoints.
struct Plant {
    std::vector<std::unique_ptr<StationSide>> stations;   // the first answers the routes without /api/stations/{name}
    bool named = false;                                    // a plant: station names in routes, metrics, lists
    std::atomic<bool> ready{false};                        // every station started (GET /readyz)
    const config::ShardLayout* layout = nullptr;           // every station of the plant file and its shard (GET /api/plant)
    bool metrics_by_profile = false;                       // GET /metrics sums the stations of each profile

    StationSide* find(std::string_view name);
};

// GET /healthz, /readyz, /api/stations[/{name}], and for a plant /metrics with
// a station label (plant_endpoints.cpp).
void add_plant_endpoints(Router& router, Plant& plant);

}  // namespace slmp::control
