// Own network and station numbers over the wire (docs/end-codes.md): with
// --network-no/--station-no a request addressed to them is served, another
// station gets 4A02, another network 4A01; 00/FF is still the own station.
#include <catch2/catch.hpp>

#include "frames.hpp"
#include "sim_process.hpp"
#include "sockets.hpp"

using namespace slmp::test;

TEST_CASE("Own network and station numbers (--network-no, --station-no) are served, others get 4A01 or 4A02", "[route][tcp]") {
    SimProcess sim(with_args({"--network-no", "18", "--station-no", "5"}));
    auto c = TcpClient::open(sim.tcp_port());
    auto exchange = [&](const std::string& request) {
        REQUIRE(c.send(hex(request)));
        Bytes frame;
        std::string why;
        if (!c.response(&frame, kReplyTimeout, &why)) return "<no response: " + why + ">";
        return show(frame);
    };
    // 0401 D100 ×1 to network 12h station 05h, then 12h/06h, 13h/05h, 00/FF.
    CHECK(exchange("50 00 12 05 FF 03 00 0C 00 10 00 01 04 00 00 64 00 00 A8 01 00") ==
          show(hex("D0 00 12 05 FF 03 00 04 00 00 00 00 00")));
    CHECK(exchange("50 00 12 06 FF 03 00 0C 00 10 00 01 04 00 00 64 00 00 A8 01 00") ==
          show(hex("D0 00 12 06 FF 03 00 0B 00 02 4A 12 06 FF 03 00 01 04 00 00")));
    CHECK(exchange("50 00 13 05 FF 03 00 0C 00 10 00 01 04 00 00 64 00 00 A8 01 00") ==
          show(hex("D0 00 13 05 FF 03 00 0B 00 01 4A 13 05 FF 03 00 01 04 00 00")));
    CHECK(exchange("50 00 00 FF FF 03 00 0C 00 10 00 01 04 00 00 64 00 00 A8 01 00") ==
          show(hex("D0 00 00 FF FF 03 00 04 00 00 00 00 00")));
}
