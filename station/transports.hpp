// What a station asks of the transports that serve it. The station knows no
// sockets (server/ implements this), yet a scenario's power cut closes the TCP
// ports and a restarted CPU gives its UDP clients fresh sessions.
#pragma once

#include <cstdint>
#include <functional>
#include <vector>

#include "protocol/frame.hpp"
#include "protocol/peer.hpp"

namespace slmp::station {

// A client an Ondemand push can reach (docs/timing.md): an open TCP
// connection, or a UDP peer that has sent the port a request. `kind` and
// `codec` are those of its last request (the push takes that shape).
struct PushTarget {
    std::uint64_t session = 0;                  // TCP connection id, or the UDP port's session id
    protocol::Peer peer;
    protocol::FrameKind kind = protocol::FrameKind::E3;
    protocol::Codec codec = protocol::Codec::Binary;
    std::function<void(std::vector<std::uint8_t>)> send;   // queues the bytes on the connection / sends the datagram
};

class Transports {
public:
    // While true the TCP ports are closed, so new clients are refused; afterwards
    // they listen again.
    virtual void refuse_connections(bool refusing) = 0;
    // Every UDP port's protocol session starts afresh (locked again when the CPU
    // has a remote password).
    virtual void restart_sessions() = 0;
    // Every client an Ondemand push can reach now.
    virtual std::vector<PushTarget> push_targets() { return {}; }

protected:
    ~Transports() = default;
};

}  // namespace slmp::station
