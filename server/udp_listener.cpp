#include "server/udp_listener.hpp"

#include <spdlog/spdlog.h>

#include "server/tcp_session.hpp"
#include "server/udp_delivery.hpp"
#include "station/log_exception.hpp"
#include "station/scan_loop.hpp"

namespace slmp::server {

namespace asio = boost::asio;
using asio::ip::udp;
using protocol::Outcome;

constexpr std::size_t kMaxPushPeers = 256;   // UDP peers an Ondemand push reaches (docs/timing.md)

UdpListener::UdpListener(asio::io_context& io, station::Station& station, const config::PortConfig& port,
                         const asio::ip::address& bind)
    : station_(station),
      policy_(to_policy(port.data_code)),
      config_(port),
      session_(station.new_session(port)),
      socket_(io, udp::endpoint(bind, port.port)) {
    port_ = socket_.local_endpoint().port();
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
        if (station_.timing_mode() == config::TimingMode::EndOfScan && station_.scan_loop())   // docs/timing.md
            co_await station_.scan_loop()->until_scan_after(station_.scan_loop()->scans());
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
        // Remember who spoke, for Ondemand pushes; bounded, so a flood of
        // source ports cannot grow it without end (later peers are not pushed to).
        if (outcome.command != 0 && (peers_.size() < kMaxPushPeers || peers_.count(sender))) {
            auto [kind, codec] = request_shape(input);
            peers_[sender] = {kind, codec};
        }
        if (outcome.action == Outcome::Action::Restart) station_.restart();
        if (outcome.action != Outcome::Action::Respond) continue;
        if (handled.release && station_.scan_loop()) co_await station_.scan_loop()->until(*handled.release);
        co_await send_datagrams(socket_, sender, outcome.response, handled.delivery, ec);
        if (ec) spdlog::debug("{} send failed: {}", peer.text(), ec.message());
    }
}

void UdpListener::restart_session() {
    session_ = station_.new_session(config_);
}

void UdpListener::push_targets(std::vector<station::PushTarget>& targets) {
    for (const auto& entry : peers_) {
        const auto& to = entry.first;
        const protocol::Peer peer{protocol::Transport::Udp, to.address().to_string(), to.port(), port_};
        targets.push_back({session_.id, peer, entry.second.kind, entry.second.codec, [this, to](std::vector<std::uint8_t> bytes) {
                               auto data = std::make_shared<std::vector<std::uint8_t>>(std::move(bytes));
                               socket_.async_send_to(asio::buffer(*data), to, [data](const boost::system::error_code&, std::size_t) {});
                           }});
    }
}

void UdpListener::stop() {
    boost::system::error_code ec;
    socket_.close(ec);
}

}  // namespace slmp::server
