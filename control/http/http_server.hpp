// The HTTP side of slmp-sim: JSON control API, /metrics, /api/events and the
// web monitor, on its own port and strand. Each request for a station runs on
// that station's strand (StationSide, on_station), so an API write is atomic with
// respect to SLMP requests. "/api/stations/{name}/..." reaches a station of a
// plant; the routes without it mean the first (or only) station.
#pragma once

#include <cstdint>
#include <memory>
#include <unordered_set>

#include "station/asio.hpp"

#include "config/config.hpp"
#include "config/plant_config.hpp"
#include "control/endpoints/station_side.hpp"

namespace slmp::control {

class HttpServer {
public:
    // Binds the port (throws config::ConfigError naming the fix when it cannot)
    // and serves on `strand`. `plant`: a plant (routes, lists and metrics by
    // name) or one station, its shards and metrics mode; it outlives the server.
    HttpServer(const station::Home& strand, const std::vector<ServedStation>& stations, const config::HttpConfig& config,
               const boost::asio::ip::address& bind, const config::PlantConfig& plant);

    std::uint16_t port() const { return port_; }
    // Every station is listening: GET /readyz answers 200.
    void set_ready() { plant_.ready = true; }
    void stop();

private:
    boost::asio::awaitable<void> accept_loop();
    boost::asio::awaitable<void> serve(boost::asio::ip::tcp::socket socket);
    // The station a request is for and the target its Router sees, or null
    // for the plant's own routes (and 404s).
    StationSide* station_for(std::string_view target, std::string* station_target, Reply* error);

    station::Home strand_;   // the HTTP server's own state (connections, the plant router)
    Plant plant_;
    Router plant_router_;   // /healthz, /readyz, /api/stations[/{name}], a plant's /metrics
    boost::asio::ip::tcp::acceptor acceptor_;
    std::uint16_t port_ = 0;
    std::unordered_set<boost::asio::ip::tcp::socket*> sockets_;   // open connections, closed by stop()
    std::unordered_set<boost::asio::ip::tcp::socket*> lent_;      // in a station's hands now (a wait, an event stream)
    bool stopping_ = false;                                        // stop(): lent connections close when they come back
};

}  // namespace slmp::control
