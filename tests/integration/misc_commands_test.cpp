// Read Type Name (0101) and Self Test loopback (0619) against the real server,
// over TCP and UDP, binary and ASCII, 3E and 4E.
// Layouts: SLMP Reference Manual §5.6, §5.9;
// R08CPU name and code: real-CPU measurements.
#include <catch2/catch.hpp>

#include <memory>

#include "frames.hpp"
#include "link.hpp"
#include "sim_process.hpp"

using namespace slmp::test;
namespace client = slmp::protocol::client;

namespace {

const std::vector<Wire> kWires = {
    {FrameKind::E3, Codec::Binary, 0},
    {FrameKind::E3, Codec::Ascii, 0},
    {FrameKind::E4, Codec::Binary, 0x0102},
    {FrameKind::E4, Codec::Ascii, 0xFEDC},
};

void type_name_and_loopback(Link& link) {
    for (const auto& w : kWires) {
        INFO(link.name() << ", " << w.name());
        // 0101: "R08CPU" padded to 16 characters (raw in both codes), model code 4801.
        Bytes name = text("R08CPU          ");
        Bytes code = w.codec == Codec::Binary ? hex("01 48") : text("4801");
        CHECK(show(link.exchange(client::build_request(w.options(), 0x0101, 0x0000))) ==
              show(expected_response(w, concat({name, code}))));

        // 0619 with "ABCDE" (§7's example): the count and the raw characters are echoed.
        Bytes count = w.codec == Codec::Binary ? hex("05 00") : text("0005");
        Bytes body = w.codec == Codec::Binary ? hex("10 00 19 06 00 00 05 00") : text("001006190000" "0005");
        body = concat({body, text("ABCDE")});
        CHECK(show(link.exchange(request_frame(w, body))) == show(expected_response(w, concat({count, text("ABCDE")}))));

        // 0619 through the client encoder, 960 characters (the maximum).
        Bytes big;
        for (int i = 0; i < 960; ++i) big.push_back(static_cast<std::uint8_t>("0123456789ABCDEF"[i % 16]));
        auto request = client::build_request(w.options(), 0x0619, 0x0000, [&](slmp::protocol::FieldWriter& fw) {
            fw.u16(960);
            fw.raw(big);
        });
        Bytes big_count = w.codec == Codec::Binary ? hex("C0 03") : text("03C0");
        CHECK(show(link.exchange(request)) == show(expected_response(w, concat({big_count, big}))));
    }
}

}  // namespace

TEST_CASE("0101 type name and 0619 loopback over TCP", "[misc][tcp]") {
    SimProcess sim(with_args({"--profile", "R08CPU"}));
    TcpLink link(sim.tcp_port());
    type_name_and_loopback(link);
}

TEST_CASE("0101 type name and 0619 loopback over UDP", "[misc][udp]") {
    SimProcess sim(with_args({"--profile", "R08CPU"}));
    UdpLink link(sim.udp_port());
    type_name_and_loopback(link);
}

TEST_CASE("0619 with a count of zero answers an error frame and keeps the connection", "[misc][tcp][errors]") {
    SimProcess sim;
    TcpLink link(sim.tcp_port());
    const Wire b3{FrameKind::E3, Codec::Binary, 0};
    auto reply = link.exchange(request_frame(b3, hex("10 00 19 06 00 00 00 00")));
    REQUIRE(reply.size() == 20);   // 11-byte header + 9-byte error information
    CHECK(show(Bytes(reply.begin(), reply.begin() + 9)) == show(hex("D0 00 00 FF FF 03 00 0B 00")));
    CHECK(reply[9] | reply[10]);   // a non-zero end code
    CHECK(show(Bytes(reply.begin() + 11, reply.end())) == show(error_info(b3, 0x0619, 0x0000)));
    // The connection still serves.
    CHECK(show(link.exchange(request_frame(b3, hex("10 00 19 06 00 00 01 00 41"))))
          == show(expected_response(b3, hex("01 00 41"))));
}
