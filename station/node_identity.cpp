#include "station/node_identity.hpp"

#include <arpa/inet.h>

namespace slmp::station {
namespace {

std::uint32_t fnv1a(std::string_view text) {
    std::uint32_t hash = 2166136261u;
    for (unsigned char c : text) {
        hash ^= c;
        hash *= 16777619u;
    }
    return hash;
}

}  // namespace

devicemodel::NodeIdentity node_identity(const config::ServerConfig& config, const devicemodel::CpuProfile& profile) {
    devicemodel::NodeIdentity node;
    node.host_name = config.name.empty() ? "slmp-sim" : config.name;
    const auto first_port = config.ports.empty() ? 0u : unsigned{config.ports.front().port};
    const auto hash = fnv1a(node.host_name + ":" + std::to_string(first_port));
    node.mac = {0x02, 0x00, static_cast<std::uint8_t>(hash >> 24), static_cast<std::uint8_t>(hash >> 16),
                static_cast<std::uint8_t>(hash >> 8), static_cast<std::uint8_t>(hash)};
    in_addr v4{};
    if (inet_pton(AF_INET, config.bind.c_str(), &v4) == 1 && v4.s_addr != 0) {
        const auto host = ntohl(v4.s_addr);
        node.ip = {static_cast<std::uint8_t>(host >> 24), static_cast<std::uint8_t>(host >> 16),
                   static_cast<std::uint8_t>(host >> 8), static_cast<std::uint8_t>(host)};
    } else {
        node.ip = {127, 0, 0, 1};
    }
    node.model_code = profile.model_code;
    return node;
}

}  // namespace slmp::station
