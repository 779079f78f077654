// The running simulator: one CPU, its listeners, and the signals that stop it.
#pragma once

#include <memory>
#include <vector>

#include "server/asio.hpp"

#include "config/config.hpp"
#include "server/core.hpp"
#include "server/http/http_server.hpp"
#include "server/persistence.hpp"
#include "server/scan_loop.hpp"
#include "server/scenario_station.hpp"
#include "server/tcp_listener.hpp"
#include "server/udp_listener.hpp"

namespace slmp::server {

class Server {
public:
    // Builds the CPU and binds every port; throws config::ConfigError or
    // boost::system::system_error with a message that names the problem.
    explicit Server(const config::ServerConfig& config);

    // Serves until SIGINT or SIGTERM, then closes everything cleanly.
    void run();

private:
    void write_ready_file() const;
    void stop();
    void start_cpu_runtime();     // "cpu" parameters, scan cycle, state directory
    void restart_station();       // after a Remote RESET: every connection closes
    void wait_for_snapshot_signal();
    std::vector<scenarios::Scenario> load_scenarios();              // server_scenarios.cpp
    void start_scenarios(std::vector<scenarios::Scenario> list);

    config::ServerConfig config_;
    boost::asio::io_context io_{1};
    Core core_;
    std::vector<std::unique_ptr<TcpListener>> tcp_;
    std::vector<std::unique_ptr<UdpListener>> udp_;
    std::unique_ptr<http::HttpServer> http_;   // null with --no-http
    boost::asio::signal_set signals_{io_, SIGINT, SIGTERM};
    std::unique_ptr<ScanLoop> scan_;
    std::unique_ptr<Persistence> persistence_;   // null without a state directory
    boost::asio::signal_set snapshot_signal_{io_, SIGUSR1};
    std::unique_ptr<ScenarioStation> station_;   // null without scenarios
};

}  // namespace slmp::server
