#include "tools/bench/transport.hpp"

#include <boost/asio/ip/tcp.hpp>
#include <boost/asio/ip/udp.hpp>
#include <boost/asio/redirect_error.hpp>
#include <boost/asio/use_awaitable.hpp>
#include <boost/asio/write.hpp>

namespace slmp::bench {

namespace asio = boost::asio;
using asio::ip::tcp;
using asio::ip::udp;

namespace {

class TcpTransport final : public Transport {
public:
    TcpTransport(const asio::any_io_executor& executor, tcp::endpoint endpoint)
        : socket_(executor), endpoint_(endpoint) {}

    awaitable<error_code> open() override {
        close();
        error_code ec;
        socket_ = tcp::socket(socket_.get_executor());
        co_await socket_.async_connect(endpoint_, asio::redirect_error(asio::use_awaitable, ec));
        if (!ec) socket_.set_option(tcp::no_delay(true), ec);
        co_return ec;
    }

    awaitable<error_code> send(std::span<const std::uint8_t> bytes) override {
        error_code ec;
        co_await asio::async_write(socket_, asio::buffer(bytes.data(), bytes.size()),
                                   asio::redirect_error(asio::use_awaitable, ec));
        co_return ec;
    }

    awaitable<Received> receive(std::span<std::uint8_t> into) override {
        Received r;
        r.size = co_await socket_.async_read_some(asio::buffer(into.data(), into.size()),
                                                  asio::redirect_error(asio::use_awaitable, r.error));
        co_return r;
    }

    void close() override {
        error_code ignored;
        socket_.close(ignored);
    }

    bool datagram() const override { return false; }

private:
    tcp::socket socket_;
    tcp::endpoint endpoint_;
};

class UdpTransport final : public Transport {
public:
    UdpTransport(const asio::any_io_executor& executor, udp::endpoint endpoint)
        : socket_(executor), endpoint_(endpoint) {}

    awaitable<error_code> open() override {
        close();
        error_code ec;
        socket_ = udp::socket(socket_.get_executor());
        socket_.open(endpoint_.protocol(), ec);
        // connect() on UDP only fixes the peer: datagrams from elsewhere are
        // dropped by the kernel, and an ICMP "port unreachable" becomes an error.
        if (!ec) socket_.connect(endpoint_, ec);
        co_return ec;
    }

    awaitable<error_code> send(std::span<const std::uint8_t> bytes) override {
        error_code ec;
        co_await socket_.async_send(asio::buffer(bytes.data(), bytes.size()),
                                    asio::redirect_error(asio::use_awaitable, ec));
        co_return ec;
    }

    awaitable<Received> receive(std::span<std::uint8_t> into) override {
        Received r;
        r.size = co_await socket_.async_receive(asio::buffer(into.data(), into.size()),
                                                asio::redirect_error(asio::use_awaitable, r.error));
        co_return r;
    }

    void close() override {
        error_code ignored;
        socket_.close(ignored);
    }

    bool datagram() const override { return true; }

private:
    udp::socket socket_;
    udp::endpoint endpoint_;
};

}  // namespace

std::unique_ptr<Transport> make_transport(const asio::any_io_executor& executor, bool udp,
                                          const asio::ip::address& address, std::uint16_t port) {
    if (udp) return std::make_unique<UdpTransport>(executor, udp::endpoint(address, port));
    return std::make_unique<TcpTransport>(executor, tcp::endpoint(address, port));
}

}  // namespace slmp::bench
