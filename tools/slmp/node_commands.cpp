// slmp nodes (0E30 Node Search) and slmp status (0E44 Status Read, 0E53 Status
// Read2): the node commands of the Japanese SLMP manual, which an
// SLMP-compatible device's port serves (docs/nodes.md). The request goes to
// --host/--port like every other command; a broadcast sweep of a subnet is the
// engineering tool's, not this CLI's.
#include "protocol/client_nodes.hpp"
#include "tools/slmp/arguments.hpp"
#include "tools/slmp/commands.hpp"
#include "tools/slmp/errors.hpp"

namespace slmp::cli {

namespace client = protocol::client;

// The client's own MAC and IP are not known to a socket user: zeros, which the
// server only echoes back (JA §3.12).
void run_nodes(Invocation& in) {
    if (!in.options.args.empty()) throw UsageError("nodes takes no arguments");
    auto response = in.client.exchange(client::node_search(in.client.frame(), {}, {}));
    auto node = client::decode_node_search(response);
    if (!node) throw ConnectionError("the Node Search answer does not have the fields of JA §3.12");
    const auto ip = client::ip_text(node->ip), mac = client::mac_text(node->mac);
    const auto model = word_hex(node->model_code, 8), vendor = word_hex(node->vendor_code, 4);
    const auto version = word_hex(node->version, 4), status = word_hex(node->status, 4);
    const auto port = std::to_string(node->port);
    Json json{{"ip", ip},          {"mac", mac},       {"station", node->host_name},
              {"model_code", model}, {"vendor_code", vendor}, {"version", version},
              {"status", status},  {"port", node->port}, {"subnet_mask", client::ip_text(node->subnet_mask)},
              {"gateway", client::ip_text(node->gateway)}, {"partner", client::ip_text(node->partner_ip)},
              {"partner_port", node->partner_port}};
    in.output.result(json, Table{{"ip", "mac", "station", "model code", "vendor", "version", "status", "port"},
                                 {{ip, mac, node->host_name, model, vendor, version, status, port}}});
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
