// Client-side builders and decoders for the node commands of the Japanese SLMP
// manual (JA §3.12-3.14): Node Search 0E30, Status Read 0E44 and Status Read2
// 0E53 — what `slmp nodes` and `slmp status` send. Like client.hpp, every
// request goes through build_request() and a FieldWriter; the layouts are the
// server's (protocol/commands/node.cpp, docs/nodes.md).
#pragma once

#include <array>
#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "protocol/client.hpp"

namespace slmp::protocol::client {

using Octets = std::vector<std::uint8_t>;   // an address, most significant octet first

// 0E30: the client's MAC (6 octets) and IPv4 address (4 octets).
std::vector<std::uint8_t> node_search(const FrameOptions& options, const std::array<std::uint8_t, 6>& client_mac,
                                      const std::array<std::uint8_t, 4>& client_ip);

struct NodeInfo {
    Octets client_mac, client_ip;
    Octets mac, ip, subnet_mask, gateway;
    std::string host_name;
    std::uint16_t vendor_code = 0;
    std::uint32_t model_code = 0;
    std::uint16_t version = 0;
    Octets partner_ip;
    std::uint16_t partner_port = 0;
    std::uint16_t status = 0;
    std::uint16_t port = 0;
    std::uint8_t protocol = 0;
};
std::optional<NodeInfo> decode_node_search(const Response& response);

std::vector<std::uint8_t> status_read(const FrameOptions& options);    // 0E44
std::vector<std::uint8_t> status_read2(const FrameOptions& options);   // 0E53

// 0E44's status code (0000 normal).
std::optional<std::uint16_t> decode_status_read(const Response& response);

struct NodeStatus {
    Octets ip, partner_ip;
    std::uint8_t state = 0;   // 00 normal, 01 error
    std::uint16_t status = 0;
};
std::optional<NodeStatus> decode_status_read2(const Response& response);

// "192.168.0.1", "00:26:92:12:34:56"
std::string ip_text(const Octets& ip);
std::string mac_text(const Octets& mac);

}  // namespace slmp::protocol::client
