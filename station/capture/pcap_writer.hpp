// Recordings as a classic libpcap capture (--record-pcap FILE) that Wireshark
// and tshark open and dissect: every exchange becomes packets with synthetic
// IP (v4 or v6) and TCP or UDP headers between the client's real address and
// port and the simulator's port, so "Follow TCP stream" and the SLMP
// dissector work. The bytes are the ones the JSON-lines recording holds; the
// headers around them are made up (LINKTYPE_RAW, no Ethernet):
//   - a TCP connection starts with SYN, SYN-ACK, ACK and ends with FIN/ACK
//     from the side that closed (or RST for a reset); sequence numbers
//     advance by the payload, so Wireshark reassembles split frames;
//   - checksums (IPv4 header, TCP, UDP) are correct, so no "bad checksum";
//   - the simulator's address is its --bind address; for a wildcard bind it
//     is the loopback address when the client is local, else 0.0.0.0 / ::.
// A response split or coalesced by a fault is written as one segment: the
// capture shows what was said, not how the writes were cut.
#pragma once

#include <array>
#include <chrono>
#include <cstdint>
#include <filesystem>
#include <fstream>
#include <map>
#include <span>
#include <string>
#include <vector>

#include "station/capture/recorder.hpp"

namespace slmp::station {

class PcapWriter : public Recorder {
public:
    // Truncates `file` and writes the global header; throws config::ConfigError
    // when it cannot be written. `wall_start` is the wall-clock time at `start`
    // (packets carry wall-clock timestamps, as a real capture does).
    PcapWriter(const std::filesystem::path& file, const std::string& server_address, TimePoint start,
               std::chrono::system_clock::time_point wall_start);

    void opened(TimePoint at, const RecordedLink& link) override;
    void exchange(TimePoint at, const RecordedLink& link, std::span<const std::uint8_t> request,
                  const std::vector<std::uint8_t>* response, const std::vector<std::string>& faults,
                  const std::string& named) override;
    void closed(TimePoint at, const RecordedLink& link, const std::string& why) override;

    // An IP address and port as the packets carry them (v4 in the first 4 bytes).
    struct Endpoint {
        bool v6 = false;
        std::array<std::uint8_t, 16> address{};
        std::uint16_t port = 0;
    };

private:
    struct Flow {                   // one TCP connection's next sequence numbers
        std::uint32_t client = 0;
        std::uint32_t server = 0;
    };
    struct Pair {
        Endpoint client, server;
    };

    Pair endpoints(const RecordedLink& link) const;
    Flow& flow(TimePoint at, const RecordedLink& link, const Pair& ends);
    void tcp(TimePoint at, const Pair& ends, bool from_client, std::uint8_t flags, std::uint32_t seq, std::uint32_t ack,
             std::span<const std::uint8_t> payload = {});
    void udp(TimePoint at, const Pair& ends, bool from_client, std::span<const std::uint8_t> payload);
    void packet(TimePoint at, const Endpoint& from, const Endpoint& to, std::uint8_t protocol,
                std::vector<std::uint8_t> transport_header, std::span<const std::uint8_t> payload);

    std::ofstream out_;
    std::string server_address_;
    TimePoint start_;
    std::chrono::system_clock::time_point wall_start_;
    std::map<std::uint64_t, Flow> flows_;   // open TCP connections by id
    std::uint16_t ip_id_ = 0;               // IPv4 identification, one per packet
};

}  // namespace slmp::station
