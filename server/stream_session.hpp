// What a TcpListener needs of a connection it accepted, whatever protocol the
// connection speaks: SLMP (tcp_session.hpp) or a front end such as the host
// link (hostlink_session.hpp). The listener keeps its connection limits, the
// per-address cap and its power-cut refusals the same for all of them.
#pragma once

#include <cstddef>
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

// Builds the session for an accepted socket. `on_closed` must be called once
// when the session ends; `connections` counts the port's open connections.
using SessionFactory = std::function<std::shared_ptr<StreamSession>(
    boost::asio::ip::tcp::socket socket, std::function<void(StreamSession*)> on_closed,
    std::function<std::size_t()> connections)>;

}  // namespace slmp::server
