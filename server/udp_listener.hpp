// A UDP port: one datagram is one request, answered to the sender's address
// and port. No connection, so one protocol session serves the port.
#pragma once

#include <array>
#include <cstdint>

#include "station/asio.hpp"

#include "config/config.hpp"
#include "station/station.hpp"

namespace slmp::server {

class UdpListener {
public:
    UdpListener(boost::asio::io_context& io, station::Station& station, const config::PortConfig& port,
                const boost::asio::ip::address& bind);

    std::uint16_t port() const { return port_; }
    void stop();
    // After a Remote RESET: the port's session starts afresh (locked again when
    // the CPU has a remote password).
    void restart_session();

private:
    boost::asio::awaitable<void> serve();

    station::Station& station_;
    protocol::DataCodePolicy policy_;
    boost::asio::ip::udp::socket socket_;
    protocol::Session session_;
    protocol::StationNumbers own_;   // the port's network/station numbers, kept across a restart
    std::uint16_t port_ = 0;
};

}  // namespace slmp::server
