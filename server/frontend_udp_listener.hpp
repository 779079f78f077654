// A front end's UDP port (the JW-51CM computer link): one request per
// datagram, the answer sent back to the datagram's source (inferred for JW).
#pragma once

#include <chrono>
#include <cstdint>
#include <functional>
#include <span>
#include <string>

#include "station/asio.hpp"

#include "protocol/peer.hpp"

namespace slmp::server {

// The answer to one datagram (empty: none), and how long a scenario fault
// holds it back (the port's next datagram waits behind it, as on a busy unit).
struct DatagramAnswer {
    std::string bytes;
    std::chrono::microseconds delay{0};
};
using DatagramHandler = std::function<DatagramAnswer(std::span<const std::uint8_t> datagram, const protocol::Peer& peer)>;

class FrontEndUdpListener {
public:
    // Binds at once; throws boost::system::system_error when the port cannot be had.
    FrontEndUdpListener(const station::Home& home, std::string protocol, std::uint16_t port,
                        const boost::asio::ip::address& bind, DatagramHandler handler);
    std::uint16_t port() const { return port_; }
    void stop();

private:
    boost::asio::awaitable<void> serve();

    std::string protocol_;
    DatagramHandler handler_;
    boost::asio::ip::udp::socket socket_;
    std::uint16_t port_ = 0;
};

}  // namespace slmp::server
