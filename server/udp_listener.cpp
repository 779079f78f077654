#include "server/udp_listener.hpp"

#include <spdlog/spdlog.h>

#include "server/tcp_session.hpp"
#include "server/udp_delivery.hpp"

namespace slmp::server {

namespace asio = boost::asio;
using asio::ip::udp;
using protocol::Outcome;

UdpListener::UdpListener(asio::io_context& io, Core& core, const config::PortConfig& port,
                         const asio::ip::address& bind)
    : core_(core), policy_(to_policy(port.data_code)), socket_(io, udp::endpoint(bind, port.port)) {
    port_ = socket_.local_endpoint().port();
    session_.id = core_.next_session_id++;
    asio::co_spawn(io, serve(), [this](std::exception_ptr e) {
        if (!e) return;
        try {
            std::rethrow_exception(e);
        } catch (const std::exception& ex) {
            spdlog::error("UDP port {}: receive loop failed: {}", port_, ex.what());
        }
    });
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
        auto peer = "udp:" + sender.address().to_string() + ":" + std::to_string(sender.port());
        auto input = std::span<const std::uint8_t>(datagram.data(), n);
        core_.activity.request_starting();
        auto started = std::chrono::steady_clock::now();
        auto handled = core_.scenario.process(core_.engine, input, policy_, session_, {config::Transport::Udp, peer, port_});
        auto& outcome = handled.outcome;
        if (outcome.action == Outcome::Action::NeedMore) {
            spdlog::debug("{} datagram of {} byte(s) holds no whole request frame (check the request data length); "
                          "not answered", peer, n);
            continue;
        }
        log_outcome(peer, outcome);
        core_.activity.request({session_.id, config::Transport::Udp, peer, input.first(outcome.consumed), outcome,
                                std::chrono::steady_clock::now() - started});
        if (outcome.consumed < n)
            spdlog::debug("{} {} byte(s) after the request frame ignored", peer, n - outcome.consumed);
        if (outcome.action == Outcome::Action::Restart && core_.on_restart) core_.on_restart();
        if (outcome.action != Outcome::Action::Respond) continue;
        co_await send_datagrams(socket_, sender, outcome.response, handled.delivery, ec);
        if (ec) spdlog::debug("{} send failed: {}", peer, ec.message());
    }
}

void UdpListener::restart_session() {
    session_ = protocol::Session{};
    session_.id = core_.next_session_id++;
}

void UdpListener::stop() {
    boost::system::error_code ec;
    socket_.close(ec);
}

}  // namespace slmp::server
