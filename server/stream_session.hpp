// What a TcpListener needs of a connection it accepted, whatever protocol the
// connection speaks: SLMP (tcp_session.hpp) or a front end such as the host
// link (frontend_session.hpp). The listener keeps its connection limits, the
// per-address cap and its power-cut refusals the same for all of them.
#pragma once

#include <chrono>
#include <cstddef>
#include <optional>
#include <functional>
#include <memory>

#include "station/asio.hpp"

#include "protocol/peer.hpp"

namespace slmp::server {

class StreamSession {
public:
    virtual ~StreamSession() = default;
    virtual void start() = 0;
    virtual void close() = 0;   // from the listener at shutdown
    virtual const protocol::Peer& peer() const = 0;
};

// The client of an accepted connection and the port it reached ("?" when the
// socket no longer knows); also turns Nagle off, as every session answers at once.
inline protocol::Peer accepted_peer(station::StrandSocket& socket) {
    boost::system::error_code ec;
    protocol::Peer peer;
    peer.transport = protocol::Transport::Tcp;
    if (auto remote = socket.remote_endpoint(ec); ec) {
        peer.address = "?";
    } else {
        peer.address = remote.address().to_string();
        peer.port = remote.port();
    }
    peer.local_port = socket.local_endpoint(ec).port();
    socket.set_option(boost::asio::ip::tcp::no_delay(true), ec);
    return peer;
}

// When a connection's watchdog fires: `idle` after its last activity, or
// `partial` after the first byte of a request still not whole, whichever is
// first (a zero duration is off). `partial` in the answer says which one.
struct Deadline {
    std::chrono::steady_clock::time_point at = std::chrono::steady_clock::time_point::max();
    bool partial = false;
};
inline Deadline next_deadline(std::chrono::steady_clock::time_point last_activity, std::chrono::milliseconds idle,
                              std::optional<std::chrono::steady_clock::time_point> partial_since,
                              std::chrono::milliseconds partial) {
    Deadline d;
    if (idle.count() > 0) d.at = last_activity + idle;
    if (partial.count() > 0 && partial_since && *partial_since + partial < d.at) d = {*partial_since + partial, true};
    return d;
}

// Builds the session for an accepted socket. `on_closed` must be called once
// when the session ends; `connections` counts the port's open connections.
using SessionFactory = std::function<std::shared_ptr<StreamSession>(
    station::StrandSocket socket, std::function<void(StreamSession*)> on_closed,
    std::function<std::size_t()> connections)>;

}  // namespace slmp::server
