// A front end's UDP port (the JW-51CM computer link): one request per
// datagram, the answer sent back to the datagram's source (inferred for JW).
#pragma once

#include <cstdint>
#include <functional>
#include <span>
#include <string>

#include "station/asio.hpp"

namespace slmp::server {

// The answer to one datagram; empty: none.
using DatagramHandler = std::function<std::string(std::span<const std::uint8_t> datagram)>;

class FrontEndUdpListener {
public:
    // Binds at once; throws boost::system::system_error when the port cannot be had.
    FrontEndUdpListener(boost::asio::io_context& io, std::string protocol, std::uint16_t port,
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
