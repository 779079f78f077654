// Proxy mode (docs/twin.md, "Proxy"): slmp-sim B with --upstream forwards
// every request to slmp-sim A (the "PLC") and returns A's answer byte for
// byte. A runs Q06UDVCPU behind a QJ71E71 (3E, 4E and 1E) and B's own
// profile is R08CPU, so an answer that names Q06UDVCPU, or one to a 1E frame
// (which R08CPU's port does not take), can only have come from A.
#include <catch2/catch.hpp>

#include <arpa/inet.h>
#include <netinet/in.h>
#include <sys/socket.h>

#include "ask.hpp"
#include "frames.hpp"
#include "plant_ports.hpp"
#include "protocol/client.hpp"
#include "protocol/client_commands.hpp"
#include "scenario_support.hpp"
#include "sim_process.hpp"
#include "sockets.hpp"

using namespace slmp::test;
namespace client = slmp::protocol::client;

namespace {

const char* const kPlc = "Q06UDVCPU-QJ71E71";

const Wire kWires[] = {{FrameKind::E3, Codec::Binary, 0}, {FrameKind::E3, Codec::Ascii, 0},
                       {FrameKind::E4, Codec::Binary, 0x1234}, {FrameKind::E4, Codec::Ascii, 0xBEEF}};

bool names(const Bytes& answer, const std::string& cpu) {
    return std::string(answer.begin(), answer.end()).find(cpu) != std::string::npos;
}

std::string upstream_of(const SimProcess& plc) { return "127.0.0.1:" + std::to_string(plc.tcp_port()); }

SimProcess proxy_to(const std::string& upstream, std::vector<std::string> more = {}) {
    std::vector<std::string> args = {"--profile", "R08CPU", "--no-http", "--upstream", upstream};
    args.insert(args.end(), more.begin(), more.end());
    return SimProcess(with_args(args));
}

// A 1E answer has no length field: exactly `size` bytes.
Bytes ask_1e(TcpClient& c, const Bytes& request, std::size_t size) {
    REQUIRE(c.send(request));
    return c.read_exactly(size);
}

// A local TCP port on which nothing is served: bound, never listening, so a
// connection to it is refused for as long as `holder` lives.
std::uint16_t refused_port(Socket& holder) {
    holder = Socket(::socket(AF_INET, SOCK_STREAM, 0));
    auto addr = loopback(0);
    REQUIRE(::bind(holder.fd(), reinterpret_cast<sockaddr*>(&addr), sizeof addr) == 0);
    socklen_t size = sizeof addr;
    REQUIRE(::getsockname(holder.fd(), reinterpret_cast<sockaddr*>(&addr), &size) == 0);
    return ntohs(addr.sin_port);
}

// A port that accepts connections (the kernel's backlog) and never answers.
std::uint16_t silent_port(Socket& holder) {
    auto port = refused_port(holder);
    REQUIRE(::listen(holder.fd(), 8) == 0);
    return port;
}

std::string lower_hex(const Bytes& bytes) {
    std::string out;
    for (auto b : bytes) out += hex_digits(b, 2);
    for (auto& c : out) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
    return out;
}

Bytes cf71(const Wire& w, std::uint16_t command, std::uint16_t subcommand) {
    return expected_response(w, error_info(w, command, subcommand), 0xCF71);
}

}  // namespace

TEST_CASE("proxy: B's answers are A's bytes — 3E/4E, binary/ASCII, TCP and UDP clients", "[proxy]") {
    TempDir dir;
    auto recording = dir.path() / "proxy.jsonl";
    SimProcess plc(with_args({"--profile", kPlc, "--no-http"}));
    auto proxy = proxy_to(upstream_of(plc), {"--record", recording.string()});
    auto direct = TcpClient::open(plc.tcp_port());
    auto via = TcpClient::open(proxy.tcp_port());
    UdpClient via_udp;

    // A write through B lands in A's memory.
    const Wire bin3 = kWires[0];
    CHECK(show(ask(via, client::write_words(bin3.options(), addr("D100"), std::vector<std::uint16_t>{0x1111, 0x2222, 0x3333}))) ==
          show(expected_response(bin3, {})));
    CHECK(show(ask(direct, client::read_words(bin3.options(), addr("D100"), 3))) ==
          show(expected_response(bin3, word_data(bin3, {0x1111, 0x2222, 0x3333}))));

    for (const auto& w : kWires) {
        INFO(w.name());
        const std::vector<Bytes> requests = {
            client::read_type_name(w.options()),                    // A's name, not R08CPU's
            client::read_words(w.options(), addr("D100"), 3),
            client::read_words(w.options(), addr("D100"), 961),     // A's word limit's end code
            client::read_words(w.options(), addr("ZR0"), 2),
        };
        for (const auto& request : requests) {
            INFO(show(request));
            const auto from_plc = ask(direct, request);
            CHECK(show(ask(via, request)) == show(from_plc));
            CHECK(show(ask(via_udp, proxy.udp_port(), request)) == show(from_plc));
        }
        CHECK(names(ask(via, client::read_type_name(w.options())), "Q06UDVCPU"));
    }

    // 1E, which R08CPU's own port does not take: word read of D100, bit read of M100-M104.
    const auto read_d100 = hex("01 FF 0A 00 64 00 00 00 20 44 03 00");
    const auto read_m100 = hex("00 FF 0A 00 64 00 00 00 20 4D 05 00");
    const auto words_1e = ask_1e(direct, read_d100, 8);
    CHECK(show(words_1e) == show(hex("81 00 11 11 22 22 33 33")));
    CHECK(show(ask_1e(via, read_d100, 8)) == show(words_1e));
    CHECK(show(ask_1e(via, read_m100, 5)) == show(ask_1e(direct, read_m100, 5)));
    CHECK(via.pending().empty());

    // The recording holds what the client sent and what it got (A's bytes).
    proxy.stop();
    const auto read = client::read_words(bin3.options(), addr("D100"), 3);
    const auto answer = expected_response(bin3, word_data(bin3, {0x1111, 0x2222, 0x3333}));
    bool found = false;
    for (const auto& line : lines_of(read_text(recording))) {
        auto entry = nlohmann::json::parse(line);
        if (entry.value("event", "") != "exchange" || entry.value("request", "") != lower_hex(read)) continue;
        CHECK(entry["response"] == lower_hex(answer));
        found = true;
        break;
    }
    CHECK(found);
}

TEST_CASE("proxy: an upstream that refuses gets CF71, and the client's connection goes on", "[proxy][upstream-down]") {
    Socket holder;
    auto proxy = proxy_to("127.0.0.1:" + std::to_string(refused_port(holder)));
    auto via = TcpClient::open(proxy.tcp_port());
    UdpClient via_udp;
    for (const auto& w : kWires) {
        INFO(w.name());
        for (int twice = 0; twice < 2; ++twice) {
            CHECK(show(ask(via, client::read_words(w.options(), addr("D0"), 1))) == show(cf71(w, 0x0401, 0x0000)));
            CHECK(show(ask(via_udp, proxy.udp_port(), client::read_type_name(w.options()))) == show(cf71(w, 0x0101, 0x0000)));
        }
    }
    // 1E: CF71's 1E code, 60 (docs/frames.md).
    CHECK(via.send(hex("01 FF 0A 00 64 00 00 00 20 44 03 00")));
    CHECK(show(via.read_exactly(2)) == show(hex("81 60")));
    // One warning names the upstream and the cause.
    proxy.stop();
    const auto logs = proxy.logs();
    CHECK(logs.find("upstream 127.0.0.1:") != std::string::npos);
    CHECK(logs.find("cannot connect: Connection refused") != std::string::npos);
}

TEST_CASE("proxy: an upstream that does not answer in time gets CF71 after --upstream-timeout", "[proxy][upstream-down]") {
    Socket holder;
    auto proxy = proxy_to("127.0.0.1:" + std::to_string(silent_port(holder)), {"--upstream-timeout", "0.2"});
    auto via = TcpClient::open(proxy.tcp_port());
    const Wire w = kWires[0];
    CHECK(show(ask(via, client::read_words(w.options(), addr("D0"), 1))) == show(cf71(w, 0x0401, 0x0000)));
    CHECK(show(ask(via, client::read_type_name(w.options()))) == show(cf71(w, 0x0101, 0x0000)));
    proxy.stop();
    CHECK(proxy.logs().find("no answer within 200 ms") != std::string::npos);
}

TEST_CASE("proxy: the upstream stops, the client gets CF71, and B reconnects once it is back", "[proxy][upstream-down]") {
    auto plc = std::make_unique<SimProcess>(with_args({"--profile", kPlc, "--no-http"}));
    const auto port = plc->tcp_port();
    auto proxy = proxy_to(upstream_of(*plc));
    auto via = TcpClient::open(proxy.tcp_port());
    const Wire w = kWires[1];
    const auto write = client::write_words(w.options(), addr("D7"), std::vector<std::uint16_t>{0x0777});
    const auto read = client::read_words(w.options(), addr("D7"), 1);
    CHECK(show(ask(via, write)) == show(expected_response(w, {})));
    CHECK(show(ask(via, read)) == show(expected_response(w, word_data(w, {0x0777}))));

    REQUIRE(plc->stop() == 0);
    plc.reset();
    CHECK(show(ask(via, read)) == show(cf71(w, 0x0401, 0x0000)));   // the kept connection was closed
    CHECK(show(ask(via, read)) == show(cf71(w, 0x0401, 0x0000)));   // nothing listens

    SimOptions again = with_args({"--profile", kPlc, "--no-http", "--tcp-port", std::to_string(port)});
    again.tcp_ports = 0;
    SimProcess back(again);
    // A fresh CPU: D7 is 0 again, and B's new connection reads it.
    CHECK(show(ask(via, read)) == show(expected_response(w, word_data(w, {0x0000}))));
}

TEST_CASE("proxy: B's scenario faults apply in front of the upstream", "[proxy][scenario]") {
    SimProcess plc(with_args({"--profile", kPlc, "--no-http"}));
    ScenarioSim proxy({R"({"faults": [{"do": "end_code", "end_code": "C051", "match": {"command": "0401", "devices": "D100-D199"}},
                                      {"do": "no_response", "count": 1, "match": {"devices": "D300"}}]})"},
                      {"--profile", "R08CPU", "--upstream", upstream_of(plc)});
    auto via = TcpClient::open(proxy.sim->tcp_port());
    auto direct = TcpClient::open(plc.tcp_port());
    const Wire w = kWires[0];
    CHECK(show(ask(direct, client::write_words(w.options(), addr("D300"), std::vector<std::uint16_t>{0x0300}))) == show(expected_response(w, {})));
    CHECK(show(ask(via, client::read_words(w.options(), addr("D100"), 1))) ==
          show(expected_response(w, error_info(w, 0x0401, 0x0000), 0xC051)));
    // Dropped in front of A: the first answer to arrive is the next request's.
    REQUIRE(via.send(client::read_words(w.options(), addr("D300"), 1)));
    CHECK(show(ask(via, client::read_words(w.options(), addr("D200"), 1))) == show(expected_response(w, word_data(w, {0}))));
    CHECK(show(ask(via, client::read_words(w.options(), addr("D300"), 1))) == show(expected_response(w, word_data(w, {0x0300}))));
}

TEST_CASE("proxy: a plant station with \"upstream\"", "[proxy][plant]") {
    SimProcess plc(with_args({"--profile", kPlc, "--no-http"}));
    SimOptions options;
    options.plant = true;
    options.config_json = R"({"bind": "127.0.0.1", "http": {"enabled": false}, "stations": [
        {"name": "own", "profile": "R08CPU", "tcp_port": 0, "udp_port": 0},
        {"name": "twin", "profile": "R08CPU", "tcp_port": 0, "udp_port": 0, "upstream": ")" + upstream_of(plc) +
                          R"(", "upstream_timeout_ms": 1000}]})";
    SimProcess plant(options);
    const Wire w = kWires[2];
    auto own = TcpClient::open(tcp_of(plant, "own"));
    auto twin = TcpClient::open(tcp_of(plant, "twin"));
    CHECK(names(ask(own, client::read_type_name(w.options())), "R08CPU"));
    CHECK(names(ask(twin, client::read_type_name(w.options())), "Q06UDVCPU"));

    TempDir dir;
    auto bad = dir.write("bad.json", R"({"stations": [{"name": "twin", "tcp_port": 0, "upstream": "plc-without-port"}]})");
    auto checked = run_sim({"--check-config", bad.string()});
    CHECK(checked.exit_code == 2);
    CHECK(checked.err.find("'plc-without-port' is not HOST:PORT") != std::string::npos);
}

TEST_CASE("proxy: in each timing mode B holds a request as its clock says, then it goes on, frames of one write in order", "[proxy][timing]") {
    SimProcess plc(with_args({"--profile", kPlc, "--no-http"}));
    auto direct = TcpClient::open(plc.tcp_port());
    for (const char* mode : {"instant", "end_of_scan", "model"}) {
        INFO(mode);
        auto proxy = proxy_to(upstream_of(plc), {"--timing", mode});
        auto via = TcpClient::open(proxy.tcp_port());
        UdpClient via_udp;
        for (const auto& w : kWires) {
            INFO(w.name());
            const auto request = client::read_type_name(w.options());
            const auto from_plc = ask(direct, request);
            CHECK(show(ask(via, request)) == show(from_plc));
            CHECK(show(ask(via_udp, proxy.udp_port(), request)) == show(from_plc));
        }
        // Two frames in one write: both go on, in order.
        const Wire w = kWires[0];
        REQUIRE(via.send(concat({client::read_words(w.options(), addr("D0"), 1), client::read_type_name(w.options())})));
        Bytes first, second;
        REQUIRE(via.response(&first));
        REQUIRE(via.response(&second));
        CHECK(show(first) == show(expected_response(w, word_data(w, {0}))));
        CHECK(names(second, "Q06UDVCPU"));
    }
}
