// Who owns the file locks a request takes (1827-182A, docs/files.md): a TCP
// connection (its session id), or one UDP peer — address and port — so two
// UDP clients of the same port cannot close or write each other's files.
// A UDP owner is computed from the peer, not allocated, so a flood of source
// ports costs no memory; the high bit keeps it apart from session ids.
#pragma once

#include <arpa/inet.h>

#include <array>
#include <cstdint>
#include <functional>
#include <optional>
#include <string>

#include "protocol/peer.hpp"

namespace slmp::protocol {

constexpr std::uint64_t kUdpOwnerBit = std::uint64_t{1} << 63;
constexpr std::uint64_t kUdpHashedBit = std::uint64_t{1} << 62;   // an IPv6 peer: hashed, not decodable

// The sender's IPv4 address as octets (Status Read2 0E53 compares it with
// the node's partner; a UDP peer's lock owner is made of it); 0.0.0.0 when the
// peer is not IPv4. Taken once where the Peer was made; parsed from the text
// for a Peer made without it (a test's).
inline std::array<std::uint8_t, 4> peer_ipv4(const Peer& peer) {
    if (peer.ipv4 != std::array<std::uint8_t, 4>{}) return peer.ipv4;
    in_addr v4{};
    if (inet_pton(AF_INET, peer.address.c_str(), &v4) != 1) return {};
    const auto host = ntohl(v4.s_addr);
    return {static_cast<std::uint8_t>(host >> 24), static_cast<std::uint8_t>(host >> 16),
            static_cast<std::uint8_t>(host >> 8), static_cast<std::uint8_t>(host)};
}

inline std::uint64_t lock_owner(const Peer& peer, std::uint64_t session_id) {
    if (peer.transport == Transport::Tcp) return session_id;
    if (const auto v4 = peer_ipv4(peer); v4 != std::array<std::uint8_t, 4>{})
        return kUdpOwnerBit | std::uint64_t{v4[0]} << 40 | std::uint64_t{v4[1]} << 32 | std::uint64_t{v4[2]} << 24 |
               std::uint64_t{v4[3]} << 16 | peer.port;
    auto hashed = std::hash<std::string>{}(peer.endpoint());
    return kUdpOwnerBit | kUdpHashedBit | (hashed & (kUdpHashedBit - 1));
}

// "udp:127.0.0.1:50312" for an IPv4 UDP owner; nullopt for a connection's id.
inline std::optional<std::string> udp_owner_text(std::uint64_t owner) {
    if (!(owner & kUdpOwnerBit)) return std::nullopt;
    if (owner & kUdpHashedBit) return "udp:ipv6-peer";
    in_addr v4{};
    v4.s_addr = htonl(static_cast<std::uint32_t>(owner >> 16));
    char text[INET_ADDRSTRLEN] = {};
    inet_ntop(AF_INET, &v4, text, sizeof text);
    return "udp:" + std::string(text) + ":" + std::to_string(owner & 0xFFFF);
}

}  // namespace slmp::protocol
