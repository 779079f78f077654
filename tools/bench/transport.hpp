// One client socket, TCP or UDP, behind one small interface, so the request
// loop in connection.cpp is written once. Errors come back as values.
#pragma once

#include <utility>   // Boost 1.74's awaitable.hpp uses std::exchange without it

#include <boost/asio/awaitable.hpp>
#include <boost/asio/ip/address.hpp>
#include <boost/system/error_code.hpp>

#include <cstdint>
#include <memory>
#include <span>

namespace slmp::bench {

using boost::asio::awaitable;
using boost::system::error_code;

struct Received {
    error_code error;
    std::size_t size = 0;
};

class Transport {
public:
    virtual ~Transport() = default;
    // TCP: a fresh connection (TCP_NODELAY on). UDP: a fresh socket, so late
    // answers to requests we gave up on cannot be mistaken for new ones.
    virtual awaitable<error_code> open() = 0;
    virtual awaitable<error_code> send(std::span<const std::uint8_t> bytes) = 0;
    // TCP: whatever has arrived; UDP: exactly one datagram.
    virtual awaitable<Received> receive(std::span<std::uint8_t> into) = 0;
    // Idempotent; a pending open/send/receive completes with operation_aborted.
    virtual void close() = 0;
    virtual bool datagram() const = 0;
};

std::unique_ptr<Transport> make_transport(const boost::asio::any_io_executor& executor, bool udp,
                                          const boost::asio::ip::address& address, std::uint16_t port);

}  // namespace slmp::bench
