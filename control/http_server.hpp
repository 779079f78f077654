// The HTTP side of slmp-sim: JSON control API, /metrics, /api/events and the
// web monitor, on its own port but on the SLMP listeners' io_context thread,
// so an API write is atomic with respect to SLMP requests.
#pragma once

#include <cstdint>
#include <memory>
#include <unordered_set>

#include "station/asio.hpp"

#include "config/config.hpp"
#include "control/api.hpp"
#include "control/device_waits.hpp"
#include "control/event_hub.hpp"
#include "control/metrics.hpp"
#include "control/router.hpp"
#include "station/station.hpp"

namespace slmp::control {

class HttpServer {
public:
    // Binds the port (throws config::ConfigError naming the fix when it cannot);
    // `ports` lists the SLMP ports for /api/info.
    HttpServer(boost::asio::io_context& io, station::Station& station, const config::HttpConfig& config,
               const boost::asio::ip::address& bind, PortList ports);

    std::uint16_t port() const { return port_; }
    void stop();

private:
    boost::asio::awaitable<void> accept_loop();
    boost::asio::awaitable<void> serve(boost::asio::ip::tcp::socket socket);

    boost::asio::io_context& io_;
    Metrics metrics_;
    EventHub events_;
    DeviceWaits waits_;
    Api api_;
    Router router_;
    boost::asio::ip::tcp::acceptor acceptor_;
    std::uint16_t port_ = 0;
    std::unordered_set<boost::asio::ip::tcp::socket*> sockets_;   // open connections, closed by stop()
};

}  // namespace slmp::control
