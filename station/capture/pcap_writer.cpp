#include "station/capture/pcap_writer.hpp"

#include <arpa/inet.h>

#include <algorithm>
#include <cstdlib>

#include "config/config_error.hpp"

namespace slmp::station {

namespace {

using Bytes = std::vector<std::uint8_t>;

constexpr std::uint32_t kLinkTypeRaw = 101;   // packets start at the IP header (v4 or v6)
constexpr std::uint32_t kSnapLength = 262144;
constexpr std::uint8_t kTcp = 6, kUdp = 17;
constexpr std::uint8_t kFin = 0x01, kSyn = 0x02, kRst = 0x04, kPsh = 0x08, kAck = 0x10;
// An IPv4 packet is at most 65535 bytes; larger payloads go in several segments.
constexpr std::size_t kMaxSegment = 65000;

// pcap's own fields are little-endian (magic d4 c3 b2 a1 on disk); network headers are big-endian.
void le32(Bytes& b, std::uint32_t v) {
    for (int i = 0; i < 4; ++i) b.push_back(static_cast<std::uint8_t>(v >> (8 * i)));
}
void le16(Bytes& b, std::uint16_t v) {
    b.push_back(static_cast<std::uint8_t>(v));
    b.push_back(static_cast<std::uint8_t>(v >> 8));
}
void be16(Bytes& b, std::uint16_t v) {
    b.push_back(static_cast<std::uint8_t>(v >> 8));
    b.push_back(static_cast<std::uint8_t>(v));
}
void be32(Bytes& b, std::uint32_t v) {
    be16(b, static_cast<std::uint16_t>(v >> 16));
    be16(b, static_cast<std::uint16_t>(v));
}
void put16(Bytes& b, std::size_t at, std::uint16_t v) {
    b[at] = static_cast<std::uint8_t>(v >> 8);
    b[at + 1] = static_cast<std::uint8_t>(v);
}

// The Internet checksum (RFC 1071): one's-complement sum of 16-bit words.
struct Checksum {
    std::uint32_t sum = 0;
    bool odd = false;   // a byte is waiting for its partner
    void add(std::span<const std::uint8_t> bytes) {
        for (auto byte : bytes) {
            sum += odd ? byte : static_cast<std::uint32_t>(byte) << 8;
            odd = !odd;
        }
    }
    std::uint16_t done() const {
        auto s = sum;
        while (s >> 16) s = (s & 0xFFFF) + (s >> 16);
        return static_cast<std::uint16_t>(~s);
    }
};

// "127.0.0.1:50312", "::1:50312" or "::ffff:10.0.0.5:50312" (v4-mapped, from a dual-stack socket).
PcapWriter::Endpoint parse_address(std::string_view text, std::uint16_t port) {
    PcapWriter::Endpoint e;
    e.port = port;
    std::string address(text);
    if (address.size() > 2 && address.front() == '[' && address.back() == ']') address = address.substr(1, address.size() - 2);
    if (::inet_pton(AF_INET, address.c_str(), e.address.data()) == 1) return e;
    if (::inet_pton(AF_INET6, address.c_str(), e.address.data()) == 1) {
        static constexpr std::uint8_t mapped[12] = {0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0xFF, 0xFF};
        if (std::equal(mapped, mapped + 12, e.address.begin())) {
            std::copy(e.address.begin() + 12, e.address.end(), e.address.begin());
            std::fill(e.address.begin() + 4, e.address.end(), 0);
        } else {
            e.v6 = true;
        }
    }
    return e;   // unparsable: 0.0.0.0, the packets still show the bytes
}

bool unspecified(const PcapWriter::Endpoint& e) {
    return std::all_of(e.address.begin(), e.address.begin() + (e.v6 ? 16 : 4), [](auto b) { return b == 0; });
}

bool loopback(const PcapWriter::Endpoint& e) {
    if (!e.v6) return e.address[0] == 127;
    return std::all_of(e.address.begin(), e.address.begin() + 15, [](auto b) { return b == 0; }) && e.address[15] == 1;
}

}  // namespace

PcapWriter::PcapWriter(const std::filesystem::path& file, const std::string& server_address, TimePoint start,
                       std::chrono::system_clock::time_point wall_start)
    : out_(file, std::ios::binary | std::ios::trunc), server_address_(server_address), start_(start), wall_start_(wall_start) {
    if (!out_) throw config::ConfigError(file.string() + ": cannot write the capture; check the path given to --record-pcap");
    Bytes header;
    le32(header, 0xA1B2C3D4);   // microsecond timestamps
    le16(header, 2);            // version 2.4
    le16(header, 4);
    le32(header, 0);            // timestamps in UTC
    le32(header, 0);            // accuracy (always 0)
    le32(header, kSnapLength);
    le32(header, kLinkTypeRaw);
    out_.write(reinterpret_cast<const char*>(header.data()), static_cast<std::streamsize>(header.size()));
    out_.flush();
}

PcapWriter::Pair PcapWriter::endpoints(const RecordedLink& link) const {
    Pair p;
    auto colon = link.peer.rfind(':');
    std::uint16_t port = 0;
    if (colon != std::string::npos) port = static_cast<std::uint16_t>(std::atoi(link.peer.c_str() + colon + 1));
    p.client = parse_address(std::string_view(link.peer).substr(0, colon), port);
    p.server = parse_address(server_address_, link.local_port);
    // Both ends need one IP version; a wildcard bind names no address, so use
    // what the client must have reached: loopback for a local client.
    if (p.server.v6 != p.client.v6 || unspecified(p.server)) {
        p.server = Endpoint{p.client.v6, {}, link.local_port};
        if (loopback(p.client)) {
            if (p.client.v6) p.server.address[15] = 1;
            else p.server.address = {127, 0, 0, 1};
        }
    }
    return p;
}

void PcapWriter::opened(TimePoint at, const RecordedLink& link) {
    if (link.transport == Transport::Tcp) flow(at, link, endpoints(link));
}

// The connection's sequence numbers; the three-way handshake is written the
// first time a connection is seen. Initial sequence numbers are fixed per
// connection id, so a capture of the same session is the same file.
PcapWriter::Flow& PcapWriter::flow(TimePoint at, const RecordedLink& link, const Pair& ends) {
    if (auto it = flows_.find(link.connection); it != flows_.end()) return it->second;
    auto client_isn = static_cast<std::uint32_t>(0x10000000u + link.connection);
    auto server_isn = static_cast<std::uint32_t>(0x20000000u + link.connection);
    tcp(at, ends, true, kSyn, client_isn, 0);
    tcp(at, ends, false, kSyn | kAck, server_isn, client_isn + 1);
    tcp(at, ends, true, kAck, client_isn + 1, server_isn + 1);
    return flows_[link.connection] = Flow{client_isn + 1, server_isn + 1};
}

void PcapWriter::exchange(TimePoint at, const RecordedLink& link, std::span<const std::uint8_t> request,
                          const std::vector<std::uint8_t>* response, const std::vector<std::string>&,
                          const std::string&) {
    auto ends = endpoints(link);
    if (link.transport == Transport::Udp) {
        if (!request.empty()) udp(at, ends, true, request);   // an Ondemand push has none
        if (response) udp(at, ends, false, *response);
        return;
    }
    auto& f = flow(at, link, ends);
    auto send = [&](bool from_client, std::span<const std::uint8_t> bytes) {
        for (std::size_t done = 0; done < bytes.size(); done += kMaxSegment) {
            auto part = bytes.subspan(done, std::min(kMaxSegment, bytes.size() - done));
            auto& seq = from_client ? f.client : f.server;
            tcp(at, ends, from_client, kPsh | kAck, seq, from_client ? f.server : f.client, part);
            seq += static_cast<std::uint32_t>(part.size());
        }
    };
    send(true, request);
    if (response) send(false, *response);
}

// FIN from the side that closed, the other's FIN, the last ACK; a reset is one RST.
void PcapWriter::closed(TimePoint at, const RecordedLink& link, const std::string& why) {
    if (link.transport != Transport::Tcp) return;
    auto ends = endpoints(link);
    auto f = flow(at, link, ends);
    flows_.erase(link.connection);
    if (why.find("reset") != std::string::npos || why.find("RST") != std::string::npos) {
        bool by_client = why.find("by peer") != std::string::npos;   // ECONNRESET on our side
        tcp(at, ends, by_client, kRst | kAck, by_client ? f.client : f.server, by_client ? f.server : f.client);
        return;
    }
    bool by_client = why.find("client") != std::string::npos;
    auto& first = by_client ? f.client : f.server;
    auto& second = by_client ? f.server : f.client;
    tcp(at, ends, by_client, kFin | kAck, first, second);
    tcp(at, ends, !by_client, kFin | kAck, second, first + 1);
    tcp(at, ends, by_client, kAck, first + 1, second + 1);
}

void PcapWriter::tcp(TimePoint at, const Pair& ends, bool from_client, std::uint8_t flags, std::uint32_t seq,
                     std::uint32_t ack, std::span<const std::uint8_t> payload) {
    const auto& from = from_client ? ends.client : ends.server;
    const auto& to = from_client ? ends.server : ends.client;
    Bytes h;
    be16(h, from.port);
    be16(h, to.port);
    be32(h, seq);
    be32(h, ack);
    h.push_back(5 << 4);   // 20-byte header, no options
    h.push_back(flags);
    be16(h, 0xFFFF);       // window
    be16(h, 0);            // checksum, filled in by packet()
    be16(h, 0);            // urgent pointer
    packet(at, from, to, kTcp, std::move(h), payload);
}

void PcapWriter::udp(TimePoint at, const Pair& ends, bool from_client, std::span<const std::uint8_t> payload) {
    const auto& from = from_client ? ends.client : ends.server;
    const auto& to = from_client ? ends.server : ends.client;
    Bytes h;
    be16(h, from.port);
    be16(h, to.port);
    be16(h, static_cast<std::uint16_t>(8 + payload.size()));
    be16(h, 0);   // checksum, filled in by packet()
    packet(at, from, to, kUdp, std::move(h), payload);
}

// IP header + transport header (checksum filled in here) + payload, as one pcap record.
void PcapWriter::packet(TimePoint at, const Endpoint& from, const Endpoint& to, std::uint8_t protocol, Bytes th,
                        std::span<const std::uint8_t> payload) {
    const auto length = th.size() + payload.size();   // transport header + payload
    const std::size_t address_bytes = from.v6 ? 16 : 4;
    // Transport checksum over the pseudo-header (addresses, protocol, length) and the segment.
    Checksum sum;
    sum.add(std::span(from.address).first(address_bytes));
    sum.add(std::span(to.address).first(address_bytes));
    Bytes pseudo;   // v4: zero, protocol, 16-bit length; v6: 32-bit length, three zeros, next header
    if (from.v6) {
        be32(pseudo, static_cast<std::uint32_t>(length));
        be32(pseudo, protocol);
    } else {
        be16(pseudo, protocol);
        be16(pseudo, static_cast<std::uint16_t>(length));
    }
    sum.add(pseudo);
    sum.add(th);
    sum.add(payload);
    auto check = sum.done();
    if (protocol == kUdp && check == 0) check = 0xFFFF;   // 0 means "no checksum" in UDP
    put16(th, protocol == kTcp ? 16 : 6, check);

    Bytes ip;
    if (from.v6) {
        be32(ip, 0x60000000);   // version 6, no traffic class, no flow label
        be16(ip, static_cast<std::uint16_t>(length));
        ip.push_back(protocol);
        ip.push_back(64);       // hop limit
        ip.insert(ip.end(), from.address.begin(), from.address.end());
        ip.insert(ip.end(), to.address.begin(), to.address.end());
    } else {
        ip.push_back(0x45);     // version 4, 20-byte header
        ip.push_back(0);
        be16(ip, static_cast<std::uint16_t>(20 + length));
        be16(ip, ++ip_id_);
        be16(ip, 0x4000);       // don't fragment
        ip.push_back(64);       // TTL
        ip.push_back(protocol);
        be16(ip, 0);            // header checksum, below
        ip.insert(ip.end(), from.address.begin(), from.address.begin() + 4);
        ip.insert(ip.end(), to.address.begin(), to.address.begin() + 4);
        Checksum header;
        header.add(ip);
        put16(ip, 10, header.done());
    }

    auto since = std::chrono::duration_cast<std::chrono::microseconds>(at - start_);
    auto us = std::chrono::duration_cast<std::chrono::microseconds>(wall_start_.time_since_epoch()) + since;
    const auto size = static_cast<std::uint32_t>(ip.size() + th.size() + payload.size());
    Bytes record;
    le32(record, static_cast<std::uint32_t>(us.count() / 1000000));
    le32(record, static_cast<std::uint32_t>(us.count() % 1000000));
    le32(record, size);   // captured length
    le32(record, size);   // original length
    for (const auto* part : {&record, &ip, &th})
        out_.write(reinterpret_cast<const char*>(part->data()), static_cast<std::streamsize>(part->size()));
    out_.write(reinterpret_cast<const char*>(payload.data()), static_cast<std::streamsize>(payload.size()));
    // Flushed per packet, like the JSON lines: a killed simulator leaves a capture Wireshark reads.
    out_.flush();
}

}  // namespace slmp::station
