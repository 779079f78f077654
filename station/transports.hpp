// What a station asks of the transports that serve it. The station knows no
// sockets (server/ implements this), yet a scenario's power cut closes the TCP
// ports and a restarted CPU gives its UDP clients fresh sessions.
#pragma once

namespace slmp::station {

class Transports {
public:
    // While true the TCP ports are closed, so new clients are refused; afterwards
    // they listen again.
    virtual void refuse_connections(bool refusing) = 0;
    // Every UDP port's protocol session starts afresh (locked again when the CPU
    // has a remote password).
    virtual void restart_sessions() = 0;

protected:
    ~Transports() = default;
};

}  // namespace slmp::station
