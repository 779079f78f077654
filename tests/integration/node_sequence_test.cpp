// The parameter write sequence of the node commands (JA §4.2.1.8,
// docs/nodes.md) against the real slmp-sim over UDP and TCP: two UDP clients
// of one port are two clients (the sender's address and port), every other
// request is refused CEE0 while a write runs, and the 10 s timeout runs on the
// station's clock (--clock frozen, stepped through the HTTP API).
#include <catch2/catch.hpp>

#include "ask.hpp"
#include "http_client.hpp"
#include "sim_process.hpp"

using namespace slmp::test;

namespace {

const std::string kProfile = R"({"name": "R08CPU-NODE", "extends": "R08CPU", "node_commands": true,
    "description": "an SLMP-compatible device with an R08CPU's device memory"})";

// Binary 3E requests to the own station, monitoring timer 0010.
const Bytes kStart = hex("50 00 00 FF FF 03 00 06 00 10 00 35 0E 00 00");
const Bytes kSet1234 = hex("50 00 00 FF FF 03 00 0E 00 10 00 34 0E 00 00 01 00 01 00 02 00 34 12");
const Bytes kEnd = hex("50 00 00 FF FF 03 00 06 00 10 00 36 0E 00 00");
const Bytes kGet1 = hex("50 00 00 FF FF 03 00 0A 00 10 00 33 0E 00 00 01 00 01 00");
const Bytes kReadD0 = hex("50 00 00 FF FF 03 00 0C 00 10 00 01 04 00 00 00 00 00 A8 01 00");

const std::string kOk = show(hex("D0 00 00 FF FF 03 00 02 00 00 00"));
std::string refused(const std::string& code, const std::string& command) {
    return show(hex("D0 00 00 FF FF 03 00 0B 00 " + code + " 00 FF FF 03 00 " + command + " 00 00"));
}
std::string parameter_1(const std::string& value) {
    return show(hex("D0 00 00 FF FF 03 00 0A 00 00 00 01 00 01 00 02 00 " + value));
}

void step_clock(std::uint16_t http_port, int ms) {
    REQUIRE(http(http_port, "POST", "/api/clock/step", R"({"ms": )" + std::to_string(ms) + "}").status == 200);
}

}  // namespace

TEST_CASE("node parameter write: two UDP clients, CEE0 for others, the 10 s timeout on the station's clock", "[node]") {
    TempDir dir;
    SimOptions options;
    options.config_json = R"({"profile": ")" + dir.write("node.json", kProfile).string() + R"("})";
    options.args = {"--clock", "frozen"};
    SimProcess sim(options);
    const auto udp = sim.udp_port();
    UdpClient a, b;

    CHECK(show(ask(a, udp, kStart)) == kOk);
    CHECK(show(ask(b, udp, kSet1234)) == refused("E0 CE", "34 0E"));   // another client (another source port)
    CHECK(show(ask(b, udp, kReadD0)) == refused("E0 CE", "01 04"));    // every other command
    CHECK(show(ask(a, udp, kSet1234)) == kOk);
    step_clock(sim.http_port(), 9000);
    CHECK(show(ask(b, udp, kGet1)) == refused("E0 CE", "33 0E"));      // 9 s after the Set: still under way
    step_clock(sim.http_port(), 1500);
    CHECK(show(ask(a, udp, kEnd)) == refused("31 CF", "36 0E"));       // timed out: back in the normal state
    CHECK(show(ask(b, udp, kGet1)) == parameter_1("00 00"));           // the held value was dropped
    CHECK(show(ask(b, udp, kReadD0)) == show(hex("D0 00 00 FF FF 03 00 04 00 00 00 00 00")));

    // Over TCP: the whole sequence reflects the value.
    auto tcp = TcpClient::open(sim.tcp_port());
    CHECK(show(ask(tcp, kStart)) == kOk);
    CHECK(show(ask(tcp, kSet1234)) == kOk);
    CHECK(show(ask(tcp, kEnd)) == kOk);
    CHECK(show(ask(a, udp, kGet1)) == parameter_1("34 12"));
}
