// slmp nodes (0E30 Node Search) and slmp status (0E44 Status Read, 0E53 Status
// Read2): the node commands of the Japanese SLMP manual, which an
// SLMP-compatible device's port serves (docs/nodes.md). The request goes to
// --host/--port like every other command; `nodes --broadcast` sends it as a
// broadcast to --host (e.g. 127.255.255.255) and lists every node that
// answers within --timeout (the manual's client collects for 2 s: each node
// waits 0-1500 ms at random before it answers).
#include <arpa/inet.h>
#include <netinet/in.h>
#include <poll.h>
#include <sys/socket.h>
#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <chrono>
#include <cstring>

#include "protocol/client_nodes.hpp"
#include "tools/slmp/arguments.hpp"
#include "tools/slmp/commands.hpp"
#include "tools/slmp/errors.hpp"

namespace slmp::cli {

namespace client = protocol::client;

namespace {

const std::vector<std::string> kNodeColumns{"ip", "mac", "station", "model code", "vendor", "version", "status", "port"};

// One node's answer: its JSON object and its table row.
std::pair<Json, std::vector<std::string>> node_row(const client::NodeInfo& node) {
    const auto ip = client::ip_text(node.ip), mac = client::mac_text(node.mac);
    const auto model = word_hex(node.model_code, 8), vendor = word_hex(node.vendor_code, 4);
    const auto version = word_hex(node.version, 4), status = word_hex(node.status, 4);
    Json json{{"ip", ip},          {"mac", mac},       {"station", node.host_name},
              {"model_code", model}, {"vendor_code", vendor}, {"version", version},
              {"status", status},  {"port", node.port}, {"subnet_mask", client::ip_text(node.subnet_mask)},
              {"gateway", client::ip_text(node.gateway)}, {"partner", client::ip_text(node.partner_ip)},
              {"partner_port", node.partner_port}};
    return {json, {ip, mac, node.host_name, model, vendor, version, status, std::to_string(node.port)}};
}

// A UDP socket that may send to a broadcast address, closed on every path.
struct BroadcastSocket {
    int fd = ::socket(AF_INET, SOCK_DGRAM, 0);
    ~BroadcastSocket() {
        if (fd >= 0) ::close(fd);
    }
};

// Node search as the manual sends it: one broadcast, then every answer that
// comes within `collect` (a node answers after its random delay).
std::vector<client::NodeInfo> search_by_broadcast(const Options& options, std::span<const std::uint8_t> request) {
    sockaddr_in to{};
    to.sin_family = AF_INET;
    to.sin_port = htons(options.target.port);
    if (::inet_pton(AF_INET, options.target.host.c_str(), &to.sin_addr) != 1)
        throw UsageError("nodes --broadcast needs --host as an IPv4 broadcast address, e.g. 127.255.255.255");
    BroadcastSocket socket;
    const int on = 1;
    if (socket.fd < 0 || ::setsockopt(socket.fd, SOL_SOCKET, SO_BROADCAST, &on, sizeof on) != 0)
        throw ConnectionError(std::string("cannot open a broadcast socket: ") + std::strerror(errno));
    if (::sendto(socket.fd, request.data(), request.size(), 0, reinterpret_cast<const sockaddr*>(&to), sizeof to) < 0)
        throw ConnectionError("cannot send the node search to " + options.target.host + ":" +
                              std::to_string(options.target.port) + ": " + std::strerror(errno));
    std::vector<client::NodeInfo> nodes;
    const auto deadline = std::chrono::steady_clock::now() + options.target.timeout;
    std::vector<std::uint8_t> buffer(4096);
    for (;;) {
        const auto left = std::chrono::duration_cast<std::chrono::milliseconds>(deadline - std::chrono::steady_clock::now());
        if (left.count() <= 0) break;
        pollfd ready{socket.fd, POLLIN, 0};
        if (::poll(&ready, 1, static_cast<int>(left.count())) <= 0) continue;
        const auto n = ::recv(socket.fd, buffer.data(), buffer.size(), 0);
        if (n <= 0) continue;
        auto response = client::parse_response(std::span<const std::uint8_t>(buffer.data(), static_cast<std::size_t>(n)));
        if (!response || response->end_code != 0) continue;   // a port that refuses 0E30 is no node
        if (auto node = client::decode_node_search(*response)) nodes.push_back(std::move(*node));
    }
    // In a steady order (the answers come in the order of their random delays).
    std::sort(nodes.begin(), nodes.end(), [](const client::NodeInfo& a, const client::NodeInfo& b) {
        return std::tie(a.host_name, a.port) < std::tie(b.host_name, b.port);
    });
    return nodes;
}

}  // namespace

// The client's own MAC and IP are not known to a socket user: zeros, which the
// server only echoes back (JA §3.12).
void run_nodes(Invocation& in) {
    if (!in.options.args.empty()) throw UsageError("nodes takes no arguments");
    const auto request = client::node_search(in.client.frame(), {}, {});
    if (in.options.broadcast) {
        const auto nodes = search_by_broadcast(in.options, request);
        if (nodes.empty()) throw ConnectionError("no node answered the node search within --timeout");
        Json list = Json::array();
        Table table{kNodeColumns, {}};
        for (const auto& node : nodes) {
            auto [json, row] = node_row(node);
            list.push_back(std::move(json));
            table.rows.push_back(std::move(row));
        }
        in.output.result(list, table);
        return;
    }
    auto response = in.client.exchange(request);
    auto node = client::decode_node_search(response);
    if (!node) throw ConnectionError("the Node Search answer does not have the fields of JA §3.12");
    auto [json, row] = node_row(*node);
    in.output.result(json, Table{kNodeColumns, {row}});
}

// Status Read2 answers only the node's partner (JA §4.3.1.3): silence is shown, not an error.
void run_status(Invocation& in) {
    if (!in.options.args.empty()) throw UsageError("status takes no arguments");
    auto response = in.client.exchange(client::status_read(in.client.frame()));
    auto code = client::decode_status_read(response);
    if (!code) throw ConnectionError("the Status Read answer is not 0001 and a status code");
    auto second = in.client.exchange_allow_silence(client::status_read2(in.client.frame()));
    std::optional<client::NodeStatus> detail;
    if (second) {
        detail = client::decode_status_read2(*second);
        if (!detail) throw ConnectionError("the Status Read2 answer does not have the fields of JA §3.14");
    }
    const auto status = word_hex(*code, 4);
    const std::string state = *code == 0 ? "normal" : "error";
    const auto ip = detail ? client::ip_text(detail->ip) : "-";
    const auto partner = detail ? client::ip_text(detail->partner_ip) : "-";
    Json json{{"status", status}, {"state", state}};
    if (detail) {
        json["ip"] = ip;
        json["partner"] = partner;
        json["operating_state"] = word_hex(detail->state, 2);
    }
    in.output.result(json, Table{{"status", "state", "ip", "partner"}, {{status, state, ip, partner}}});
}

}  // namespace slmp::cli
