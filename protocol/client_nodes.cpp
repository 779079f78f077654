#include "protocol/client_nodes.hpp"

#include "devicemodel/hex.hpp"

namespace slmp::protocol::client {
namespace {

Octets sized_address(FieldReader& r, std::string_view size_name, std::string_view name) {
    const auto size = r.u8(size_name);
    return r.octets(size, name);
}

}  // namespace

std::vector<std::uint8_t> node_search(const FrameOptions& options, const std::array<std::uint8_t, 6>& client_mac,
                                      const std::array<std::uint8_t, 4>& client_ip) {
    return build_request(options, 0x0E30, 0x0000, [&](FieldWriter& w) {
        w.octets(client_mac);
        w.u8(static_cast<std::uint8_t>(client_ip.size()));
        w.octets(client_ip);
    });
}

std::optional<NodeInfo> decode_node_search(const Response& response) {
    auto r = response.reader();
    NodeInfo node;
    node.client_mac = r.octets(6, "client MAC address");
    node.client_ip = sized_address(r, "client IP address size", "client IP address");
    node.mac = r.octets(6, "server MAC address");
    const auto size = r.u8("server IP address size");
    node.ip = r.octets(size, "server IP address");
    node.subnet_mask = r.octets(size, "server subnet mask");
    node.gateway = r.octets(size, "server default gateway");
    const auto name_size = r.u8("server host name size");
    auto name = r.raw(name_size, "server host name");
    node.host_name.assign(name.begin(), name.end());
    node.vendor_code = r.u16("vendor code");
    node.model_code = r.u32("model code");
    node.version = r.u16("device version");
    node.partner_ip = sized_address(r, "partner IP address size", "partner IP address");
    node.partner_port = r.u16("partner port number");
    node.status = r.u16("server status");
    node.port = r.u16("server port number");
    node.protocol = r.u8("server protocol setting");
    if (!r.finish()) return std::nullopt;
    return node;
}

std::vector<std::uint8_t> status_read(const FrameOptions& options) { return build_request(options, 0x0E44, 0x0000); }
std::vector<std::uint8_t> status_read2(const FrameOptions& options) { return build_request(options, 0x0E53, 0x0000); }

std::optional<std::uint16_t> decode_status_read(const Response& response) {
    auto r = response.reader();
    const auto count = r.u16("number of status codes");
    const auto code = r.u16("status code");
    if (!r.finish() || count != 1) return std::nullopt;
    return code;
}

std::optional<NodeStatus> decode_status_read2(const Response& response) {
    auto r = response.reader();
    NodeStatus status;
    const auto size = r.u8("IP address size");
    status.ip = r.octets(size, "server IP address");
    status.partner_ip = r.octets(size, "partner IP address");
    status.state = r.u8("operating state");
    status.status = r.u16("status code");
    if (!r.finish()) return std::nullopt;
    return status;
}

std::string ip_text(const Octets& ip) {
    std::string text;
    for (auto octet : ip) text += (text.empty() ? "" : ".") + std::to_string(octet);
    return text;
}

std::string mac_text(const Octets& mac) {
    std::string text;
    for (auto octet : mac) text += (text.empty() ? "" : ":") + devicemodel::hex_text(octet, 2);
    return text;
}

}  // namespace slmp::protocol::client
