// The station as an SLMP-compatible device of the CC-Link Partner Association's
// manual (SLMP リファレンスマニュアル, JA §3.12–3.14 and ch. 4): what node
// search reports and IP Address Set changes (MAC, IP, subnet, gateway, host
// name, vendor/model code, version, the communication partner), the parameter
// store of Parameter Get/Set and its write-exclusive sequence (Start → Set … →
// End, or Cancel; JA §4.2.1.8's state table, 10 s timeout). Plain data and
// rules, no wire format: protocol/commands/node.cpp reads and writes the
// fields, station/ fills the identity from the configuration (docs/nodes.md).
// Only ports whose profile has "node_commands" reach it.
#pragma once

#include <array>
#include <chrono>
#include <cstdint>
#include <map>
#include <string>
#include <vector>

namespace slmp::devicemodel {

using MacAddress = std::array<std::uint8_t, 6>;   // most significant octet first, as written 00:26:92:…
using Ipv4Address = std::array<std::uint8_t, 4>;  // 192.168.0.1 = {192, 168, 0, 1}

// What Node Search (0E30) answers about the server and IP Address Set (0E31) sets.
struct NodeIdentity {
    MacAddress mac{};
    Ipv4Address ip{};
    Ipv4Address subnet_mask{255, 255, 255, 0};
    Ipv4Address gateway{};
    std::string host_name;
    std::uint16_t vendor_code = 0;
    std::uint32_t model_code = 0;
    std::uint16_t version = 1;
    // The communication partner ("交信相手ユニット"): Status Read2 (0E53)
    // answers only a sender with this address; 0.0.0.0 = none set, every
    // sender is answered (inferred: a fresh device has no partner yet).
    Ipv4Address partner_ip{};
    std::uint16_t partner_port = 0;
    std::uint8_t protocol = 0;   // "サーバ通信プロトコル設定", kept as set (its values are not in the manual)
    // Communication Setting Get (0E45): the client's timeout towards this
    // server, 0400H-FFFFH ms (2000 ms, inferred: the manual's own wait, JA §4.1.1).
    std::uint32_t timeout_ms = 2000;
};

// One parameter of the store: its value as `size` octets, most significant first.
struct NodeParameter {
    std::vector<std::uint8_t> value;
};

// The per-station parameter store and the write-exclusive sequence of JA §4.2.1.8.
class Node {
public:
    using TimePoint = std::chrono::steady_clock::time_point;
    using Client = std::uint64_t;   // the connection (TCP) or peer (UDP) that started the write
    static constexpr std::chrono::seconds kWriteTimeout{10};   // JA §4.2.1.6

    enum class WriteState : std::uint8_t { Normal, Started, Holding };
    // What a sequence event answers; the protocol maps each to its end code.
    enum class Verdict : std::uint8_t {
        Ok,
        Busy,            // CEE0: a write is under way (another client, a second Start, any other command)
        NotStarted,      // CF31: Set/End/Cancel without Start
        BadParameter,    // CF30: unknown ID, or a size the ID does not have
    };

    Node();

    NodeIdentity& identity() { return identity_; }
    const NodeIdentity& identity() const { return identity_; }

    const std::map<std::uint16_t, NodeParameter>& parameters() const { return parameters_; }
    const NodeParameter* parameter(std::uint16_t id) const;

    // The sequence's state at `now` (a write left 10 s without Set/End has timed out).
    WriteState write_state(TimePoint now);
    // Whether a request that is not part of the write sequence is refused (CEE0) at `now`.
    bool busy(TimePoint now) { return write_state(now) != WriteState::Normal; }

    Verdict start(Client client, TimePoint now);
    // Checks every parameter first; a refused Set holds nothing.
    Verdict set(Client client, const std::vector<std::pair<std::uint16_t, std::vector<std::uint8_t>>>& values,
                TimePoint now);
    Verdict end(Client client, TimePoint now);   // held values become the parameters
    Verdict cancel(Client client, TimePoint now);   // held values are dropped

    // Whether `client` may send Set/End/Cancel now (Ok, NotStarted or Busy):
    // asked before the request data, which only then can make a Set CF30.
    Verdict owner_event(Client client, TimePoint now);
    std::size_t held() const { return pending_.size(); }

private:

    NodeIdentity identity_;
    std::map<std::uint16_t, NodeParameter> parameters_;
    WriteState state_ = WriteState::Normal;
    Client owner_ = 0;
    TimePoint deadline_{};
    std::map<std::uint16_t, std::vector<std::uint8_t>> pending_;
};

// The simulator's parameter IDs (inferred: a real device's IDs and sizes are
// in its CSP+ profile, which the manual leaves to each device): 0001–0010,
// one word each, all 0 at power-on (docs/nodes.md).
constexpr std::uint16_t kFirstNodeParameter = 0x0001;
constexpr std::uint16_t kLastNodeParameter = 0x0010;
constexpr std::size_t kNodeParameterBytes = 2;

}  // namespace slmp::devicemodel
