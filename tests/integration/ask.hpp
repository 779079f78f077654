// One request, its answer: the whole response frame a TCP client reads next,
// or the datagram a UDP port sends back; on nothing, a text saying why, so
// that a comparison of answers shows it.
#pragma once

#include <catch2/catch.hpp>

#include <string>

#include "frames.hpp"
#include "sockets.hpp"

namespace slmp::test {

inline Bytes ask(TcpClient& c, const Bytes& request) {
    REQUIRE(c.send(request));
    Bytes frame;
    std::string why;
    if (!c.response(&frame, kReplyTimeout, &why)) return text("<no response: " + why + ">");
    return frame;
}

inline Bytes ask(UdpClient& c, std::uint16_t port, const Bytes& request) {
    REQUIRE(c.send_to(port, request));
    auto answer = c.receive();
    return answer ? *answer : text("<no response>");
}

}  // namespace slmp::test
