// One connection to a PLC, TCP or UDP, with blocking calls bounded by a timeout.
// Each call starts an Asio operation and runs the private io_context until it
// completes or the deadline passes (then it is cancelled): the usual way to get
// timeouts on Asio 1.18 without threads. Failures throw ConnectionError with a
// message that says what to check.
#pragma once

#include <utility>   // before Boost 1.74's Asio headers, which use std::exchange without it

#include <boost/asio/io_context.hpp>
#include <boost/asio/ip/tcp.hpp>
#include <boost/asio/ip/udp.hpp>

#include <chrono>
#include <cstdint>
#include <span>
#include <string>
#include <vector>

namespace slmp::cli {

using Clock = std::chrono::steady_clock;

class Link {
public:
    Link(std::string host, std::uint16_t port, bool udp);

    // Resolves the host and connects (UDP: fixes the peer, so an ICMP "port
    // unreachable" shows up as an error on the next receive).
    void open(Clock::time_point deadline);
    void send(std::span<const std::uint8_t> bytes, Clock::time_point deadline);
    // TCP: whatever has arrived (at least one byte); UDP: exactly one datagram.
    std::vector<std::uint8_t> receive(Clock::time_point deadline);
    // The same without throwing on what a probe wants to see: nothing before the
    // deadline (Silence) or the peer closing or resetting the connection (Closed).
    enum class Received : std::uint8_t { Data, Silence, Closed };
    Received try_receive(Clock::time_point deadline, std::vector<std::uint8_t>& bytes);
    bool datagram() const { return udp_; }
    std::string peer() const;

    boost::asio::io_context& context() { return io_; }

private:
    // Runs io_ until `done` or the deadline; on the deadline cancels the socket's
    // operations, lets their handlers run, and returns false.
    bool run_until(const bool& done, Clock::time_point deadline);
    void cancel();

    std::string host_;
    std::uint16_t port_;
    bool udp_;
    boost::asio::io_context io_;
    boost::asio::ip::tcp::socket tcp_{io_};
    boost::asio::ip::udp::socket udp_socket_{io_};
};

}  // namespace slmp::cli
