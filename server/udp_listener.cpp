#include "server/udp_listener.hpp"

#include <spdlog/spdlog.h>

#include "server/tcp_session.hpp"
#include "server/udp_delivery.hpp"
#include "station/log_exception.hpp"

namespace slmp::server {

namespace asio = boost::asio;
using asio::ip::udp;
using protocol::Outcome;

UdpListener::UdpListener(asio::io_context& io, station::Station& station, const config::PortConfig& port,
                         const asio::ip::address& bind)
    : station_(station), policy_(to_policy(port.data_code)), socket_(io, udp::endpoint(bind, port.port)) {
    port_ = socket_.local_endpoint().port();
    own_ = port.numbers;
    session_.id = station_.next_session_id();
    session_.own = own_;
    asio::co_spawn(io, serve(), station::log_exception("UDP port " + std::to_string(port_) + ": receive loop failed"));
}

asio::awaitable<void> UdpListener::serve() {
    std::array<std::uint8_t, 65536> datagram;
    udp::endpoint sender;
    while (socket_.is_open()) {
        boost::system::error_code ec;
        auto n = co_await socket_.async_receive_from(asio::buffer(datagram), sender,
                                                     asio::redirect_error(asio::use_awaitable, ec));
        if (ec) {
            if (ec == asio::error::operation_aborted || !socket_.is_open()) co_return;
            spdlog::debug("UDP port {}: receive failed: {}", port_, ec.message());
            continue;
        }
        const protocol::Peer peer{protocol::Transport::Udp, sender.address().to_string(), sender.port(), port_};
        auto input = std::span<const std::uint8_t>(datagram.data(), n);
        auto handled = station_.handle(input, policy_, session_, peer);
        auto& outcome = handled.outcome;
        if (outcome.action == Outcome::Action::NeedMore) {
            spdlog::debug("{} datagram of {} byte(s) holds no whole request frame (check the request data length); "
                          "not answered", peer.text(), n);
            continue;
        }
        if (outcome.consumed < n)
            spdlog::debug("{} {} byte(s) after the request frame ignored", peer.text(), n - outcome.consumed);
        if (outcome.action == Outcome::Action::Restart) station_.restart();
        if (outcome.action != Outcome::Action::Respond) continue;
        co_await send_datagrams(socket_, sender, outcome.response, handled.delivery, ec);
        if (ec) spdlog::debug("{} send failed: {}", peer.text(), ec.message());
    }
}

void UdpListener::restart_session() {
    session_ = protocol::Session{};
    session_.id = station_.next_session_id();
    session_.own = own_;
}

void UdpListener::stop() {
    boost::system::error_code ec;
    socket_.close(ec);
}

}  // namespace slmp::server
