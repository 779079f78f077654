// The front ends' address names in the HTTP API and their unit state in
// snapshots and the state directory, against the real binary
// (docs/api.md "Devices", "Snapshots"; docs/hostlink.md; docs/jw51cm.md):
// a value written through the front end is read by its own name over HTTP and
// the other way round; the host link's RE/WE image and the JW unit's mode,
// system memory, program and clock come back after a restore and a restart.
#include <catch2/catch.hpp>

#include <string>

#include "frames.hpp"
#include "http_client.hpp"
#include "sim_process.hpp"
#include "sockets.hpp"

using namespace slmp::test;
using nlohmann::json;

namespace {

std::string fcs(const std::string& body) {
    unsigned x = 0;
    for (unsigned char c : body) x ^= c;
    static constexpr char digits[] = "0123456789ABCDEF";
    return {digits[x >> 4], digits[x & 0xF]};
}
std::string record(const std::string& body) { return body + fcs(body) + "*\r"; }
std::string ask(TcpClient& client, const std::string& request) {
    REQUIRE(client.send(request));
    std::string got;
    while (got.empty() || got.back() != '\r') {
        auto more = client.read_exactly(1);
        if (more.empty()) FAIL("no whole host-link record; got: " << got);
        got.push_back(static_cast<char>(more[0]));
    }
    return got;
}

Bytes jw(std::uint8_t id, Bytes after_id) {
    Bytes frame(40, 0);
    frame.push_back(id);
    frame.push_back(0x00);
    frame.insert(frame.end(), after_id.begin(), after_id.end());
    return frame;
}
Bytes request(Bytes after_id) { return jw(0x47, std::move(after_id)); }
Bytes response(Bytes after_id) { return jw(0x45, std::move(after_id)); }
Bytes ask(TcpClient& client, const Bytes& after_id, std::size_t answer_bytes) {
    REQUIRE(client.send(request(after_id)));
    return client.read_exactly(answer_bytes);
}

SimOptions station(const std::string& config, std::vector<std::string> args = {}) {
    SimOptions options;
    options.tcp_ports = 0;
    options.udp_ports = 0;
    options.config_json = config;
    options.args = std::move(args);
    return options;
}
const std::string kLadderMotion = R"({"kind": "ladder-motion", "hostlink": {"tcp_port": 0}})";
const std::string kSharpJw = R"({"kind": "sharp-jw", "jw51cm": {"tcp_port": 0, "udp_port": null}})";

std::uint16_t hostlink_port(const SimProcess& sim) { return sim.ready().at("hostlink").at(0).get<std::uint16_t>(); }
std::uint16_t jw_tcp(const SimProcess& sim) { return sim.ready().at("jw51cm").at("tcp").at(0).get<std::uint16_t>(); }

json get(const SimProcess& sim, const std::string& target) { return http_get(sim.http_port(), target).json(); }

}  // namespace

TEST_CASE("HTTP host-link names: CIO, HR, DM, VR both ways, bad names refused naming the form", "[hostlink][frontend][http]") {
    SimProcess sim(station(kLadderMotion));
    auto client = TcpClient::open(hostlink_port(sim));

    // Host link writes, HTTP reads by the host link's name (and the device it maps to).
    CHECK(ask(client, record("@00WD0100ABCD1234")) == record("@00WD00"));
    auto dm = get(sim, "/api/devices/DM0100?count=2");
    CHECK(dm["device"] == "D100");
    CHECK(dm["values"] == json({0xABCD, 0x1234}));
    CHECK(get(sim, "/api/devices/dm100")["values"] == json({0xABCD}));
    CHECK(ask(client, record("@00WR00101234")) == record("@00WR00"));
    auto cio = get(sim, "/api/devices/CIO0010");
    CHECK(cio["device"] == "M160");
    CHECK(cio["as"] == "words");
    CHECK(cio["values"] == json({0x1234}));
    CHECK(ask(client, record("@00WV000312345678")) == record("@00WV00"));
    auto vr = get(sim, "/api/devices/VR3");
    CHECK(vr["as"] == "dwords");
    CHECK(vr["values"] == json({0x12345678}));

    // HTTP writes by name, the host link reads.
    CHECK(http_put(sim.http_port(), "/api/devices/HR5", R"({"values": [4660]})").status == 200);
    CHECK(ask(client, record("@00RH00050001")) == record("@00RH001234"));
    CHECK(http_put(sim.http_port(), "/api/devices/VR7", R"({"values": [2882400018]})").status == 200);
    CHECK(ask(client, record("@00RV00070001")) == record("@00RV00ABCDEF12"));
    CHECK(http_put(sim.http_port(), "/api/devices/DM0200", R"({"values": [1, 2]})").json()["device"] == "D200");
    CHECK(ask(client, record("@00RD02000002")) == record("@00RD0000010002"));

    auto past = http_get(sim.http_port(), "/api/devices/DM9999");
    CHECK(past.status == 400);
    CHECK(past.error() == "DM9999 is past the data memory (DM): DM0–DM6655 (hostlink.areas.DM.size sets its size)");
    auto form = http_get(sim.http_port(), "/api/devices/HR1A");
    CHECK(form.status == 400);
    CHECK(form.error() == "HR1A: a host-link HR address is HR and a decimal number (HR0100)");
    CHECK(http_get(sim.http_port(), "/api/devices/D100").json()["values"] == json({0xABCD}));   // MELSEC names still work
}

TEST_CASE("HTTP JW names: relays, registers and file addresses in octal, both ways", "[jw51cm][frontend][http]") {
    SimProcess sim(station(kSharpJw));
    auto client = TcpClient::open(jw_tcp(sim));
    CHECK(ask(client, {0xF9, 0x01}, 45) == response({0xF9, 0x00, 0x01}));

    // JW writes registers 09000-09003, HTTP reads 09000 and 09002 (D0, D1).
    CHECK(ask(client, {0x34, 0x00, 0x00, 0x08, 0x04, 0x00, 0x12, 0x34, 0x56, 0x78}, 49) ==
          response({0x34, 0x00, 0x00, 0x00, 0x08, 0x04, 0x00}));
    auto reg = get(sim, "/api/devices/09000?count=2");
    CHECK(reg["device"] == "D0");
    CHECK(reg["values"] == json({0x3412, 0x7856}));
    CHECK(get(sim, "/api/devices/09002")["values"] == json({0x7856}));
    // Register 19000 is byte 0o5000: D256.
    CHECK(get(sim, "/api/devices/19000")["device"] == "D256");

    // HTTP sets relay 04033 (M2075): JW relay monitor 20 sees it, byte 0o403 bit 3.
    auto relay = http_put(sim.http_port(), "/api/devices/04033", R"({"values": [1]})").json();
    CHECK(relay["device"] == "M2075");
    CHECK(ask(client, {0x20, 0x00, 0x03, 0x01, 0x03}, 49) == response({0x20, 0x00, 0x00, 0x03, 0x01, 0x03, 0x01}));

    // HTTP writes file 1 byte 0o200 (ZR64), JW reads file 1 there: the low byte first.
    auto file = http_put(sim.http_port(), "/api/devices/F1:0200", R"({"values": [43981]})").json();
    CHECK(file["device"] == "ZR64");
    CHECK(ask(client, {0x24, 0x01, 0x80, 0x00, 0x02, 0x00}, 52) ==
          response({0x24, 0x00, 0x01, 0x80, 0x00, 0x02, 0x00, 0xCD, 0xAB}));
    CHECK(get(sim, "/api/devices/F0:4000")["device"] == "D0");

    auto odd = http_get(sim.http_port(), "/api/devices/09001");
    CHECK(odd.status == 400);
    CHECK(odd.error() == "09001 is the high byte of D0; name the even address before it "
                         "(a word holds two bytes, the lower address in the low byte)");
    auto octal = http_get(sim.http_port(), "/api/devices/04039");
    CHECK(octal.status == 400);
    CHECK(octal.error() == "04039: JW relay numbers are octal (digits 0–7, 00000–15777)");
    auto register_form = http_get(sim.http_port(), "/api/devices/09800");
    CHECK(register_form.status == 400);
    CHECK(register_form.error() == "09800: a JW register is N9ooo with ooo in octal (09000–99777)");
    auto past = http_get(sim.http_port(), "/api/devices/F1:40000");
    CHECK(past.status == 400);
    CHECK(past.error() == "F1:40000 is past the JW memory: file 1 has 16384 bytes (octal 0–37777)");
}

TEST_CASE("snapshots hold the JW unit's mode, system memory, program and clock", "[jw51cm][frontend][snapshot]") {
    SimProcess sim(station(kSharpJw));
    auto client = TcpClient::open(jw_tcp(sim));
    CHECK(ask(client, {0xF9, 0x02}, 45) == response({0xF9, 0x00, 0x02}));
    CHECK(ask(client, {0xF8, 0x01}, 45) == response({0xF8, 0x00, 0x01}));
    CHECK(ask(client, {0x54, 0x08, 0x84, 0x00, 0x02, 0x00, 0x81, 0x00}, 49) == response({0x54, 0x00, 0x08, 0x84, 0x00, 0x02, 0x00}));
    CHECK(ask(client, {0x14, 0x08, 0x00, 0x00, 0x01, 0x00, 0x00, 0x80}, 49) == response({0x14, 0x00, 0x08, 0x00, 0x00, 0x01, 0x00}));
    CHECK(ask(client, {0xB3, 0x18, 0x10, 0x00, 0x01}, 44) == response({0xB3, 0x00}));
    CHECK(ask(client, {0xB2, 0x98, 0x01, 0x23, 0x05}, 44) == response({0xB2, 0x00}));
    REQUIRE(http(sim.http_port(), "POST", "/api/snapshots", R"({"name": "unit"})").status == 201);

    // Everything changes...
    CHECK(ask(client, {0x54, 0x08, 0x84, 0x00, 0x02, 0x00, 0x00, 0x00}, 49) == response({0x54, 0x00, 0x08, 0x84, 0x00, 0x02, 0x00}));
    CHECK(ask(client, {0x14, 0x08, 0x00, 0x00, 0x01, 0x00, 0x11, 0x11}, 49) == response({0x14, 0x00, 0x08, 0x00, 0x00, 0x01, 0x00}));
    CHECK(ask(client, {0xB2, 0x05, 0x12, 0x31, 0x02}, 44) == response({0xB2, 0x00}));
    CHECK(ask(client, {0xF9, 0x00}, 45) == response({0xF9, 0x00, 0x00}));
    // ...and comes back.
    REQUIRE(http(sim.http_port(), "POST", "/api/snapshots/unit/restore", "").status == 200);
    CHECK(ask(client, {0xE9}, 45) == response({0xE9, 0x00, 0x02}));
    CHECK(ask(client, {0x44, 0x08, 0x84, 0x00, 0x02, 0x00}, 51) == response({0x44, 0x00, 0x08, 0x84, 0x00, 0x02, 0x00, 0x81, 0x00}));
    CHECK(ask(client, {0x04, 0x08, 0x00, 0x00, 0x01, 0x00}, 51) == response({0x04, 0x00, 0x08, 0x00, 0x00, 0x01, 0x00, 0x00, 0x80}));
    CHECK(ask(client, {0xA2}, 48) == response({0xA2, 0x00, 0x98, 0x01, 0x23, 0x05}));
    CHECK(ask(client, {0xA3}, 47) == response({0xA3, 0x00, 0x18, 0x10, 0x00}));
}

TEST_CASE("the state directory keeps the front ends' unit state across a restart", "[hostlink][jw51cm][frontend][persistence]") {
    TempDir state;
    const std::string config = R"({"hostlink": {"tcp_port": 0}, "jw51cm": {"tcp_port": 0, "udp_port": null}})";
    {
        SimProcess sim(station(config, {"--tcp-port", "0", "--state-dir", state.path().string()}));
        auto hl = TcpClient::open(hostlink_port(sim));
        CHECK(ask(hl, record("@00WE000012345678")) == record("@00WE00"));
        auto unit = TcpClient::open(jw_tcp(sim));
        CHECK(ask(unit, {0xF9, 0x01}, 45) == response({0xF9, 0x00, 0x01}));
        CHECK(ask(unit, {0xB3, 0x18, 0x10, 0x00, 0x01}, 44) == response({0xB3, 0x00}));
        CHECK(ask(unit, {0xB2, 0x98, 0x01, 0x23, 0x05}, 44) == response({0xB2, 0x00}));
    }   // SIGTERM: a clean shutdown saves
    REQUIRE(std::filesystem::exists(state.path() / "units.bin"));
    SimProcess sim(station(config, {"--tcp-port", "0", "--state-dir", state.path().string()}));
    auto hl = TcpClient::open(hostlink_port(sim));
    CHECK(ask(hl, record("@00RE00000002")) == record("@00RE0012345678"));
    auto unit = TcpClient::open(jw_tcp(sim));
    CHECK(ask(unit, {0xE9}, 45) == response({0xE9, 0x00, 0x01}));
    CHECK(ask(unit, {0xA2}, 48) == response({0xA2, 0x00, 0x98, 0x01, 0x23, 0x05}));
}
