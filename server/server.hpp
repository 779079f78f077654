// The running simulator: one CPU, its listeners, and the signals that stop it.
#pragma once

#include <memory>
#include <vector>

#include "server/asio.hpp"

#include "config/config.hpp"
#include "server/core.hpp"
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

    config::ServerConfig config_;
    boost::asio::io_context io_{1};
    Core core_;
    std::vector<std::unique_ptr<TcpListener>> tcp_;
    std::vector<std::unique_ptr<UdpListener>> udp_;
    boost::asio::signal_set signals_{io_, SIGINT, SIGTERM};
};

}  // namespace slmp::server
