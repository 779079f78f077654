#include "server/frontend_udp_listener.hpp"

#include <spdlog/spdlog.h>

#include "station/log_exception.hpp"

namespace slmp::server {

namespace asio = boost::asio;
using asio::ip::udp;

FrontEndUdpListener::FrontEndUdpListener(const station::Home& home, std::string protocol, std::uint16_t port,
                                         const asio::ip::address& bind, DatagramHandler handler)
    : protocol_(std::move(protocol)), handler_(std::move(handler)), socket_(home, udp::endpoint(bind, port)) {
    port_ = socket_.local_endpoint().port();
    asio::co_spawn(home, serve(),
                   station::log_exception(protocol_ + " UDP port " + std::to_string(port_) + ": receive loop failed"));
}

asio::awaitable<void> FrontEndUdpListener::serve() {
    std::array<std::uint8_t, 65536> datagram;
    udp::endpoint sender;
    while (socket_.is_open()) {
        boost::system::error_code ec;
        auto n = co_await socket_.async_receive_from(asio::buffer(datagram), sender,
                                                     asio::redirect_error(asio::use_awaitable, ec));
        if (ec) {
            if (ec == asio::error::operation_aborted || !socket_.is_open()) co_return;
            continue;
        }
        protocol::Peer peer{protocol::Transport::Udp, sender.address().to_string(), sender.port(), port_};
        auto [answer, delay] = handler_(std::span<const std::uint8_t>(datagram.data(), n), peer);
        if (answer.empty()) {
            spdlog::debug("{} UDP {}:{}: datagram of {} byte(s) not answered", protocol_, sender.address().to_string(),
                          sender.port(), n);
            continue;
        }
        if (delay.count() > 0) {
            asio::steady_timer wait(socket_.get_executor(), delay);
            co_await wait.async_wait(asio::redirect_error(asio::use_awaitable, ec));
        }
        co_await socket_.async_send_to(asio::buffer(answer), sender, asio::redirect_error(asio::use_awaitable, ec));
        if (ec) spdlog::debug("{} UDP send failed: {}", protocol_, ec.message());
    }
}

void FrontEndUdpListener::stop() {
    boost::system::error_code ec;
    socket_.close(ec);
}

}  // namespace slmp::server
