// UDP specifics: one datagram in, one datagram back to the sender's address
// and port; datagrams that are not frames are dropped silently.
#include <catch2/catch.hpp>

#include <chrono>

#include "frames.hpp"
#include "link.hpp"
#include "sim_process.hpp"
#include "sockets.hpp"

using namespace slmp::test;
namespace client = slmp::protocol::client;
using namespace std::chrono_literals;

namespace {

const Wire kBin3{FrameKind::E3, Codec::Binary, 0};
const Wire kAsc4{FrameKind::E4, Codec::Ascii, 0x4321};

Bytes loopback_request(const Wire& w, const std::string& data) {
    return client::build_request(w.options(), 0x0619, 0x0000, [&](slmp::protocol::FieldWriter& fw) {
        fw.u16(static_cast<std::uint16_t>(data.size()));
        fw.raw(text(data));
    });
}
Bytes loopback_response(const Wire& w, const std::string& data) {
    Bytes count = w.codec == Codec::Binary ? Bytes{std::uint8_t(data.size()), 0}
                                           : text(hex_digits(static_cast<std::uint32_t>(data.size()), 4));
    return expected_response(w, concat({count, text(data)}));
}

}  // namespace

TEST_CASE("UDP: each response goes back to the port that sent the request", "[udp]") {
    SimProcess sim;
    UdpClient a, b;
    REQUIRE(a.local_port() != b.local_port());
    // Interleaved: a, b, then a again.
    REQUIRE(a.send_to(sim.udp_port(), loopback_request(kBin3, "AAAA")));
    REQUIRE(b.send_to(sim.udp_port(), loopback_request(kAsc4, "BBBBBB")));
    std::uint16_t from = 0;
    auto ra = a.receive(kReplyTimeout, &from);
    REQUIRE(ra.has_value());
    CHECK(show(*ra) == show(loopback_response(kBin3, "AAAA")));
    CHECK(from == sim.udp_port());
    auto rb = b.receive(kReplyTimeout, &from);
    REQUIRE(rb.has_value());
    CHECK(show(*rb) == show(loopback_response(kAsc4, "BBBBBB")));
    CHECK(from == sim.udp_port());

    REQUIRE(a.send_to(sim.udp_port(), loopback_request(kBin3, "A2")));
    auto ra2 = a.receive();
    REQUIRE(ra2.has_value());
    CHECK(show(*ra2) == show(loopback_response(kBin3, "A2")));
    // b got nothing more: its next datagram is the answer to its own next request.
    REQUIRE(b.send_to(sim.udp_port(), loopback_request(kBin3, "B2")));
    auto rb2 = b.receive();
    REQUIRE(rb2.has_value());
    CHECK(show(*rb2) == show(loopback_response(kBin3, "B2")));
}

TEST_CASE("UDP: a garbage datagram is ignored and the next valid one is answered", "[udp][garbage]") {
    SimProcess sim;
    UdpClient c;
    for (const auto& garbage : {hex("00 01 02 03"), text("hello"), hex("D0 00 00 FF FF 03 00 02 00 00 00"), hex("FF")}) {
        INFO("garbage " << show(garbage));
        REQUIRE(c.send_to(sim.udp_port(), garbage));
        REQUIRE(c.send_to(sim.udp_port(), loopback_request(kBin3, "OK")));
        auto reply = c.receive();
        REQUIRE(reply.has_value());
        CHECK(show(*reply) == show(loopback_response(kBin3, "OK")));
    }
}

TEST_CASE("UDP: a datagram holding a truncated frame gets no answer but the next one does", "[udp][garbage]") {
    SimProcess sim;
    UdpClient c;
    auto whole = loopback_request(kBin3, "TRUNC");
    REQUIRE(c.send_to(sim.udp_port(), Bytes(whole.begin(), whole.end() - 3)));
    REQUIRE(c.send_to(sim.udp_port(), loopback_request(kBin3, "NEXT")));
    auto reply = c.receive();
    REQUIRE(reply.has_value());
    CHECK(show(*reply) == show(loopback_response(kBin3, "NEXT")));
}

TEST_CASE("UDP: device writes over UDP are seen over TCP", "[udp][tcp][device]") {
    SimProcess sim;
    UdpLink udp(sim.udp_port());
    TcpLink tcp(sim.tcp_port());
    std::vector<std::uint16_t> values = {0x0102, 0x0304};
    REQUIRE(show(udp.exchange(client::write_words(kAsc4.options(), addr("W1F0"), values))) ==
            show(expected_response(kAsc4, {})));
    CHECK(show(tcp.exchange(client::read_words(kBin3.options(), addr("W1F0"), 2))) ==
          show(expected_response(kBin3, word_data(kBin3, values))));
}
