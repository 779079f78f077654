// The running simulator: its stations (one, or a plant of them), each with its
// listeners on its home strand; the HTTP API; the signals that stop it; the
// threads that run them all (an event loop per thread, or one shared by all
// threads when there are fewer stations than threads; docs/plants.md, "Threads").
#pragma once

#include <memory>
#include <vector>

#include "station/asio.hpp"

#include "config/plant_config.hpp"
#include "control/http/http_server.hpp"
#include "server/listeners.hpp"
#include "station/network_map.hpp"
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
    // runs there; on a loop run by several threads its TCP connections read and
    // write on strands of their own.
    struct Served {
        Served(const station::Home& home, const config::StationConfig& config, bool shared_loop);
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

    // An io_context and the threads that run it. Station k lives on loop
    // k % loops; a loop of one thread hands nothing to another thread.
    struct Loop {
        explicit Loop(std::size_t threads);
        std::size_t threads;
        boost::asio::io_context io;
        boost::asio::executor_work_guard<boost::asio::io_context::executor_type> keep_running;   // until stop()
    };
    static std::vector<std::unique_ptr<Loop>> make_loops(std::size_t threads, std::size_t stations);
    Loop& loop_of(std::size_t station) { return *loops_[station % loops_.size()]; }

    config::PlantConfig plant_;
    std::size_t threads_;                 // run the loops (the main thread is one of them)
    std::vector<std::unique_ptr<Loop>> loops_;
    station::Home main_;                  // the HTTP server and the signals, on the last loop
    std::vector<std::unique_ptr<Served>> stations_;
    station::NetworkMap networks_;   // the plant's networks: read-only once the stations joined it
    std::unique_ptr<control::HttpServer> http_;   // null with --no-http; destroyed before the stations
    boost::asio::signal_set signals_;
    boost::asio::signal_set snapshot_signal_;
};

}  // namespace slmp::server
