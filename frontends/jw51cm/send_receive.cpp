#include "frontends/jw51cm/send_receive.hpp"

#include <algorithm>
#include <chrono>
#include <set>

#include "frontends/jw51cm/computer_link.hpp"

namespace slmp::jw51cm {

namespace {

std::uint16_t u16(std::span<const std::uint8_t> p, std::size_t at) { return static_cast<std::uint16_t>(p[at] | (p[at + 1] << 8)); }
std::string parameter(std::uint32_t address) { return "parameter " + octal(address, 4); }

constexpr std::size_t kCom = kHeaderBytes + 2;
// A UDP command is at most 1024 bytes (§4.1): 34's 48 bytes before its data leave 976.
constexpr std::uint32_t kUdpChunk = kMaxData - (kHeaderBytes + 8);
// Default timers (§13): TCP 2 min, UDP 1 s; the block's TIMER (+01) in 100 ms units when not 0.
constexpr std::chrono::milliseconds kTcpTimer{120000}, kUdpTimer{1000};

// The channel's connection: the one of 0100–0137 with local port 6008 (first one wins; the check allows one).
std::optional<std::uint8_t> channel_connection(std::span<const std::uint8_t> p) {
    for (unsigned n = 0; n < kConnections; ++n) {
        const auto at = kConnectionParameters + 4 * n;
        if (u16(p, at + 2) == kDataMemoryPort && (p[at] == kTcpActive || p[at] == kUdpOpen)) return static_cast<std::uint8_t>(n);
    }
    return std::nullopt;
}

std::vector<std::uint8_t> command(std::uint8_t com, Place at, std::uint16_t count) {
    std::vector<std::uint8_t> frame(kHeaderBytes + 8, 0);   // an all-zero header: no 2-tier relaying
    frame[kHeaderBytes] = kCommandId;
    frame[kCom] = com;
    frame[kCom + 1] = at.file;
    frame[kCom + 2] = static_cast<std::uint8_t>(at.address & 0xFF);
    frame[kCom + 3] = static_cast<std::uint8_t>(at.address >> 8);
    frame[kCom + 4] = static_cast<std::uint8_t>(count & 0xFF);
    frame[kCom + 5] = static_cast<std::uint8_t>(count >> 8);
    return frame;
}

}  // namespace

DataMemoryChannel data_memory_channel(std::span<const std::uint8_t> p) {
    DataMemoryChannel channel;
    const auto at = kControlBlockParameters;
    auto connection = channel_connection(p);
    channel.on = p[at + 3] == kOutputOn && connection.has_value();
    channel.control = {p[at + 2], u16(p, at)};
    if (connection) {
        channel.connection = *connection;
        channel.tcp = p[kConnectionParameters + 4 * *connection] == kTcpActive;
    }
    return channel;
}

std::string PartnerAddress::address() const {
    return std::to_string(ip[0]) + "." + std::to_string(ip[1]) + "." + std::to_string(ip[2]) + "." + std::to_string(ip[3]);
}

std::optional<PartnerAddress> partner_of(std::span<const std::uint8_t> p, std::uint8_t station) {
    if (p[kMappingParameter] != kIndividualMapping) return std::nullopt;
    for (unsigned k = 0; k < kStationEntries; ++k) {
        const auto at = kStationTables + 8 * k;
        if (p[at] != 0x01 || p[at + 1] != station) continue;
        return PartnerAddress{{p[at + 4], p[at + 5], p[at + 6], p[at + 7]}, u16(p, at + 2)};
    }
    return std::nullopt;
}

std::string check_send_receive_parameters(std::span<const std::uint8_t> p, const MemoryMap& map, bool udp_port) {
    std::optional<unsigned> channel;
    for (unsigned n = 0; n < kConnections; ++n) {
        const auto at = kConnectionParameters + 4 * n;
        if (p[at] == 0 && p[at + 1] == 0 && u16(p, at + 2) == 0) continue;   // not given
        if (p[at + 1] != 0) return parameter(at + 1) + " (connection " + std::to_string(n) + ") is unused and must be 00";
        if (u16(p, at + 2) != kDataMemoryPort || (p[at] != kTcpActive && p[at] != kUdpOpen))
            return parameter(at) + " (connection " + std::to_string(n) +
                   "): the simulated unit's computer-link connections are \"tcp_port\" and \"udp_port\"; only the "
                   "SEND/RECEIVE data-memory channel may be given here: local port 6008 (+2, +3 = 08 60) with open "
                   "method 80 (TCP_Active) or 01 (UDP)";
        if (channel)
            return parameter(at) + ": connection " + std::to_string(*channel) + " already has local port 6008; give it once";
        if (udp_port && n == kUdpConnection)
            return parameter(at) + ": connection 7 is the unit's UDP port (\"udp_port\") in the simulator; give SEND/RECEIVE connection 0-6";
        channel = n;
    }
    const auto mapping = p[kMappingParameter];
    if (mapping == kAutomaticMapping)
        return parameter(kMappingParameter) +
               " is 01 (automatic: the partner's address from the unit's own, 0000-0003, which the simulated unit does not "
               "have); use 02 and give each partner station an entry at 0410-0777 (+0 01, +1 station, +2/+3 port, +4-+7 IP)";
    if (mapping != 0 && mapping != kIndividualMapping) return parameter(kMappingParameter) + " is not 00, 01 or 02";
    for (std::uint32_t at = kMappingParameter + 1; at < kStationTables; ++at)
        if (p[at] != 0) return parameter(at) + " is unused and must be 00";
    std::set<std::uint8_t> stations;
    for (unsigned k = 0; k < kStationEntries; ++k) {
        const auto at = kStationTables + 8 * k;
        if (p[at] == 0) continue;
        const auto entry = "station table " + octal(k + 1, 2) + " (" + parameter(at) + ")";
        if (p[at] != 0x01) return entry + ": +0 is not 00 (unused) or 01 (valid)";
        if (p[at + 1] > 077) return entry + ": station " + octal(p[at + 1], 3) + " is not 00-77 (octal)";
        if (!stations.insert(p[at + 1]).second) return entry + ": station " + octal(p[at + 1], 2) + " has an entry already";
        const auto port = u16(p, at + 2);
        if (port == 0 || port == 0xFFFF) return entry + ": port (+2 L, +3 H) " + std::to_string(port) + " is not 1-65534";
        if (p[at + 4] == 0 && p[at + 5] == 0 && p[at + 6] == 0 && p[at + 7] == 0) return entry + ": the IP address (+4-+7) is 0.0.0.0";
    }
    const auto c = kControlBlockParameters;
    if (p[c + 3] != 0 && p[c + 3] != kOutputOn) return parameter(c + 3) + " (the SEND/RECEIVE control block) is not 00 (off) or 80 (valid)";
    if (p[c + 3] == kOutputOn) {
        if (!channel)
            return parameter(c + 3) + ": the data-memory SEND/RECEIVE needs a connection with local port 6008; give one of "
                   "0100-0137 as 80 00 08 60 (TCP_Active) or 01 00 08 60 (UDP)";
        if (mapping != kIndividualMapping)
            return parameter(c + 3) + ": the data-memory SEND/RECEIVE needs the station table; set 0400 to 02 and give entries at 0410-0777";
        Place control{p[c + 2], u16(p, c)};
        if (!map.contains(control.file, control.address, kControlBlockBytes))
            return parameter(c) + ": the control block (16 bytes from file " + std::to_string(control.file) + " " +
                   octal(control.address, 6) + ") is not inside a file; 3770/3771 is the address (L, H), 3772 the file 0-7";
    }
    return {};
}

std::optional<std::size_t> answer_length(std::span<const std::uint8_t> r) {
    if (r.size() < kCom + 2) return std::nullopt;
    if (r[kCom + 1] != 0x00) return kCom + 2;   // an error answer: no text
    if (r[kCom] == 0x34) return kCom + 2 + 5;
    if (r[kCom] == 0x24) {
        if (r.size() < kCom + 2 + 5) return std::nullopt;
        return kCom + 2 + 5 + u16(r, kCom + 5);
    }
    return kCom + 2;   // not an answer to what was asked: the caller refuses it
}

SendReceive::SendReceive(ComputerLink& link) : link_(link), channel_(data_memory_channel(link.options().parameters)) {}

SendReceive::~SendReceive() = default;

std::function<bool()> SendReceive::still_running() {
    std::weak_ptr<int> alive = alive_;
    return [this, alive, generation = generation_] { return alive.lock() && busy_ && generation == generation_; };
}

std::function<void()> SendReceive::guarded(std::function<void()> action) {
    return [running = still_running(), action = std::move(action)] {
        if (running()) action();
    };
}

void SendReceive::end_of_scan() {
    if (!channel_.on || !services_) return;
    // The partner closed the TCP connection (or it broke) while idle: its status flag bit goes.
    if (!busy_ && channel_.tcp && outgoing_ && !outgoing_->connected()) close_tcp();
    if (busy_) return;
    ByteAccess memory(link_.cpu().memory(), link_.map());
    std::vector<std::uint8_t> block;
    for (std::uint32_t i = 0; i < kControlBlockBytes; ++i) block.push_back(memory.byte(channel_.control.file, channel_.control.address + i));
    if (!(block[2] & kStartBit)) return;
    // Taken: the start bit is cleared (inferred) and FLAGS shows busy until the end.
    memory.set_byte(channel_.control.file, channel_.control.address + 2, static_cast<std::uint8_t>(block[2] & ~kStartBit));
    begin(block);
}

void SendReceive::begin(std::span<const std::uint8_t> b) {
    busy_ = true;
    set_flags(kFlagsBusy);
    transfer_ = {};
    transfer_.type = static_cast<std::uint8_t>(b[2] & ~kStartBit);
    transfer_.count = u16(b, 006);
    transfer_.own = {b[012], u16(b, 010)};
    transfer_.theirs = {b[016], u16(b, 014)};
    auto partner = partner_of(link_.options().parameters, b[3]);
    if ((transfer_.type != kTypeSend && transfer_.type != kTypeReceive) || !partner) return finish(kFlagsError);
    transfer_.partner = *partner;
    const auto timer = b[1] ? std::chrono::milliseconds(100 * b[1]) : channel_.tcp ? kTcpTimer : kUdpTimer;
    services_->after(timer, still_running(), guarded([this] {
        if (channel_.tcp) close_tcp();   // an answer that comes later must not pass for the next one's
        finish(kFlagsTimeout);
    }));
    // Open (ADR_B 177777) and close (177776) with file 0 and n = 0 (§13).
    const bool open = transfer_.theirs.file == 0 && transfer_.count == 0 && transfer_.theirs.address == 0xFFFF;
    const bool close = transfer_.theirs.file == 0 && transfer_.count == 0 && transfer_.theirs.address == 0xFFFE;
    if (open || close) {
        if (!channel_.tcp) return finish(kFlagsDone);   // UDP has nothing to open or close (inferred)
        if (close) {
            close_tcp();
            return finish(kFlagsDone);
        }
        if (outgoing_ && outgoing_->connected())   // one TCP_Active connection, to one partner at a time (inferred)
            return finish(same_partner() ? kFlagsDone : kFlagsError);
        return open_tcp();
    }
    if (transfer_.count == 0 || transfer_.count > kMaxTransfer || transfer_.theirs.file > 7 ||
        !link_.map().contains(transfer_.own.file, transfer_.own.address, transfer_.count))
        return finish(kFlagsError);
    if (channel_.tcp) {
        if (!outgoing_ || !outgoing_->connected() || !same_partner()) return finish(kFlagsError);   // not opened to it (inferred)
        return next_chunk();
    }
    if (!outgoing_ || !same_partner()) {   // a UDP socket a partner: only its datagrams are answers
        outgoing_ = services_->connect(protocol::Transport::Udp, transfer_.partner.address(), transfer_.partner.port);
        connected_to_ = transfer_.partner;
        outgoing_->open([](bool) {});
    }
    next_chunk();
}

void SendReceive::open_tcp() {
    outgoing_ = services_->connect(protocol::Transport::Tcp, transfer_.partner.address(), transfer_.partner.port);
    connected_to_ = transfer_.partner;
    outgoing_->open([done = guarded([this] {
                        set_connected(true);
                        finish(kFlagsDone);
                    })](bool connected) {
        // Not connected: no answer from the partner; its timer ends the open with 60 (inferred).
        if (connected) done();
    });
}

bool SendReceive::same_partner() const {
    return connected_to_.ip == transfer_.partner.ip && connected_to_.port == transfer_.partner.port;
}

void SendReceive::close_tcp() {
    outgoing_.reset();
    set_connected(false);
}

void SendReceive::next_chunk() {
    const auto left = transfer_.count - transfer_.done;
    if (left == 0) return finish(kFlagsDone);
    const auto chunk = std::min<std::uint32_t>(left, channel_.tcp ? kMaxData : kUdpChunk);
    const Place theirs{transfer_.theirs.file, transfer_.theirs.address + transfer_.done};
    std::vector<std::uint8_t> request;
    if (transfer_.type == kTypeSend) {
        request = command(0x34, theirs, static_cast<std::uint16_t>(chunk));
        ByteAccess memory(link_.cpu().memory(), link_.map());
        for (std::uint32_t i = 0; i < chunk; ++i)
            request.push_back(memory.byte(transfer_.own.file, transfer_.own.address + transfer_.done + i));
    } else {
        request = command(0x24, theirs, static_cast<std::uint16_t>(chunk));
    }
    std::weak_ptr<int> alive = alive_;
    auto generation = generation_;
    outgoing_->exchange(std::move(request), answer_length,
                        [this, alive, generation, chunk](std::optional<std::vector<std::uint8_t>> answer) {
                            if (!alive.lock() || !busy_ || generation != generation_) return;
                            answered(std::move(answer), chunk);
                        });
}

void SendReceive::answered(std::optional<std::vector<std::uint8_t>> answer, std::uint32_t chunk) {
    if (!answer) {
        if (channel_.tcp) {   // the partner closed the connection: an error end (inferred)
            close_tcp();
            return finish(kFlagsError);
        }
        return;   // UDP: no answer; the timer decides
    }
    const auto& a = *answer;
    const std::uint8_t com = transfer_.type == kTypeSend ? 0x34 : 0x24;
    const auto want = transfer_.type == kTypeSend ? kCom + 7 : kCom + 7 + chunk;
    if (a.size() < kCom + 2 || a[kHeaderBytes] != kResponseId || a[kCom] != com || a[kCom + 1] != 0x00 || a.size() != want)
        return finish(kFlagsError);   // the partner's error response (or not an answer to this command)
    if (transfer_.type == kTypeReceive) {
        ByteAccess memory(link_.cpu().memory(), link_.map());
        for (std::uint32_t i = 0; i < chunk; ++i)
            memory.set_byte(transfer_.own.file, transfer_.own.address + transfer_.done + i, a[kCom + 7 + i]);
    }
    transfer_.done += chunk;
    next_chunk();
}

void SendReceive::finish(std::uint8_t flags) {
    set_flags(flags);
    busy_ = false;
    ++generation_;
}

void SendReceive::set_flags(std::uint8_t flags) {
    ByteAccess memory(link_.cpu().memory(), link_.map());
    memory.set_byte(channel_.control.file, channel_.control.address, flags);
}

void SendReceive::set_connected(bool on) {
    if (channel_.tcp) link_.set_connection(channel_.connection, on);
}

void SendReceive::power_on() {
    if (busy_) {   // the restarted unit forgot it: the channel is idle again
        set_flags(kFlagsIdle);
        busy_ = false;
        ++generation_;
    }
    outgoing_.reset();
    if (channel_.on && channel_.tcp) link_.set_connection(channel_.connection, false);
}

}  // namespace slmp::jw51cm
