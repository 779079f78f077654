// The running simulator: its stations (one, or a plant of them), each with its
// listeners on its home strand; the HTTP API; the signals that stop it; the
// threads that run them all (one io_context shared by --threads threads).
#pragma once

#include <memory>
#include <vector>

#include "station/asio.hpp"

#include "config/plant_config.hpp"
#include "control/http/http_server.hpp"
#include "server/listeners.hpp"
#include "station/router.hpp"
#include "station/station.hpp"

namespace slmp::server {

class Server {
public:
    // Builds every station and binds every port; throws config::ConfigError or
    // boost::system::system_error with a message that names the problem (and
    // the station, in a plant).
    explicit Server(const config::PlantConfig& plant);
    ~Server();

    // Serves until SIGINT or SIGTERM, then closes everything cleanly.
    void run();

private:
    void join_networks();
    // One station on its home strand: everything it does (its listeners,
    // scan, scenarios, the serving of its requests, the HTTP requests for it)
    // runs there; its TCP connections read and write on strands of their own.
    struct Served {
        Served(const station::Home& home, const config::StationConfig& config);
        station::Home home;
        config::StationConfig settings;   // as read (Listeners keep references into it)
        station::Station station;
        Listeners listeners;
    };

    void take_initial_snapshots();
    void log_stations() const;
    std::string http_bind() const;
    void write_ready_file() const;
    void stop();
    void wait_for_snapshot_signal();
    const config::ServerConfig& first() const { return plant_.stations.front().server; }   // the process-wide keys

    config::PlantConfig plant_;
    std::size_t threads_;                 // run io_ (the main thread is one of them)
    boost::asio::io_context io_;
    station::Home main_;                  // the HTTP server and the signals
    std::vector<std::unique_ptr<Served>> stations_;
    station::Router router_;   // the plant's networks: read-only once the stations joined it
    std::unique_ptr<control::HttpServer> http_;   // null with --no-http; destroyed before the stations
    boost::asio::signal_set signals_;
    boost::asio::signal_set snapshot_signal_;
};

}  // namespace slmp::server
