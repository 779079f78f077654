// The node commands of the CC-Link Partner Association's SLMP manual (JA
// §3.12-3.14, ch. 4), served by a port whose profile has "node_commands" (an
// SLMP-compatible device; docs/nodes.md). One definition for binary and ASCII:
// MAC and IP addresses are octet values (FieldReader::octets: binary least
// significant octet first, ASCII hex most significant first — the manual's
// 0E30 example shows both), host names raw characters.
//   0E30 Node Search     client MAC, IP size (byte), client IP → the client's
//                        fields echoed, then the server's MAC, IP size, IP,
//                        mask, gateway, host name size (byte) and name, vendor
//                        code (word), model code (dword), version (word),
//                        partner IP size and IP, partner port (word), status
//                        (word), server port (word), protocol (byte)
//   0E31 IP Address Set  client MAC, IP size, IP, server MAC, IP size, IP,
//                        mask, gateway, host name size and name, partner IP
//                        size and IP, partner port, protocol → client MAC
//                        (layout inferred from 0E30's fields; no example)
//   0E32 Device Info Compare  target (word: bit 0 vendor, 1 model, 2 version),
//                        the targeted values → target, result (bits 0-2: 1 =
//                        differs; bits 15-14: version 11 same, 10 own higher,
//                        01 own lower)
//   0E33 Parameter Get   count (word, 1-3), IDs (words) → count, then ID,
//                        size (word), value (size octets) each (inferred widths)
//   0E34 Parameter Set   count, then ID, size, value each → no data
//   0E35/0E36/0E3A Parameter Set Start/End/Cancel: no data either way
//   0E44 Status Read     → 0001 (inferred: the count of status codes), status code
//   0E53 Status Read2    → IP size (byte), server IP, partner IP, operating
//                        state (byte 00 normal / 01 error), status code (word);
//                        only the configured partner is answered (JA §4.3.1.3)
//   0E45 Communication Setting Get  target (word: bit 0 port, bit 1 timeout)
//                        → target, port (word) and/or timeout (dword, ms)
// The parameter write sequence (Start/Set/End/Cancel, CF31, CF30, CEE0, the
// 10 s timeout) is devicemodel::Node's; the CEE0 for every other command
// while it runs is protocol/execute.cpp's.
#include <algorithm>
#include <string>

#include "devicemodel/hex.hpp"
#include "devicemodel/node.hpp"
#include "protocol/commands/handlers.hpp"

namespace slmp::protocol::commands {
namespace {

using devicemodel::Node;

constexpr std::size_t kMacBytes = 6;
constexpr std::uint8_t kIpv4Bytes = 4;
constexpr std::uint8_t kIpv6Bytes = 16;   // "将来拡張用": read, never set
constexpr std::uint16_t kDefaultPort = 0xB0B5;   // 45237, the manual's default (JA §4.2.1.2)
constexpr std::size_t kMaxParameters = 3;
constexpr std::size_t kMaxParameterBytes = 512;

// The node is the station's: CPU No.1, whichever CPU the route selected.
devicemodel::Cpu& station_cpu(CommandContext& ctx) { return ctx.cpus[0] ? *ctx.cpus[0] : ctx.cpu; }
Node& node_of(CommandContext& ctx) { return station_cpu(ctx).node(); }
Node::TimePoint now_of(CommandContext& ctx) { return request_time(ctx.session, station_cpu(ctx)); }

// The status code of Status Read/Read2 and node search: 0000 normal, else the
// CPU's error code (SD0) while one is pending (inferred: "サーバメーカー固有").
std::uint16_t status_code(const devicemodel::Cpu& cpu) {
    const auto& error = cpu.runtime().operating_state().error();
    return error ? std::max<std::uint16_t>(error->code, 1) : 0;
}

EndCode end_code_for(Node::Verdict verdict) {
    switch (verdict) {
        case Node::Verdict::Ok: return EndCode::Ok;
        case Node::Verdict::Busy: return EndCode::Busy;
        case Node::Verdict::NotStarted: return EndCode::ExclusiveStartMissing;
        case Node::Verdict::BadParameter: return EndCode::ParameterIdNotFound;
    }
    return EndCode::Busy;
}

// An address with its size byte before it (IPv4 4, IPv6 16).
struct SizedAddress {
    std::uint8_t size = 0;
    std::vector<std::uint8_t> octets;
};

SizedAddress read_address(FieldReader& in, std::string_view size_name, std::string_view name) {
    SizedAddress address;
    address.size = in.u8(size_name);
    if (!in.ok()) return address;
    address.octets = in.octets(address.size, name);
    return address;
}

bool address_size_known(std::uint8_t size) { return size == kIpv4Bytes || size == kIpv6Bytes; }

void write_ipv4(FieldWriter& out, const devicemodel::Ipv4Address& address) { out.octets(address); }

std::string mac_text(std::span<const std::uint8_t> mac) {
    std::string text;
    for (auto octet : mac) text += (text.empty() ? "" : ":") + devicemodel::hex_text(octet, 2);
    return text;
}

}  // namespace

EndCode node_search(CommandContext& ctx) {
    auto client_mac = ctx.in.octets(kMacBytes, "client MAC address");
    auto client_ip = read_address(ctx.in, "client IP address size", "client IP address");
    if (!ctx.in.finish()) return ctx.in.error();
    if (!address_size_known(client_ip.size)) return EndCode::BadRequestContent;
    const auto& cpu = station_cpu(ctx);
    const auto& node = cpu.node().identity();
    auto& out = ctx.out;
    out.octets(client_mac);
    out.u8(client_ip.size);
    out.octets(client_ip.octets);
    out.octets(node.mac);
    out.u8(kIpv4Bytes);
    write_ipv4(out, node.ip);
    write_ipv4(out, node.subnet_mask);
    write_ipv4(out, node.gateway);
    const auto name = std::string_view(node.host_name).substr(0, 255);
    out.u8(static_cast<std::uint8_t>(name.size()));
    out.raw(std::span(reinterpret_cast<const std::uint8_t*>(name.data()), name.size()));
    out.u16(node.vendor_code);
    out.u32(node.model_code);
    out.u16(node.version);
    out.u8(kIpv4Bytes);
    write_ipv4(out, node.partner_ip);
    out.u16(node.partner_port);
    out.u16(status_code(cpu));
    out.u16(ctx.session.local_port ? ctx.session.local_port : kDefaultPort);
    out.u8(node.protocol);
    ctx.named = "node " + mac_text(node.mac);
    return EndCode::Ok;
}

// JA §4.1.2: the server compares the MAC in the request with its own and sets
// the network information when they match; another device stays silent
// (inferred: the request is a broadcast every device sees). IPv6 (16-octet)
// addresses cannot be set: CF20. The listening address does not change
// (docs/nodes.md): what node search and Status Read2 report does.
EndCode ip_address_set(CommandContext& ctx) {
    auto& in = ctx.in;
    auto client_mac = in.octets(kMacBytes, "client MAC address");
    auto client_ip = read_address(in, "client IP address size", "client IP address");
    auto server_mac = in.octets(kMacBytes, "server MAC address");
    const auto size = in.u8("IP address size to set");
    auto ip = in.octets(size, "IP address to set");
    auto mask = in.octets(size, "subnet mask to set");
    auto gateway = in.octets(size, "default gateway IP address to set");
    const auto name_size = in.u8("host name size to set");
    auto name = in.raw(name_size, "host name to set");
    auto partner = read_address(in, "partner IP address size", "partner IP address");
    const auto partner_port = in.u16("partner port number");
    const auto protocol = in.u8("protocol setting");
    if (!in.finish()) return in.error();
    if (!address_size_known(client_ip.size) || !address_size_known(size) || !address_size_known(partner.size))
        return EndCode::BadRequestContent;
    auto& node = node_of(ctx).identity();
    ctx.named = "node " + mac_text(server_mac);
    if (!std::equal(server_mac.begin(), server_mac.end(), node.mac.begin())) {
        ctx.silent = "IP Address Set names MAC " + mac_text(server_mac) + ", this node is " + mac_text(node.mac);
        return EndCode::Ok;
    }
    if (size != kIpv4Bytes || partner.size != kIpv4Bytes) return EndCode::SettingNotAllowed;
    std::copy(ip.begin(), ip.end(), node.ip.begin());
    std::copy(mask.begin(), mask.end(), node.subnet_mask.begin());
    std::copy(gateway.begin(), gateway.end(), node.gateway.begin());
    node.host_name.assign(name.begin(), name.end());
    std::copy(partner.octets.begin(), partner.octets.end(), node.partner_ip.begin());
    node.partner_port = partner_port;
    node.protocol = protocol;
    ctx.out.octets(client_mac);
    return EndCode::Ok;
}

EndCode device_info_compare(CommandContext& ctx) {
    constexpr std::uint16_t kVendor = 1 << 0, kModel = 1 << 1, kVersion = 1 << 2;
    auto& in = ctx.in;
    const auto target = in.u16("comparison target");
    const auto vendor = (target & kVendor) ? in.u16("vendor code") : 0;
    const auto model = (target & kModel) ? in.u32("model code") : 0;
    const auto version = (target & kVersion) ? in.u16("device version") : 0;
    if (!in.finish()) return in.error();
    if (target == 0 || (target & ~(kVendor | kModel | kVersion))) return EndCode::BadRequestContent;
    const auto& node = node_of(ctx).identity();
    std::uint16_t result = 0;
    if ((target & kVendor) && vendor != node.vendor_code) result |= kVendor;
    if ((target & kModel) && model != node.model_code) result |= kModel;
    if (target & kVersion) {
        if (version != node.version) result |= kVersion;
        result |= node.version == version ? 0xC000 : node.version > version ? 0x8000 : 0x4000;
    }
    ctx.out.u16(target);
    ctx.out.u16(result);
    return EndCode::Ok;
}

EndCode parameter_get(CommandContext& ctx) {
    auto& in = ctx.in;
    const auto count = in.u16("number of parameters");
    if (!in.ok()) return in.error();
    if (count == 0 || count > kMaxParameters) return EndCode::BadRequestContent;
    std::vector<std::uint16_t> ids;
    for (std::size_t i = 0; i < count; ++i) ids.push_back(in.u16("parameter ID"));
    if (!in.finish()) return in.error();
    const auto& node = node_of(ctx);
    for (auto id : ids)
        if (!node.parameter(id)) return EndCode::ParameterIdNotFound;
    ctx.out.u16(count);
    for (auto id : ids) {
        const auto& value = node.parameter(id)->value;
        ctx.out.u16(id);
        ctx.out.u16(static_cast<std::uint16_t>(value.size()));
        ctx.out.octets(value);
    }
    return EndCode::Ok;
}

// JA §4.2.1.8: the sequence decides first (CF31 before Start, CEE0 from
// another client), then the data: a count, size or ID the store does not
// have, or fields that do not decode, are "要求データ不正" — CF30.
EndCode parameter_set(CommandContext& ctx) {
    auto& node = node_of(ctx);
    const auto now = now_of(ctx);
    const auto client = ctx.session.lock_owner();
    if (auto verdict = node.owner_event(client, now); verdict != Node::Verdict::Ok) return end_code_for(verdict);
    auto& in = ctx.in;
    const auto count = in.u16("number of parameters");
    if (!in.ok() || count == 0 || count > kMaxParameters) return EndCode::ParameterIdNotFound;
    std::vector<std::pair<std::uint16_t, std::vector<std::uint8_t>>> values;
    for (std::size_t i = 0; i < count && in.ok(); ++i) {
        const auto id = in.u16("parameter ID");
        const auto size = in.u16("parameter value size");
        if (!in.ok() || size == 0 || size > kMaxParameterBytes) return EndCode::ParameterIdNotFound;
        values.emplace_back(id, in.octets(size, "parameter value"));
    }
    if (!in.finish()) return EndCode::ParameterIdNotFound;
    return end_code_for(node.set(client, values, now));
}

EndCode parameter_set_start(CommandContext& ctx) {
    if (!ctx.in.finish()) return ctx.in.error();
    return end_code_for(node_of(ctx).start(ctx.session.lock_owner(), now_of(ctx)));
}

EndCode parameter_set_end(CommandContext& ctx) {
    if (!ctx.in.finish()) return ctx.in.error();
    return end_code_for(node_of(ctx).end(ctx.session.lock_owner(), now_of(ctx)));
}

EndCode parameter_set_cancel(CommandContext& ctx) {
    if (!ctx.in.finish()) return ctx.in.error();
    return end_code_for(node_of(ctx).cancel(ctx.session.lock_owner(), now_of(ctx)));
}

EndCode status_read(CommandContext& ctx) {
    if (!ctx.in.finish()) return ctx.in.error();
    ctx.out.u16(0x0001);
    ctx.out.u16(status_code(station_cpu(ctx)));
    return EndCode::Ok;
}

// JA §4.3.1.3: sent as a broadcast; a server answers only when the sender is
// its partner. A node without a partner (0.0.0.0) answers everyone (inferred).
EndCode status_read2(CommandContext& ctx) {
    if (!ctx.in.finish()) return ctx.in.error();
    const auto& cpu = station_cpu(ctx);
    const auto& node = cpu.node().identity();
    constexpr devicemodel::Ipv4Address kNone{};
    if (node.partner_ip != kNone && node.partner_ip != ctx.session.peer_ipv4) {
        ctx.silent = "Status Read2 from a sender that is not this node's partner";
        return EndCode::Ok;
    }
    const auto code = status_code(cpu);
    ctx.out.u8(kIpv4Bytes);
    write_ipv4(ctx.out, node.ip);
    write_ipv4(ctx.out, node.partner_ip);
    ctx.out.u8(code ? 0x01 : 0x00);
    ctx.out.u16(code);
    return EndCode::Ok;
}

EndCode communication_setting_get(CommandContext& ctx) {
    constexpr std::uint16_t kPort = 1 << 0, kTimeout = 1 << 1;
    const auto target = ctx.in.u16("acquisition target");
    if (!ctx.in.finish()) return ctx.in.error();
    if (target == 0 || (target & ~(kPort | kTimeout))) return EndCode::BadRequestContent;
    ctx.out.u16(target);
    if (target & kPort) ctx.out.u16(ctx.session.local_port ? ctx.session.local_port : kDefaultPort);
    if (target & kTimeout) ctx.out.u32(node_of(ctx).identity().timeout_ms);
    return EndCode::Ok;
}

}  // namespace slmp::protocol::commands
