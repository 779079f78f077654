// The node commands 0E30-0E53 of the CC-Link Partner Association's SLMP manual
// (JA §3.12-3.14, ch. 4): the manual's worked examples byte for byte (0E30,
// 0E32 and the fixed requests of 0E35/0E36/0E3A/0E44/0E53), the layouts
// docs/nodes.md reconstructs (inferred), the parameter write sequence of JA
// §4.2.1.8 with its end codes, and the ports that refuse them (C059).
#include "devicemodel/node.hpp"
#include "support/device_commands.hpp"

using namespace slmp;
using namespace slmp::test;

namespace {

protocol::PortProfile node_port(const devicemodel::Cpu& cpu) {
    auto port = port_of(cpu);
    port.node_commands = true;
    return port;
}

// The server of the manual's node search example (JA §3.12).
void manual_example_node(devicemodel::Cpu& cpu) {
    auto& node = cpu.node().identity();
    node.mac = {0x00, 0x26, 0x92, 0xAB, 0xCD, 0xEF};
    node.ip = {192, 168, 0, 2};
    node.subnet_mask = {255, 255, 255, 0};
    node.gateway = {255, 255, 255, 255};
    node.host_name = "node1";
    node.vendor_code = 0xABCD;
    node.model_code = 0x12345678;
    node.version = 0x0001;
    node.partner_ip = {192, 168, 0, 1};
    node.partner_port = 0x3000;
    node.protocol = 0x00;
}

// The binary response as the manual prints it has 9 octets for the subnet
// mask and the gateway ("00 FF FF FF FF FF FF FF FF"), one FF more than the
// two 4-octet fields its ASCII form shows (FFFFFF00, FFFFFFFF): the binary
// below follows the ASCII form (docs/nodes.md, "Where the manual is unclear").
const Payload kNodeSearchRequest{"30 0E 00 00 56 34 12 92 26 00 04 01 00 A8 C0", "0E300000" "002692123456" "04" "C0A80001"};
const Payload kNodeSearchResponse{
    "56 34 12 92 26 00 04 01 00 A8 C0 EF CD AB 92 26 00 04 02 00 A8 C0 00 FF FF FF FF FF FF FF "
    "05 6E 6F 64 65 31 CD AB 78 56 34 12 01 00 04 01 00 A8 C0 00 30 00 00 B5 B0 00",
    "002692123456" "04" "C0A80001" "002692ABCDEF" "04" "C0A80002" "FFFFFF00" "FFFFFFFF" "05" "node1" "ABCD" "12345678"
    "0001" "04" "C0A80001" "3000" "0000" "B0B5" "00"};

Payload bare(std::uint16_t command) { return word(command) + word(0x0000); }

Payload parameter_set(std::vector<std::pair<std::uint16_t, std::uint16_t>> values) {
    Payload p = bare(0x0E34) + word(static_cast<std::uint16_t>(values.size()));
    for (auto [id, value] : values) p = p + word(id) + word(2) + word(value);
    return p;
}

Payload parameter_get(std::vector<std::uint16_t> ids) {
    Payload p = bare(0x0E33) + word(static_cast<std::uint16_t>(ids.size()));
    for (auto id : ids) p = p + word(id);
    return p;
}

}  // namespace

TEST_CASE("0E30 Node Search: the manual's example, binary and ASCII", "[node][spec]") {
    auto cpu = make_cpu("R08CPU");
    manual_example_node(cpu);
    protocol::Engine engine(cpu, node_port(cpu));
    Connection client{engine};
    client.session.local_port = 0xB0B5;   // the example server's port, 45237
    auto wire = GENERATE(kBinary3E, kBinary4E, kAscii3E, kAscii4E);
    CHECK(client.exchange(wire, kNodeSearchRequest) == wire.expect(ok(kNodeSearchResponse)));
}

TEST_CASE("0E30 whole frames, 3E (derived from the manual's data)", "[node][spec]") {
    auto cpu = make_cpu("R08CPU");
    manual_example_node(cpu);
    protocol::Engine engine(cpu, node_port(cpu));
    protocol::Session session;
    session.local_port = 0xB0B5;
    auto out = engine.process(bytes("50 00 00 FF FF 03 00 11 00 10 00 30 0E 00 00 56 34 12 92 26 00 04 01 00 A8 C0"),
                              DataCodePolicy::Auto, session);
    CHECK(hex(out.response) ==
          "D0 00 00 FF FF 03 00 3A 00 00 00 56 34 12 92 26 00 04 01 00 A8 C0 EF CD AB 92 26 00 04 02 00 A8 C0 00 FF FF FF "
          "FF FF FF FF 05 6E 6F 64 65 31 CD AB 78 56 34 12 01 00 04 01 00 A8 C0 00 30 00 00 B5 B0 00");
}

TEST_CASE("0E30 request faults", "[node]") {
    auto cpu = make_cpu("R08CPU");
    protocol::Engine engine(cpu, node_port(cpu));
    Connection client{engine};
    auto wire = GENERATE(kBinary3E, kAscii3E);
    SECTION("an IP address size other than 4 or 16 -> C05C") {
        CHECK(client.exchange(wire, Payload{"30 0E 00 00 56 34 12 92 26 00 03 00 A8 C0", "0E300000" "002692123456" "03" "C0A800"}) ==
              wire.expect(error(0xC05C, 0x0E30, 0x0000)));
    }
    SECTION("a client IP address cut short -> C061") {
        CHECK(client.exchange(wire, Payload{"30 0E 00 00 56 34 12 92 26 00 04 01 00", "0E300000" "002692123456" "04" "C0A8"}) ==
              wire.expect(error(0xC061, 0x0E30, 0x0000)));
    }
}

TEST_CASE("0E32 Device Info Compare: the manual's example and the result bits", "[node][spec]") {
    auto cpu = make_cpu("R08CPU");
    manual_example_node(cpu);
    protocol::Engine engine(cpu, node_port(cpu));
    Connection client{engine};
    auto wire = GENERATE(kBinary3E, kBinary4E, kAscii3E, kAscii4E);
    SECTION("vendor ABCD, model 12345678, version 0001: all match, version the same") {
        const Payload request{"32 0E 00 00 07 00 CD AB 78 56 34 12 01 00", "0E3200000007ABCD123456780001"};
        CHECK(client.exchange(wire, request) == wire.expect(ok(Payload{"07 00 00 C0", "0007C000"})));
    }
    SECTION("vendor and version only, the version given lower than the node's (inferred bit order)") {
        CHECK(client.exchange(wire, bare(0x0E32) + word(0x0005) + word(0xABCD) + word(0x0000)) ==
              wire.expect(ok(word(0x0005) + word(0x8004))));
    }
    SECTION("a model code that differs, the version given higher") {
        CHECK(client.exchange(wire, bare(0x0E32) + word(0x0006) + Payload{"00 00 00 00", "00000000"} + word(0x0002)) ==
              wire.expect(ok(word(0x0006) + word(0x4006))));
    }
    SECTION("no target or an unknown bit -> C05C") {
        CHECK(client.exchange(wire, bare(0x0E32) + word(0x0000)) == wire.expect(error(0xC05C, 0x0E32, 0x0000)));
        CHECK(client.exchange(wire, bare(0x0E32) + word(0x0008)) == wire.expect(error(0xC05C, 0x0E32, 0x0000)));
    }
}

TEST_CASE("0E31 IP Address Set changes what node search and Status Read2 report (layout inferred)", "[node]") {
    auto cpu = make_cpu("R08CPU");
    manual_example_node(cpu);
    protocol::Engine engine(cpu, node_port(cpu));
    Connection client{engine};
    client.session.local_port = 0xB0B5;
    auto wire = GENERATE(kBinary3E, kAscii3E);
    // Client 00:26:92:12:34:56 at 192.168.0.1 sets 10.0.0.7/255.0.0.0, gateway
    // 10.0.0.1, host "cam", partner 10.0.0.9 port 1234, protocol 01.
    auto request = [](const std::string& server_mac_binary, const std::string& server_mac_ascii) {
        return bare(0x0E31) + Payload{"56 34 12 92 26 00 04 01 00 A8 C0 " + server_mac_binary +
                                          " 04 07 00 00 0A 00 00 00 FF 01 00 00 0A 03 63 61 6D 04 09 00 00 0A 34 12 01",
                                      "002692123456" "04" "C0A80001" + server_mac_ascii +
                                          "04" "0A000007" "FF000000" "0A000001" "03" "cam" "04" "0A000009" "1234" "01"};
    };
    SECTION("this node's MAC: set, answered with the client's MAC") {
        CHECK(client.exchange(wire, request("EF CD AB 92 26 00", "002692ABCDEF")) ==
              wire.expect(ok(Payload{"56 34 12 92 26 00", "002692123456"})));
        const auto& node = cpu.node().identity();
        CHECK(node.ip == devicemodel::Ipv4Address{10, 0, 0, 7});
        CHECK(node.subnet_mask == devicemodel::Ipv4Address{255, 0, 0, 0});
        CHECK(node.gateway == devicemodel::Ipv4Address{10, 0, 0, 1});
        CHECK(node.host_name == "cam");
        CHECK(node.partner_ip == devicemodel::Ipv4Address{10, 0, 0, 9});
        CHECK(node.partner_port == 0x1234);
        CHECK(node.protocol == 0x01);
        // Status Read2 now answers only 10.0.0.9.
        client.session.peer_ipv4 = {127, 0, 0, 1};
        CHECK(client.send(wire, bare(0x0E53)).action == Outcome::Action::Silent);
        client.session.peer_ipv4 = {10, 0, 0, 9};
        CHECK(client.exchange(wire, bare(0x0E53)) ==
              wire.expect(ok(Payload{"04 07 00 00 0A 09 00 00 0A 00 00 00", "04" "0A000007" "0A000009" "00" "0000"})));
    }
    SECTION("another MAC: not answered, nothing changes") {
        auto out = client.send(wire, request("01 00 00 00 00 02", "020000000001"));
        CHECK(out.action == Outcome::Action::Silent);
        CHECK(cpu.node().identity().host_name == "node1");
    }
    SECTION("an IPv6 address to set -> CF20 (an item that cannot be set)") {
        Payload p = bare(0x0E31) + Payload{"56 34 12 92 26 00 04 01 00 A8 C0 EF CD AB 92 26 00 10", "002692123456" "04" "C0A80001" "002692ABCDEF" "10"};
        for (int i = 0; i < 3 * 16; ++i) p = p + byte(0);
        p = p + byte(0) + byte(4) + Payload{"00 00 00 00", "00000000"} + word(0) + byte(0);
        CHECK(client.exchange(wire, p) == wire.expect(error(0xCF20, 0x0E31, 0x0000)));
        CHECK(cpu.node().identity().ip == devicemodel::Ipv4Address{192, 168, 0, 2});
    }
}

TEST_CASE("0E44 Status Read and 0E53 Status Read2", "[node][spec]") {
    auto cpu = make_cpu("R08CPU");
    manual_example_node(cpu);
    cpu.node().identity().partner_ip = {};   // no partner: every sender is answered
    protocol::Engine engine(cpu, node_port(cpu));
    Connection client{engine};
    auto wire = GENERATE(kBinary3E, kBinary4E, kAscii3E, kAscii4E);
    SECTION("the manual's requests; a CPU without an error answers 0000") {
        CHECK(wire.data(bare(0x0E44)) == (wire.ascii() ? text("0E440000") : bytes("44 0E 00 00")));
        CHECK(client.exchange(wire, bare(0x0E44)) == wire.expect(ok(word(0x0001) + word(0x0000))));
        CHECK(client.exchange(wire, bare(0x0E53)) ==
              wire.expect(ok(Payload{"04 02 00 A8 C0 00 00 00 00 00 00 00", "04" "C0A80002" "00000000" "00" "0000"})));
    }
    SECTION("a CPU error: its code and operating state 01") {
        cpu.runtime().raise_error(cpu.memory(), {0x1234, false});
        CHECK(client.exchange(wire, bare(0x0E44)) == wire.expect(ok(word(0x0001) + word(0x1234))));
        CHECK(client.exchange(wire, bare(0x0E53)) ==
              wire.expect(ok(Payload{"04 02 00 A8 C0 00 00 00 00 01 34 12", "04" "C0A80002" "00000000" "01" "1234"})));
    }
    SECTION("request data after the subcommand -> C061") {
        CHECK(client.exchange(wire, bare(0x0E44) + word(0)) == wire.expect(error(0xC061, 0x0E44, 0x0000)));
    }
}

TEST_CASE("0E45 Communication Setting Get (target bits inferred)", "[node]") {
    auto cpu = make_cpu("R08CPU");
    protocol::Engine engine(cpu, node_port(cpu));
    Connection client{engine};
    client.session.local_port = 5011;
    auto wire = GENERATE(kBinary3E, kAscii3E);
    CHECK(client.exchange(wire, bare(0x0E45) + word(0x0001)) == wire.expect(ok(word(0x0001) + word(5011))));
    CHECK(client.exchange(wire, bare(0x0E45) + word(0x0003)) ==
          wire.expect(ok(word(0x0003) + word(5011) + Payload{"D0 07 00 00", "000007D0"})));
    CHECK(client.exchange(wire, bare(0x0E45) + word(0x0002)) == wire.expect(ok(word(0x0002) + Payload{"D0 07 00 00", "000007D0"})));
    CHECK(client.exchange(wire, bare(0x0E45) + word(0x0004)) == wire.expect(error(0xC05C, 0x0E45, 0x0000)));
}

TEST_CASE("0E33-0E3A: the parameter write sequence of JA §4.2.1.8", "[node]") {
    auto cpu = make_cpu("R08CPU");
    protocol::Engine engine(cpu, node_port(cpu));
    Connection a{engine}, b{engine};
    a.session.id = 1;
    b.session.id = 2;
    auto wire = GENERATE(kBinary3E, kAscii3E);
    auto get_1_2 = [&] { return a.exchange(wire, parameter_get({0x0001, 0x0002})); };
    const auto zeros = wire.expect(ok(word(2) + word(0x0001) + word(2) + word(0) + word(0x0002) + word(2) + word(0)));
    REQUIRE(get_1_2() == zeros);

    SECTION("the manual's fixed requests") {
        CHECK(wire.data(bare(0x0E35)) == (wire.ascii() ? text("0E350000") : bytes("35 0E 00 00")));
        CHECK(wire.data(bare(0x0E36)) == (wire.ascii() ? text("0E360000") : bytes("36 0E 00 00")));
        CHECK(wire.data(bare(0x0E3A)) == (wire.ascii() ? text("0E3A0000") : bytes("3A 0E 00 00")));
    }
    SECTION("Set, End or Cancel in the normal state -> CF31") {
        CHECK(a.exchange(wire, parameter_set({{0x0001, 7}})) == wire.expect(error(0xCF31, 0x0E34, 0x0000)));
        CHECK(a.exchange(wire, bare(0x0E36)) == wire.expect(error(0xCF31, 0x0E36, 0x0000)));
        CHECK(a.exchange(wire, bare(0x0E3A)) == wire.expect(error(0xCF31, 0x0E3A, 0x0000)));
        CHECK(get_1_2() == zeros);
    }
    SECTION("Start, Set, Set, End: the held values become the parameters") {
        CHECK(a.exchange(wire, bare(0x0E35)) == wire.expect(ok()));
        CHECK(a.exchange(wire, parameter_set({{0x0001, 0x1111}})) == wire.expect(ok()));
        CHECK(a.exchange(wire, parameter_set({{0x0002, 0x2222}, {0x0001, 0x3333}})) == wire.expect(ok()));
        CHECK(a.exchange(wire, bare(0x0E36)) == wire.expect(ok()));
        CHECK(get_1_2() == wire.expect(ok(word(2) + word(0x0001) + word(2) + word(0x3333) + word(0x0002) + word(2) + word(0x2222))));
    }
    SECTION("Cancel drops what Set held") {
        CHECK(a.exchange(wire, bare(0x0E35)) == wire.expect(ok()));
        CHECK(a.exchange(wire, parameter_set({{0x0001, 0x1111}})) == wire.expect(ok()));
        CHECK(a.exchange(wire, bare(0x0E3A)) == wire.expect(ok()));
        CHECK(get_1_2() == zeros);
    }
    SECTION("while a write runs: a second Start, another client, any other command -> CEE0") {
        CHECK(a.exchange(wire, bare(0x0E35)) == wire.expect(ok()));
        CHECK(a.exchange(wire, bare(0x0E35)) == wire.expect(error(0xCEE0, 0x0E35, 0x0000)));
        CHECK(b.exchange(wire, parameter_set({{0x0001, 9}})) == wire.expect(error(0xCEE0, 0x0E34, 0x0000)));
        CHECK(b.exchange(wire, bare(0x0E36)) == wire.expect(error(0xCEE0, 0x0E36, 0x0000)));
        CHECK(b.exchange(wire, bare(0x0E3A)) == wire.expect(error(0xCEE0, 0x0E3A, 0x0000)));
        CHECK(a.exchange(wire, parameter_get({0x0001})) == wire.expect(error(0xCEE0, 0x0E33, 0x0000)));
        CHECK(b.exchange(wire, read_words_req(Form::Q, "D0", 1)) == wire.expect(error(0xCEE0, 0x0401, 0x0000)));
        CHECK(a.exchange(wire, bare(0x0E36)) == wire.expect(ok()));   // End without Set: nothing to reflect
        CHECK(b.exchange(wire, read_words_req(Form::Q, "D0", 1)) == wire.expect(ok(word(0))));
        CHECK(get_1_2() == zeros);
    }
    SECTION("Set with request data the store does not take -> CF30, nothing held") {
        CHECK(a.exchange(wire, bare(0x0E35)) == wire.expect(ok()));
        CHECK(a.exchange(wire, parameter_set({{0x0011, 1}})) == wire.expect(error(0xCF30, 0x0E34, 0x0000)));
        CHECK(a.exchange(wire, bare(0x0E34) + word(1) + word(0x0001) + word(4) + Payload{"01 00 00 00", "00000001"}) ==
              wire.expect(error(0xCF30, 0x0E34, 0x0000)));
        CHECK(a.exchange(wire, bare(0x0E34) + word(4) + word(0x0001) + word(2) + word(1)) ==
              wire.expect(error(0xCF30, 0x0E34, 0x0000)));
        CHECK(a.exchange(wire, parameter_set({{0x0001, 5}, {0x00FF, 6}})) == wire.expect(error(0xCF30, 0x0E34, 0x0000)));
        CHECK(a.exchange(wire, bare(0x0E36)) == wire.expect(ok()));
        CHECK(get_1_2() == zeros);
    }
    SECTION("Parameter Get: an unknown ID -> CF30, a count outside 1-3 -> C05C") {
        CHECK(a.exchange(wire, parameter_get({0x0001, 0x0042})) == wire.expect(error(0xCF30, 0x0E33, 0x0000)));
        CHECK(a.exchange(wire, parameter_get({})) == wire.expect(error(0xC05C, 0x0E33, 0x0000)));
        CHECK(a.exchange(wire, parameter_get({1, 2, 3, 4})) == wire.expect(error(0xC05C, 0x0E33, 0x0000)));
    }
}

TEST_CASE("the parameter write times out 10 s after Start or the last Set (JA §4.2.1.6)", "[node]") {
    devicemodel::Node node;
    using devicemodel::Node;
    const Node::TimePoint t0{std::chrono::seconds(100)};
    REQUIRE(node.start(1, t0) == Node::Verdict::Ok);
    CHECK(node.set(1, {{0x0001, {0x12, 0x34}}}, t0 + std::chrono::seconds(9)) == Node::Verdict::Ok);
    CHECK(node.busy(t0 + std::chrono::seconds(18)));   // 9 s after the Set
    CHECK_FALSE(node.busy(t0 + std::chrono::seconds(19)));
    CHECK(node.end(1, t0 + std::chrono::seconds(19)) == Node::Verdict::NotStarted);   // back in the normal state
    CHECK(node.parameter(0x0001)->value == std::vector<std::uint8_t>{0, 0});         // dropped, not reflected
    REQUIRE(node.start(2, t0 + std::chrono::seconds(20)) == Node::Verdict::Ok);
    CHECK(node.start(1, t0 + std::chrono::seconds(29)) == Node::Verdict::Busy);
    CHECK(node.start(1, t0 + std::chrono::seconds(30)) == Node::Verdict::Ok);   // Start without Set timed out
}

TEST_CASE("the node commands on the built-in profiles' ports: C059", "[node]") {
    // The Mitsubishi CPUs and modules are the clients of these commands (iQ
    // Sensor Solution); their ports do not serve them (docs/nodes.md).
    auto name = GENERATE(as<std::string>{}, "R08CPU", "RJ71EN71", "Q06UDVCPU", "L02CPU", "FX5U-32MR", "Q06UDVCPU-QJ71E71");
    auto cpu = make_cpu(name);
    auto wire = GENERATE(kBinary3E, kAscii3E);
    for (std::uint16_t command : {0x0E30, 0x0E31, 0x0E32, 0x0E33, 0x0E34, 0x0E35, 0x0E36, 0x0E3A, 0x0E44, 0x0E45, 0x0E53}) {
        INFO(name << " " << hexn(command, 4));
        CHECK(wire.exchange(cpu, bare(command)) == wire.expect(error(0xC059, command, 0x0000)));
    }
}
