// A TCP port. When it serves max_connections clients it closes its listening
// socket, so further clients are refused as by a real iQ-R built-in port
// (real-CPU measurements); it listens again when a client leaves. With a
// per-address cap, a client address already at its cap has a new connection
// accepted and closed at once (a simulator's guard; real ports have none).
#pragma once

#include <cstdint>
#include <memory>
#include <string>
#include <unordered_map>

#include "station/asio.hpp"

#include "config/config.hpp"
#include "frontends/face.hpp"
#include "server/tcp_session.hpp"
#include "station/station.hpp"

namespace slmp::server {

class TcpListener {
public:
    // Serves `unit`'s face: each connection gets the inbox the unit asks for
    // (station/face_inbox.hpp). `shared_loop`: several threads run the home's
    // io_context (server/listeners.hpp).
    TcpListener(const station::Home& home, station::Station& station, frontends::Unit& unit, const config::PortConfig& port,
                const boost::asio::ip::address& bind, bool shared_loop = false);

    std::uint16_t port() const { return endpoint_.port(); }   // the bound port, also when 0 was asked for
    void stop();
    // A scenario's power cut or refusal period: while true the port is closed
    // (clients are refused); afterwards it listens again (station/scenario_station.hpp).
    void set_refusing(bool refusing);
    // Ondemand: each open connection (station/transports.hpp).
    void push_targets(std::vector<station::PushTarget>& targets);

private:
    void listen();
    void reopen();   // listen() again after the port was closed; logs instead of throwing
    boost::asio::awaitable<void> accept_loop();
    void session_closed(TcpSession* session);
    bool over_address_cap(const station::StrandSocket& socket) const;

    station::Home home_;
    station::Station& station_;
    config::PortConfig config_;
    boost::asio::ip::tcp::endpoint endpoint_;
    boost::asio::ip::tcp::acceptor acceptor_;
    InboxMaker make_inbox_;
    std::string face_;   // its log name (empty: none, SLMP)
    std::unordered_map<TcpSession*, std::shared_ptr<TcpSession>> sessions_;
    std::unordered_map<std::string, unsigned> sessions_per_address_;   // only with a per-address cap
    bool own_strands_ = false;   // a timed unit's sessions in instant mode read and write on strands of their own
    bool stopping_ = false;
    bool refusing_ = false;
};

}  // namespace slmp::server
