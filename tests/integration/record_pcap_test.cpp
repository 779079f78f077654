// --record-pcap: a capture of a real session that Wireshark can dissect. The
// test reads the file with its own small pcap parser (no tshark needed):
// valid IPv4 header checksums, the client's real port and the simulator's
// ports, TCP sequence numbers that advance by the payload (so streams
// reassemble), and the request and response bytes of a TCP and a UDP exchange
// (docs/scenarios.md "Record & replay").
#include <catch2/catch.hpp>

#include <arpa/inet.h>
#include <netinet/in.h>
#include <sys/socket.h>

#include <map>

#include "scenario_support.hpp"

using namespace slmp::test;
using namespace std::chrono_literals;

namespace {

struct Packet {
    std::uint8_t protocol = 0;   // 6 TCP, 17 UDP
    std::uint16_t from_port = 0, to_port = 0;
    std::uint32_t seq = 0;
    std::uint8_t flags = 0;
    bool ip_checksum_ok = false;
    Bytes payload;
};

std::uint32_t le32(const Bytes& b, std::size_t at) {
    return b[at] | b[at + 1] << 8 | b[at + 2] << 16 | static_cast<std::uint32_t>(b[at + 3]) << 24;
}
std::uint16_t be16(const Bytes& b, std::size_t at) { return static_cast<std::uint16_t>(b[at] << 8 | b[at + 1]); }
std::uint32_t be32(const Bytes& b, std::size_t at) { return static_cast<std::uint32_t>(be16(b, at)) << 16 | be16(b, at + 2); }

// Parses a classic little-endian pcap of LINKTYPE_RAW IPv4 packets.
std::vector<Packet> read_pcap(const Bytes& file) {
    REQUIRE(file.size() >= 24);
    REQUIRE(le32(file, 0) == 0xA1B2C3D4);   // microsecond timestamps, little-endian
    REQUIRE(le32(file, 20) == 101);         // LINKTYPE_RAW
    std::vector<Packet> packets;
    for (std::size_t at = 24; at < file.size();) {
        REQUIRE(at + 16 <= file.size());
        auto length = le32(file, at + 8);
        REQUIRE(le32(file, at + 12) == length);
        REQUIRE(at + 16 + length <= file.size());
        Bytes ip(file.begin() + static_cast<long>(at + 16), file.begin() + static_cast<long>(at + 16 + length));
        at += 16 + length;
        REQUIRE(ip.size() >= 20);
        REQUIRE(ip[0] == 0x45);
        REQUIRE(be16(ip, 2) == ip.size());
        std::uint32_t sum = 0;
        for (std::size_t i = 0; i < 20; i += 2) sum += be16(ip, i);
        while (sum >> 16) sum = (sum & 0xFFFF) + (sum >> 16);
        Packet p;
        p.ip_checksum_ok = sum == 0xFFFF;
        p.protocol = ip[9];
        p.from_port = be16(ip, 20);
        p.to_port = be16(ip, 22);
        std::size_t data = 20;
        if (p.protocol == 6) {
            p.seq = be32(ip, 24);
            p.flags = ip[33];
            data += (ip[32] >> 4) * 4u;
        } else {
            REQUIRE(p.protocol == 17);
            data += 8;
        }
        p.payload.assign(ip.begin() + static_cast<long>(data), ip.end());
        packets.push_back(std::move(p));
    }
    return packets;
}

std::uint16_t local_port(int fd) {
    sockaddr_in a{};
    socklen_t n = sizeof a;
    ::getsockname(fd, reinterpret_cast<sockaddr*>(&a), &n);
    return ntohs(a.sin_port);
}

bool contains(const Bytes& haystack, const Bytes& needle) {
    return std::search(haystack.begin(), haystack.end(), needle.begin(), needle.end()) != haystack.end();
}

}  // namespace

TEST_CASE("record pcap: a TCP and a UDP exchange in a capture Wireshark can reassemble", "[scenario][pcap]") {
    TempDir dir;
    auto capture = dir.path() / "session.pcap";
    auto request = write_request(kBinary3E, "D100", {0x1234});
    auto read = read_request(kBinary3E, "D100");
    Bytes tcp_answer, udp_answer;
    std::uint16_t tcp_port = 0, udp_port = 0, tcp_client = 0, udp_client = 0;
    {
        // JSON lines and pcap at once: both recorders are fed.
        SimProcess sim(with_args({"--record-pcap", capture.string(), "--record", (dir.path() / "s.jsonl").string(), "--no-http"}));
        tcp_port = sim.tcp_port();
        udp_port = sim.udp_port();
        {
            TcpLink tcp(tcp_port);
            tcp_client = local_port(tcp.client().fd());
            REQUIRE_FALSE(tcp.exchange(request).empty());
            tcp_answer = tcp.exchange(read);
        }
        UdpClient udp;
        udp_client = udp.local_port();
        REQUIRE(udp.send_to(udp_port, read));
        udp_answer = udp.receive().value_or(Bytes{});
        // The FIN is captured when the simulator notices the close: wait for the
        // JSON-lines recording (fed at the same moment) to show it.
        auto deadline = std::chrono::steady_clock::now() + 10s;
        while (read_text(dir.path() / "s.jsonl").find(R"("event":"close")") == std::string::npos &&
               std::chrono::steady_clock::now() < deadline)
            std::this_thread::sleep_for(20ms);
        CHECK(sim.stop() == 0);
    }
    REQUIRE(tcp_answer == expected_response(kBinary3E, word_data(kBinary3E, {0x1234})));
    REQUIRE(udp_answer == tcp_answer);
    CHECK(lines_of(read_text(dir.path() / "s.jsonl")).size() >= 4);

    auto packets = read_pcap([&] {
        auto text = read_text(capture);
        return Bytes(text.begin(), text.end());
    }());
    Bytes to_server, to_client, udp_in, udp_out;
    std::map<bool, std::uint32_t> next_seq;   // per direction (true: from the client)
    bool syn = false, fin = false;
    for (const auto& p : packets) {
        CHECK(p.ip_checksum_ok);
        if (p.protocol == 17) {
            if (p.from_port == udp_client && p.to_port == udp_port) udp_in.insert(udp_in.end(), p.payload.begin(), p.payload.end());
            if (p.from_port == udp_port && p.to_port == udp_client) udp_out.insert(udp_out.end(), p.payload.begin(), p.payload.end());
            continue;
        }
        bool from_client = p.from_port == tcp_client && p.to_port == tcp_port;
        bool from_server = p.from_port == tcp_port && p.to_port == tcp_client;
        if (!from_client && !from_server) continue;
        if (p.flags & 0x02) {   // SYN: the sequence starts here and counts one
            syn = true;
            next_seq[from_client] = p.seq + 1;
            continue;
        }
        INFO("flags " << int(p.flags) << (from_client ? " from the client" : " from the server"));
        REQUIRE(next_seq.count(from_client));
        CHECK(p.seq == next_seq[from_client]);   // no gap, no overlap: Wireshark reassembles
        next_seq[from_client] += static_cast<std::uint32_t>(p.payload.size()) + ((p.flags & 0x01) ? 1 : 0);
        fin = fin || (p.flags & 0x01);
        (from_client ? to_server : to_client).insert((from_client ? to_server : to_client).end(), p.payload.begin(), p.payload.end());
    }
    CHECK(syn);
    CHECK(fin);
    Bytes both_requests = request;
    both_requests.insert(both_requests.end(), read.begin(), read.end());
    CHECK(show(to_server) == show(both_requests));
    CHECK(contains(to_client, tcp_answer));
    CHECK(show(udp_in) == show(read));
    CHECK(show(udp_out) == show(udp_answer));
}
