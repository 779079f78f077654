#include "server/udp_listener.hpp"

#include <spdlog/spdlog.h>

#include "server/tcp_session.hpp"   // to_policy
#include "server/udp_delivery.hpp"
#include "station/datagram_inbox.hpp"
#include "station/log_exception.hpp"

namespace slmp::server {

namespace asio = boost::asio;
using asio::ip::udp;
using protocol::Outcome;

constexpr std::size_t kMaxPushPeers = 256;   // UDP peers an Ondemand push reaches (docs/timing.md)
// Datagrams already waiting that one wake-up serves before the port lets the
// station's other work (the scan, the API, its TCP connections) run.
constexpr int kDatagramsPerTurn = 16;

UdpListener::UdpListener(const station::Home& home, station::Station& station, frontends::Unit& unit,
                         const config::PortConfig& port, const asio::ip::address& bind)
    : station_(station),
      inbox_(station::datagram_inbox(station, unit, port, to_policy(port.data_code))),
      socket_(home, udp::endpoint(bind, port.port)) {
    port_ = socket_.local_endpoint().port();
    socket_.non_blocking(true);   // a waiting datagram is read, and an answer sent, without an asynchronous operation
    const auto log_name = unit.face().log_name();
    const auto name = (log_name.empty() ? std::string() : std::string(log_name) + " ") + "UDP port ";
    asio::co_spawn(home, serve(), station::log_exception(name + std::to_string(port_) + ": receive loop failed"));
}

// Read a datagram, hand it to the station's inbox, write its answer: at once,
// or when the inbox has it (held on the clock, routed) while the port reads on.
station::StrandTask<> UdpListener::serve() {
    std::array<std::uint8_t, 65536> datagram;
    udp::endpoint sender;
    int turn = 0;   // datagrams served since the last asynchronous receive
    while (socket_.is_open()) {
        boost::system::error_code ec;
        std::size_t n = 0;
        const bool turn_over = turn >= kDatagramsPerTurn;
        if (!turn_over) n = socket_.receive_from(asio::buffer(datagram), sender, 0, ec);
        if (turn_over || ec == asio::error::would_block || ec == asio::error::try_again) {
            turn = 0;
            ec = {};
            n = co_await socket_.async_receive_from(asio::buffer(datagram), sender,
                                                    asio::redirect_error(station::use_strand, ec));
        }
        ++turn;
        if (ec) {
            if (ec == asio::error::operation_aborted || !socket_.is_open()) co_return;
            station_.log().debug("UDP port {}: receive failed: {}", port_, ec.message());
            continue;
        }
        auto input = std::span<const std::uint8_t>(datagram.data(), n);
        const auto peer = peer_of(sender);
        auto taken = inbox_->hand_over(input, peer);
        if (taken.later) {
            asio::co_spawn(socket_.get_executor(),
                           answer_later(std::move(*taken.later), std::vector<std::uint8_t>(input.begin(), input.end()), sender),
                           station::log_exception("UDP port " + std::to_string(port_) + ": a datagram served later failed"));
            continue;
        }
        if (auto later = answer_now(input, sender, peer, taken.now)) co_await send_later(sender, std::move(*later));
    }
}

station::StrandTask<> UdpListener::answer_later(station::StrandTask<std::optional<station::Handled>> later,
                                                std::vector<std::uint8_t> datagram, udp::endpoint sender) {
    auto handled = co_await std::move(later);
    if (!handled || !socket_.is_open()) co_return;
    if (auto rest = answer_now(datagram, sender, peer_of(sender), *handled)) co_await send_later(sender, std::move(*rest));
}

protocol::Peer UdpListener::peer_of(const udp::endpoint& sender) const {
    protocol::Peer peer{protocol::Transport::Udp, sender.address().to_string(), sender.port(), port_};
    if (sender.address().is_v4()) peer.ipv4 = sender.address().to_v4().to_bytes();
    return peer;
}

std::optional<station::Handled> UdpListener::answer_now(std::span<const std::uint8_t> input, const udp::endpoint& sender,
                                                        const protocol::Peer& peer, station::Handled& handled) {
    const auto n = input.size();
    auto& outcome = handled.outcome;
    if (outcome.action == Outcome::Action::NeedMore) {
        station_.log().debug("{} datagram of {} byte(s) holds no whole request frame (check the request data length); "
                             "not answered", peer.text(), n);
        return std::nullopt;
    }
    if (outcome.consumed < n)
        station_.log().debug("{} {} byte(s) after the request frame ignored", peer.text(), n - outcome.consumed);
    // Remember who spoke, for Ondemand pushes; bounded, so a flood of
    // source ports cannot grow it without end (later peers are not pushed to).
    if (outcome.command != 0 && (peers_.size() < kMaxPushPeers || peers_.count(sender))) {
        peers_[sender] = station::request_shape(input);
    }
    if (outcome.action == Outcome::Action::Restart) station_.restart();
    if (outcome.action != Outcome::Action::Respond) return std::nullopt;
    if (!handled.delivery.plain()) return std::move(handled);
    boost::system::error_code ec;
    socket_.send_to(asio::buffer(outcome.response), sender, 0, ec);
    if (ec == asio::error::would_block || ec == asio::error::try_again) return std::move(handled);   // the send buffer is full
    if (ec) station_.log().debug("{} send failed: {}", peer.text(), ec.message());
    return std::nullopt;
}

station::StrandTask<> UdpListener::send_later(udp::endpoint sender, station::Handled handled) {
    boost::system::error_code ec;
    co_await send_datagrams(socket_, sender, handled.outcome.response, handled.delivery, ec);
    if (ec) station_.log().debug("{} send failed: {}", peer_of(sender).text(), ec.message());
}

void UdpListener::restart_session() { inbox_->restart(); }

void UdpListener::push_targets(std::vector<station::PushTarget>& targets) {
    for (const auto& entry : peers_) {
        const auto& to = entry.first;
        const auto peer = peer_of(to);
        targets.push_back({inbox_->session_id(), peer, entry.second.kind, entry.second.codec, [this, to](std::vector<std::uint8_t> bytes) {
                               auto data = std::make_shared<std::vector<std::uint8_t>>(std::move(bytes));
                               socket_.async_send_to(asio::buffer(*data), to, [data](const boost::system::error_code&, std::size_t) {});
                           }});
    }
}

void UdpListener::stop() {
    inbox_->close();
    boost::system::error_code ec;
    socket_.close(ec);
}

}  // namespace slmp::server
