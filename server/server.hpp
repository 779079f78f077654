// The running simulator: one station, its listeners, the HTTP API, and the
// signals that stop it.
#pragma once

#include <memory>

#include "station/asio.hpp"

#include "config/config.hpp"
#include "config/frontend_config.hpp"
#include "control/http_server.hpp"
#include "server/listeners.hpp"
#include "station/station.hpp"

namespace slmp::server {

class Server {
public:
    // Builds the station and binds every port; throws config::ConfigError or
    // boost::system::system_error with a message that names the problem.
    Server(const config::ServerConfig& config, const config::FrontEndsConfig& frontends = {});

    // Serves until SIGINT or SIGTERM, then closes everything cleanly.
    void run();

private:
    void write_ready_file() const;
    void stop();
    void wait_for_snapshot_signal();

    config::ServerConfig config_;
    config::FrontEndsConfig frontends_;
    boost::asio::io_context io_{1};
    station::Station station_;
    Listeners listeners_;
    std::unique_ptr<control::HttpServer> http_;   // null with --no-http
    boost::asio::signal_set signals_{io_, SIGINT, SIGTERM};
    boost::asio::signal_set snapshot_signal_{io_, SIGUSR1};
};

}  // namespace slmp::server
