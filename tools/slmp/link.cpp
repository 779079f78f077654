#include "tools/slmp/link.hpp"

#include <boost/asio/connect.hpp>
#include <boost/asio/write.hpp>

#include "tools/slmp/errors.hpp"

namespace slmp::cli {

namespace asio = boost::asio;
using asio::ip::tcp;
using asio::ip::udp;
using boost::system::error_code;

Link::Link(std::string host, std::uint16_t port, bool udp) : host_(std::move(host)), port_(port), udp_(udp) {}

std::string Link::peer() const { return host_ + ":" + std::to_string(port_) + (udp_ ? " (UDP)" : " (TCP)"); }

bool Link::run_until(const bool& done, Clock::time_point deadline) {
    io_.restart();
    while (!done) {
        if (io_.run_one_until(deadline) == 0 && Clock::now() >= deadline) break;
    }
    if (done) return true;
    cancel();
    io_.restart();
    while (!done) io_.run_one();   // the cancelled handler completes with operation_aborted
    return false;
}

void Link::cancel() {
    error_code ignored;
    if (udp_) udp_socket_.cancel(ignored);
    else tcp_.cancel(ignored);
}

void Link::open(Clock::time_point deadline) {
    error_code ec;
    auto service = std::to_string(port_);
    if (udp_) {
        auto endpoints = udp::resolver(io_).resolve(host_, service, ec);
        if (ec) throw ConnectionError("cannot resolve '" + host_ + "': " + ec.message() + " (check --host)");
        for (const auto& entry : endpoints) {
            udp_socket_.close(ec);
            udp_socket_.open(entry.endpoint().protocol(), ec);
            if (!ec) udp_socket_.connect(entry.endpoint(), ec);
            if (!ec) return;
        }
        throw ConnectionError("cannot open a UDP socket to " + peer() + ": " + ec.message());
    }
    auto endpoints = tcp::resolver(io_).resolve(host_, service, ec);
    if (ec) throw ConnectionError("cannot resolve '" + host_ + "': " + ec.message() + " (check --host)");
    bool done = false;
    asio::async_connect(tcp_, endpoints, [&](const error_code& e, const tcp::endpoint&) {
        ec = e;
        done = true;
    });
    if (!run_until(done, deadline))
        throw ConnectionError("no connection to " + peer() + " within the timeout (check --host, --port, firewall)");
    if (ec)
        throw ConnectionError("cannot connect to " + peer() + ": " + ec.message() +
                              " (is the PLC's SLMP port open for TCP on this port? try --udp or --port)");
    tcp_.set_option(tcp::no_delay(true), ec);
}

void Link::send(std::span<const std::uint8_t> bytes, Clock::time_point deadline) {
    error_code ec;
    bool done = false;
    auto handler = [&](const error_code& e, std::size_t) {
        ec = e;
        done = true;
    };
    if (udp_) udp_socket_.async_send(asio::buffer(bytes.data(), bytes.size()), handler);
    else asio::async_write(tcp_, asio::buffer(bytes.data(), bytes.size()), handler);
    if (!run_until(done, deadline)) throw ConnectionError("sending to " + peer() + " timed out");
    if (ec) throw ConnectionError("sending to " + peer() + " failed: " + ec.message());
}

Link::Received Link::try_receive(Clock::time_point deadline, std::vector<std::uint8_t>& bytes) {
    bytes.assign(udp_ ? 65536 : 8192, 0);
    error_code ec;
    std::size_t size = 0;
    bool done = false;
    auto handler = [&](const error_code& e, std::size_t n) {
        ec = e;
        size = n;
        done = true;
    };
    if (udp_) udp_socket_.async_receive(asio::buffer(bytes), handler);
    else tcp_.async_read_some(asio::buffer(bytes), handler);
    if (!run_until(done, deadline)) {
        bytes.clear();
        return Received::Silence;
    }
    bytes.resize(size);
    if (ec == asio::error::eof || ec == asio::error::connection_reset) return Received::Closed;
    if (ec == asio::error::connection_refused)
        throw ConnectionError(peer() + " refused the datagram (nothing listens on that UDP port; check --port)");
    if (ec) throw ConnectionError("receiving from " + peer() + " failed: " + ec.message());
    return Received::Data;
}

std::vector<std::uint8_t> Link::receive(Clock::time_point deadline) {
    std::vector<std::uint8_t> bytes;
    switch (try_receive(deadline, bytes)) {
        case Received::Data: return bytes;
        case Received::Silence:
            throw ConnectionError("no response from " + peer() +
                                  " within the timeout (check --port, the frame type --4e and the data code --ascii "
                                  "against the PLC's settings; a PLC ignores frames it does not accept)");
        case Received::Closed: break;
    }
    throw ConnectionError(peer() + " closed the connection");
}

}  // namespace slmp::cli
