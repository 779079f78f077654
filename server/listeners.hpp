// The SLMP ports of one station: a TcpListener or UdpListener per configured
// port, bound at construction. They are the station's Transports, so a
// scenario's power cut closes the TCP ports and a restarted CPU gives UDP
// clients fresh sessions.
#pragma once

#include <cstdint>
#include <memory>
#include <string>
#include <vector>

#include "station/asio.hpp"

#include "config/config.hpp"
#include "server/tcp_listener.hpp"
#include "server/udp_listener.hpp"
#include "station/station.hpp"
#include "station/transports.hpp"

namespace slmp::server {

class Listeners final : public station::Transports {
public:
    // Binds every port of `config` on `bind`; throws config::ConfigError naming
    // the port and the fix when one cannot be had.
    Listeners(boost::asio::io_context& io, station::Station& station, const config::ServerConfig& config,
              const boost::asio::ip::address& bind);

    std::vector<std::uint16_t> tcp_ports() const;   // bound ports, also when 0 was asked for
    std::vector<std::uint16_t> udp_ports() const;
    void stop();

    void refuse_connections(bool refusing) override;
    void restart_sessions() override;
    std::vector<station::PushTarget> push_targets() override;

private:
    std::vector<std::unique_ptr<TcpListener>> tcp_;
    std::vector<std::unique_ptr<UdpListener>> udp_;
};

// "5000,5001", or "-" for none (log lines and the ready file).
std::string port_list(const std::vector<std::uint16_t>& ports);

}  // namespace slmp::server
