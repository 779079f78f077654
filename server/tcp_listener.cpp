#include "server/tcp_listener.hpp"

#include <spdlog/spdlog.h>

#include "station/face_inbox.hpp"
#include "station/log_exception.hpp"

namespace slmp::server {

namespace asio = boost::asio;
using asio::ip::tcp;

TcpListener::TcpListener(const station::Home& home, station::Station& station, frontends::Unit& unit,
                         const config::PortConfig& port, const asio::ip::address& bind, bool shared_loop)
    : home_(home),
      station_(station),
      config_(port),
      endpoint_(bind, port.port),
      acceptor_(home),
      face_(unit.face().log_name()) {
    if (!config_.max_connections) config_.max_connections = station.engine().port().max_connections;
    // On a loop that several threads run, a timed unit's connection (SLMP) in
    // the instant timing mode reads, frames and writes on a strand of its own,
    // so the threads serve one busy station together: its inbox hops to the
    // station's strand for each read's requests (station/inbox.hpp), which
    // are still served one at a time. On a loop of one thread a strand of its
    // own would only add a hand-over a request. The timing modes' waits and an
    // at-once face's inbox touch the station throughout: those connections
    // stay on the station's strand.
    own_strands_ = shared_loop && unit.timed() && station.serves_at_once();
    make_inbox_ = [this, &unit, policy = to_policy(port.data_code)](const protocol::Peer& peer, station::Feed* feed) {
        return station::connection_inbox(station_, home_, unit, config_, policy, peer, feed, [this] { return sessions_.size(); });
    };
    listen();   // throws boost::system::system_error when the port cannot be had
    endpoint_ = acceptor_.local_endpoint();
}

void TcpListener::listen() {
    acceptor_.open(endpoint_.protocol());
    acceptor_.set_option(tcp::acceptor::reuse_address(true));
    acceptor_.bind(endpoint_);
    acceptor_.listen();
    // The bound port (also when 0 was asked for: endpoint_ learns it only after the first listen()).
    const auto bound = acceptor_.local_endpoint().port();
    asio::co_spawn(home_, accept_loop(), station::log_exception("TCP port " + std::to_string(bound) + ": accept loop failed"));
}

asio::awaitable<void> TcpListener::accept_loop() {
    while (acceptor_.is_open()) {
        boost::system::error_code ec;
        // Accepted into a socket made with its executor: Boost 1.74's converting
        // move of a socket between executor types releases the strand twice
        // (valgrind: a freed strand_impl on the next wait).
        station::StrandSocket socket(own_strands_ ? asio::make_strand(home_.get_inner_executor()) : home_);
        co_await acceptor_.async_accept(socket, asio::redirect_error(asio::use_awaitable, ec));
        if (ec) {
            if (ec == asio::error::operation_aborted || !acceptor_.is_open()) co_return;
            station_.log().warn("TCP port {}: accept failed: {}", port(), ec.message());
            continue;
        }
        if (over_address_cap(socket)) continue;   // the socket closes as it goes out of scope
        auto session = std::make_shared<TcpSession>(std::move(socket), home_, station_, config_,
                                                    [this](TcpSession* s) { session_closed(s); }, make_inbox_, face_);
        sessions_.emplace(session.get(), session);
        if (config_.max_connections_per_address > 0) ++sessions_per_address_[session->peer().address];
        session->start();
        if (sessions_.size() >= *config_.max_connections) {
            station_.log().info("TCP port {}: {} of {} connection(s) in use; refusing new clients until one leaves", port(),
                                sessions_.size(), *config_.max_connections);
            acceptor_.close(ec);
            co_return;
        }
    }
}

bool TcpListener::over_address_cap(const station::StrandSocket& socket) const {
    if (config_.max_connections_per_address == 0) return false;
    boost::system::error_code ec;
    auto remote = socket.remote_endpoint(ec);
    if (ec) return false;   // the client already left; its session will notice
    auto address = remote.address().to_string();
    auto found = sessions_per_address_.find(address);
    if (found == sessions_per_address_.end() || found->second < config_.max_connections_per_address) return false;
    station_.log().warn("TCP port {}: {} already has {} connection(s), the per-address limit; closing its new connection",
                        port(), address, found->second);
    return true;
}

void TcpListener::session_closed(TcpSession* session) {
    if (config_.max_connections_per_address > 0) {
        auto found = sessions_per_address_.find(session->peer().address);
        if (found != sessions_per_address_.end() && --found->second == 0) sessions_per_address_.erase(found);
    }
    sessions_.erase(session);
    if (stopping_ || refusing_ || acceptor_.is_open()) return;
    reopen();
}

void TcpListener::reopen() {
    try {
        listen();
        station_.log().info("TCP port {}: accepting clients again", port());
    } catch (const std::exception& e) {
        station_.log().error("TCP port {}: cannot listen again: {}", port(), e.what());
    }
}

void TcpListener::set_refusing(bool refusing) {
    refusing_ = refusing;
    boost::system::error_code ec;
    if (refusing) {
        acceptor_.close(ec);
        return;
    }
    if (stopping_ || acceptor_.is_open() || sessions_.size() >= *config_.max_connections) return;
    reopen();
}

void TcpListener::stop() {
    stopping_ = true;
    boost::system::error_code ec;
    acceptor_.close(ec);
    // Sessions remove themselves from the map as they finish; copy first.
    auto sessions = sessions_;
    for (auto& [_, session] : sessions) session->close();
}

void TcpListener::push_targets(std::vector<station::PushTarget>& targets) {
    // Only connections whose inbox takes pushes (SLMP's) are targets.
    for (auto& entry : sessions_)
        if (auto target = entry.second->push_target()) targets.push_back(std::move(*target));
}

}  // namespace slmp::server
