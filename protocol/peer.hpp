// Who sent a request: the transport and the client's address, as the
// listener saw them. Created once per connection (TCP) or datagram (UDP) and
// passed down as data; nothing splits a text form of it again.
#pragma once

#include <array>
#include <cstdint>
#include <string>
#include <string_view>

namespace slmp::protocol {

enum class Transport : std::uint8_t { Tcp, Udp };

constexpr std::string_view to_string(Transport transport) { return transport == Transport::Tcp ? "tcp" : "udp"; }

struct Peer {
    Transport transport = Transport::Tcp;
    std::string address;            // the client's IP address, "127.0.0.1"
    std::uint16_t port = 0;         // the client's port
    std::uint16_t local_port = 0;   // the simulator's port it reached
    // The client's IPv4 address as octets, taken from the socket's endpoint where
    // the Peer is made, so a request does not parse `address` again (the file
    // locks' UDP owner, the node commands' sender); 0.0.0.0 when not IPv4 or not known.
    std::array<std::uint8_t, 4> ipv4{};

    // "tcp:127.0.0.1:50312", for log lines.
    std::string text() const { return std::string(to_string(transport)) + ":" + address + ":" + std::to_string(port); }
    // "127.0.0.1:50312", for recordings.
    std::string endpoint() const { return address + ":" + std::to_string(port); }
};

}  // namespace slmp::protocol
