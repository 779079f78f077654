// --record-pcap: the capture's bytes for a known session, checked against
// headers computed independently (by a few lines of Python's struct module,
// not by this code), so a checksum or byte-order slip shows (docs/scenarios.md
// "Record & replay").
#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <iterator>

#include "scenarios/recording.hpp"
#include "station/capture/pcap_writer.hpp"
#include "support/fixtures.hpp"
#include "support/scenario_fixtures.hpp"

using namespace slmp;
using namespace slmp::test;

namespace {

std::filesystem::path temp_file(const std::string& name) {
    return std::filesystem::temp_directory_path() / ("slmp-unit-" + std::to_string(::getpid()) + "-" + name);
}

Bytes unhex(std::string_view text) { return *scenarios::from_hex(text); }

Bytes slurp(const std::filesystem::path& file) {
    std::ifstream in(file, std::ios::binary);
    return Bytes(std::istreambuf_iterator<char>(in), {});
}

Bytes slice(const Bytes& b, std::size_t at, std::size_t n) {
    REQUIRE(at + n <= b.size());
    return Bytes(b.begin() + static_cast<long>(at), b.begin() + static_cast<long>(at + n));
}

const auto kWall = std::chrono::system_clock::time_point(std::chrono::seconds(1700000000));
const Bytes kRequest = unhex("500000ffff03000c00100001040000640000a80100");   // 21 bytes
const Bytes kResponse = unhex("d00000ffff0300040000002a00");                 // 13 bytes

}  // namespace

TEST_CASE("pcap: a TCP session as SYN, data with advancing sequence numbers, FIN", "[scenario][pcap]") {
    auto file = temp_file("tcp.pcap");
    {
        // A wildcard bind: a loopback client must have reached 127.0.0.1.
        station::PcapWriter w(file, "0.0.0.0", at(0), kWall);
        const station::RecordedLink link{7, scenarios::Transport::Tcp, "127.0.0.1:50312", 5000};
        w.opened(at(1.5), link);
        w.exchange(at(2), link, kRequest, &kResponse, {}, "");
        w.closed(at(3), link, "closed by the client");
    }
    auto pcap = slurp(file);
    // Global header: magic a1b2c3d4 (little-endian, microseconds), v2.4, snaplen 262144, LINKTYPE_RAW.
    CHECK(hex(slice(pcap, 0, 24)) == hex(unhex("d4c3b2a1" "0200" "0400" "00000000" "00000000" "00000400" "65000000")));
    // SYN at 1700000000.001500 s: record header, IPv4 (checksum 3ccd), TCP (checksum c9c8).
    CHECK(hex(slice(pcap, 24, 16)) == hex(unhex("00f15365dc0500002800000028000000")));
    CHECK(hex(slice(pcap, 40, 40)) ==
          hex(unhex("450000280001400040063ccd7f0000017f000001c488138810000007000000005002ffffc9c80000")));
    // SYN-ACK and ACK, then the request: seq = ISN + 1, PSH|ACK, payload after the headers.
    std::size_t request_at = 24 + 3 * (16 + 40);
    CHECK(hex(slice(pcap, request_at + 8, 8)) == hex(unhex("3d0000003d000000")));   // 61 bytes captured
    CHECK(hex(slice(pcap, request_at + 16, 40)) ==
          hex(unhex("4500003d0004400040063cb57f0000017f000001c488138810000008200000085018ffffad0e0000")));
    CHECK(slice(pcap, request_at + 56, kRequest.size()) == kRequest);
    // The response: from port 5000, its ack advanced by the request's 21 bytes.
    std::size_t response_at = request_at + 16 + 61;
    CHECK(hex(slice(pcap, response_at + 16, 40)) ==
          hex(unhex("450000350005400040063cbc7f0000017f0000011388c488200000081000001d5018ffffd9550000")));
    CHECK(slice(pcap, response_at + 56, kResponse.size()) == kResponse);
    // FIN|ACK from the client, FIN|ACK from the server, the last ACK: three more packets, then the end.
    std::size_t fin_at = response_at + 16 + 53;
    REQUIRE(pcap.size() == fin_at + 3 * (16 + 40));
    CHECK(pcap[fin_at + 16 + 33] == 0x11);              // FIN|ACK
    CHECK(pcap[fin_at + 56 + 16 + 33] == 0x11);
    CHECK(pcap[fin_at + 2 * 56 + 16 + 33] == 0x10);     // ACK
    std::filesystem::remove(file);
}

TEST_CASE("pcap: a UDP exchange between the client's address and the bound address", "[scenario][pcap]") {
    auto file = temp_file("udp.pcap");
    {
        station::PcapWriter w(file, "192.168.3.10", at(0), kWall);
        w.exchange(at(1), {3, scenarios::Transport::Udp, "10.0.0.5:40000", 5001}, kRequest, nullptr, {}, "");
    }
    auto pcap = slurp(file);
    REQUIRE(pcap.size() == 24 + 16 + 28 + kRequest.size());   // no answer: one datagram
    CHECK(hex(slice(pcap, 40, 28)) == hex(unhex("450000310001400040116d040a000005c0a8030a9c401389001d85ad")));
    CHECK(slice(pcap, 68, kRequest.size()) == kRequest);
    std::filesystem::remove(file);
}

TEST_CASE("pcap: an unwritable path names the option", "[scenario][pcap]") {
    CHECK_THROWS_WITH(station::PcapWriter("/nonexistent-dir/x.pcap", "0.0.0.0", at(0), kWall),
                      Catch::Contains("--record-pcap"));
}
