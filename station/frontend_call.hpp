// One request to a protocol face (frontends/face.hpp),
// wrapped the way Station::handle() wraps an SLMP frame: the scenario faults
// see it once its command is known (gate()), and when the front end has
// answered, finish() records it (--record) and reports it to the station's
// Activity (metrics, event stream, call monitor). The transports make one
// per request they hand to the front end.
#pragma once

#include <chrono>
#include <cstdint>
#include <span>
#include <string>
#include <string_view>

#include "frontends/gate.hpp"
#include "protocol/peer.hpp"
#include "scenarios/runner.hpp"

namespace slmp::station {

class Station;

class FrontEndCall {
public:
    // `connection`: the TCP connection id, or the UDP port's session id.
    FrontEndCall(Station& station, scenarios::Protocol protocol, std::uint64_t connection, const protocol::Peer& peer);

    // For the front end: asks the scenarios' faults once the command is known.
    frontends::Gate gate();

    // What the transport does with the answer.
    struct Delivery {
        std::chrono::microseconds delay{0};   // wait before sending it
        bool close = false, reset = false;    // close the connection (FIN / RST) instead of answering
    };
    // After the front end: `request` the bytes it took, `command` its text
    // (empty: none could be read), `known` whether the front end's table has it,
    // `name` the table's name, `code` the response code / RSLT sent (empty: none).
    Delivery finish(std::span<const std::uint8_t> request, std::string_view command, bool known, std::string_view name,
                    std::string_view code, std::span<const std::uint8_t> response);

private:
    Station& station_;
    scenarios::Protocol protocol_;
    std::uint64_t connection_;
    const protocol::Peer& peer_;
    std::chrono::steady_clock::time_point started_;
    scenarios::Incoming incoming_;
    scenarios::Plan plan_;
};

}  // namespace slmp::station
