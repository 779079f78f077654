// The JW-51CM's SEND/RECEIVE, data-memory start method (§13): the ladder
// fills a 16-byte control block in data memory and sets its start bit; the
// unit, at the END of a scan, connects out to the partner station the
// station table names and moves n bytes — SEND: own data memory → partner,
// RECEIVE: partner → own — then writes FLAGS (40 normal end, 60 timeout, E0
// error, 90 while busy). The manual does not document the wire format
// between units: the simulated unit sends the partner computer-link commands
// 34 (register write) and 24 (register read) (inferred, docs/jw51cm.md), so
// any JW-51CM face — another slmp-sim station — is a partner.
//
// Parameters (§15): the channel's connection among 0100–0137 (local port 6008,
// 80 TCP_Active or 01 UDP), 0400 = 02 and the station table 0410–0777
// (station → IP, port), the control block's place at 3770–3773.
#pragma once

#include <array>
#include <cstdint>
#include <functional>
#include <memory>
#include <optional>
#include <span>
#include <string>
#include <vector>

#include "frontends/face.hpp"
#include "frontends/jw51cm/buffers.hpp"
#include "frontends/jw51cm/memory_map.hpp"

namespace slmp::jw51cm {

class ComputerLink;

inline constexpr std::uint32_t kConnectionParameters = 0100;    // 0100–0137: 4 bytes a connection
inline constexpr std::uint32_t kMappingParameter = 0400;        // 01 automatic, 02 individual
inline constexpr std::uint32_t kStationTables = 0410;           // 0410–0777: 8 bytes an entry, 31 entries
inline constexpr unsigned kStationEntries = 31;
inline constexpr std::uint32_t kControlBlockParameters = 03770; // 3770–3773
inline constexpr std::uint16_t kDataMemoryPort = 0x6008;
inline constexpr std::uint8_t kTcpActive = 0x80, kUdpOpen = 0x01;
inline constexpr std::uint8_t kIndividualMapping = 0x02, kAutomaticMapping = 0x01;
inline constexpr std::uint32_t kControlBlockBytes = 020;       // +00–+17 (octal)
inline constexpr std::uint32_t kMaxTransfer = 0x400;

// FLAGS (control block +00), written by the unit.
inline constexpr std::uint8_t kFlagsIdle = 0x00, kFlagsBusy = 0x90, kFlagsDone = 0x40, kFlagsTimeout = 0x60,
                              kFlagsError = 0xE0;
inline constexpr std::uint8_t kStartBit = 0x80, kTypeSend = 0x00, kTypeReceive = 0x02;

// The data-memory start method's channel, as the parameters define it.
struct DataMemoryChannel {
    bool on = false;            // 3773 = 80
    Place control;              // 3770/3771 address (L, H), 3772 file
    bool tcp = true;            // its connection: 80 TCP_Active, or 01 UDP
    std::uint8_t connection = 0;
};
DataMemoryChannel data_memory_channel(std::span<const std::uint8_t> parameters);

// A partner station from the station table (0400 = 02): its IPv4 address and port.
struct PartnerAddress {
    std::array<std::uint8_t, 4> ip{};
    std::uint16_t port = 0;
    std::string address() const;
};
std::optional<PartnerAddress> partner_of(std::span<const std::uint8_t> parameters, std::uint8_t station);

// What is wrong with 0100–0137, 0400–0777 and 3770–3773, naming the parameter and the fix; empty when nothing.
// `udp_port`: the unit serves a UDP port, which is connection 7.
std::string check_send_receive_parameters(std::span<const std::uint8_t> parameters, const MemoryMap& map, bool udp_port);

// The channel at work: polled at END, one transfer at a time.
class SendReceive {
public:
    explicit SendReceive(ComputerLink& link);
    ~SendReceive();
    SendReceive(const SendReceive&) = delete;
    SendReceive& operator=(const SendReceive&) = delete;

    void attach(frontends::StationServices& services) { services_ = &services; }
    // Reads the control block; a set start bit (and no transfer running) starts one.
    void end_of_scan();
    // The unit restarted: its connection out is gone, a running transfer forgotten.
    void power_on();
    const DataMemoryChannel& channel() const { return channel_; }

private:
    struct Transfer {
        std::uint8_t type = 0;
        PartnerAddress partner;
        std::uint16_t count = 0;
        Place own, theirs;
        std::uint32_t done = 0;   // bytes moved so far
    };
    void begin(std::span<const std::uint8_t> block);
    void open_tcp();
    bool same_partner() const;   // the connection out goes to this transfer's partner
    void close_tcp();
    void next_chunk();
    void answered(std::optional<std::vector<std::uint8_t>> answer, std::uint32_t chunk);
    void finish(std::uint8_t flags);
    void set_flags(std::uint8_t flags);
    void set_connected(bool on);
    // A callback that runs only while this transfer is the running one, and the question it asks.
    std::function<void()> guarded(std::function<void()> action);
    std::function<bool()> still_running();

    ComputerLink& link_;
    DataMemoryChannel channel_;
    frontends::StationServices* services_ = nullptr;
    std::unique_ptr<frontends::Outgoing> outgoing_;
    PartnerAddress connected_to_;   // where outgoing_ goes
    bool busy_ = false;
    Transfer transfer_;
    std::uint64_t generation_ = 0;   // moves on at each finish: late callbacks of an ended transfer do nothing
    std::shared_ptr<int> alive_ = std::make_shared<int>(0);
};

// The answer's whole length once `received` shows it (computer-link answers have no length field).
std::optional<std::size_t> answer_length(std::span<const std::uint8_t> received);

}  // namespace slmp::jw51cm
