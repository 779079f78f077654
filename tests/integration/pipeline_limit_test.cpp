// Commands per connection (SLMP Reference Manual §3.3; docs/end-codes.md): a pipelined burst
// over a real TCP socket. On the R08CPU profile (buffer 32) one connection may
// have 1 + 32 = 33 requests waiting; the 34th and later of the burst get CEE0,
// in order, with their serials, and execute nothing. With two connections open
// the share is 1 + 32 ÷ 2 = 17. Every wait is for a response, never a clock.
#include <catch2/catch.hpp>

#include "frames.hpp"
#include "sim_process.hpp"
#include "sockets.hpp"

using namespace slmp::test;
namespace client = slmp::protocol::client;

namespace {

std::string next(TcpClient& c) {
    Bytes frame;
    std::string why;
    if (!c.response(&frame, kReplyTimeout, &why)) return "<no response: " + why + ">";
    return show(frame);
}

// `count` 4E writes of D(i) = i + 1, serials 0x0100 + i, sent in one write.
std::vector<Wire> send_burst(TcpClient& c, Codec codec, std::uint16_t count) {
    Bytes burst;
    std::vector<Wire> wires;
    for (std::uint16_t i = 0; i < count; ++i) {
        Wire w{FrameKind::E4, codec, static_cast<std::uint16_t>(0x0100 + i)};
        wires.push_back(w);
        auto r = client::write_words(w.options(), addr("D" + std::to_string(i)), std::vector<std::uint16_t>{std::uint16_t(i + 1)});
        burst.insert(burst.end(), r.begin(), r.end());
    }
    REQUIRE(c.send(burst));
    return wires;
}

void expect_answers(TcpClient& c, const std::vector<Wire>& wires, std::size_t served) {
    for (std::size_t i = 0; i < wires.size(); ++i) {
        INFO("request " << i);
        const auto& w = wires[i];
        if (i < served) CHECK(next(c) == show(expected_response(w, {})));
        else CHECK(next(c) == show(expected_response(w, error_info(w, 0x1401, 0x0000), 0xCEE0)));
    }
}

std::uint16_t read_word(TcpClient& c, const std::string& device) {
    Wire w{FrameKind::E3, Codec::Binary, 0};
    REQUIRE(c.send(client::read_words(w.options(), addr(device), 1)));
    Bytes frame;
    REQUIRE(c.response(&frame));
    REQUIRE(frame.size() == 13);
    return static_cast<std::uint16_t>(frame[11] | frame[12] << 8);
}

}  // namespace

TEST_CASE("Pipelining past the commands-per-connection limit answers CEE0 (R08CPU: 1 + 32 / connections)",
          "[pipeline][tcp][4e]") {
    SimProcess sim;
    SECTION("one connection: 33 served, the rest CEE0, binary and ASCII") {
        // One connection for both codecs (the port detects the code per message):
        // a second one opened after closing the first could be counted while the
        // server has not yet seen the close, halving the share.
        auto c = TcpClient::open(sim.tcp_port());
        for (auto codec : {Codec::Binary, Codec::Ascii}) {
            INFO((codec == Codec::Binary ? "binary" : "ASCII"));
            auto wires = send_burst(c, codec, 40);
            expect_answers(c, wires, 33);
            CHECK(read_word(c, "D32") == 33);
            CHECK(read_word(c, "D33") == 0);   // refused: not written
            CHECK(read_word(c, "D39") == 0);
        }
    }
    SECTION("two connections open: 17 served") {
        auto other = TcpClient::open(sim.tcp_port());
        CHECK(read_word(other, "D0") == 0);   // the server has the second connection now
        auto c = TcpClient::open(sim.tcp_port());
        CHECK(read_word(c, "D0") == 0);
        auto wires = send_burst(c, Codec::Binary, 20);
        expect_answers(c, wires, 17);
    }
    SECTION("requests that wait for their answers are never refused") {
        auto c = TcpClient::open(sim.tcp_port());
        for (int round = 0; round < 50; ++round) CHECK(read_word(c, "D0") == 0);
    }
}
