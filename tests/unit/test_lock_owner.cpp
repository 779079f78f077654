// Who owns a file lock (protocol/lock_owner.hpp, docs/files.md): a TCP
// connection by its session id, a UDP peer by its address and port — the same
// owner whether the Peer's IPv4 octets were taken from the socket or parsed
// from its text — and the owner's text names the peer again.
#include <catch2/catch.hpp>

#include "protocol/lock_owner.hpp"

using namespace slmp::protocol;

TEST_CASE("lock owner: a UDP peer is its address and port, from the socket's octets or the text alike", "[files]") {
    Peer from_text{Transport::Udp, "192.0.2.7", 50312, 5000};
    Peer from_socket = from_text;
    from_socket.ipv4 = {192, 0, 2, 7};
    CHECK(lock_owner(from_text, 3) == lock_owner(from_socket, 3));
    CHECK(udp_owner_text(lock_owner(from_socket, 3)) == "udp:192.0.2.7:50312");
    CHECK(peer_ipv4(from_text) == std::array<std::uint8_t, 4>{192, 0, 2, 7});

    Peer other_port = from_socket;
    other_port.port = 50313;
    CHECK(lock_owner(other_port, 3) != lock_owner(from_socket, 3));

    Peer tcp{Transport::Tcp, "192.0.2.7", 50312, 5000};
    CHECK(lock_owner(tcp, 3) == 3);
    CHECK_FALSE(udp_owner_text(3).has_value());

    Peer v6{Transport::Udp, "::1", 50312, 5000};
    CHECK(peer_ipv4(v6) == std::array<std::uint8_t, 4>{});
    CHECK(udp_owner_text(lock_owner(v6, 3)) == "udp:ipv6-peer");
}
