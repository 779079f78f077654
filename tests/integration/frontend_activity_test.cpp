// The front ends' requests around the station, against the real binary
// (docs/hostlink.md, docs/jw51cm.md): each host-link record and JW-51CM
// request is counted in /metrics with a protocol label, published as a
// "request" event (the call monitor's rows) and written to --record; scenario
// faults match them by protocol and command and answer a chosen code, delay,
// drop or close. A delay is checked as a lower bound only.
#include <catch2/catch.hpp>

#include <cerrno>
#include <map>
#include <sstream>
#include <string>

#include "frames.hpp"
#include "http_client.hpp"
#include "sim_process.hpp"
#include "sockets.hpp"

using namespace slmp::test;
using namespace std::chrono_literals;
using nlohmann::json;

namespace {

// XOR of the bytes, two uppercase hex digits (Ladder Motion host-link manual, docs/hostlink.md).
std::string fcs(const std::string& body) {
    unsigned x = 0;
    for (unsigned char c : body) x ^= c;
    static constexpr char digits[] = "0123456789ABCDEF";
    return {digits[x >> 4], digits[x & 0xF]};
}
std::string record(const std::string& body) { return body + fcs(body) + "*\r"; }

std::string read_record(TcpClient& client) {
    std::string got;
    while (got.empty() || got.back() != '\r') {
        auto more = client.read_exactly(1);
        if (more.empty()) FAIL("no whole host-link record; got: " << got);
        got.push_back(static_cast<char>(more[0]));
    }
    return got;
}
std::string ask(TcpClient& client, const std::string& request) {
    REQUIRE(client.send(request));
    return read_record(client);
}

Bytes jw(std::uint8_t id, Bytes after_id) {
    Bytes frame(40, 0);
    frame.push_back(id);
    frame.push_back(0x00);
    frame.insert(frame.end(), after_id.begin(), after_id.end());
    return frame;
}
Bytes jw_request(Bytes after_id) { return jw(0x47, std::move(after_id)); }
Bytes jw_response(Bytes after_id) { return jw(0x45, std::move(after_id)); }

std::string hex_of(const std::string& text) {
    static constexpr char digits[] = "0123456789abcdef";
    std::string out;
    for (unsigned char c : text) out += {digits[c >> 4], digits[c & 0xF]};
    return out;
}
std::string hex_of(const Bytes& bytes) { return hex_of(std::string(bytes.begin(), bytes.end())); }

std::map<std::string, double> samples(const std::string& text) {
    std::map<std::string, double> out;
    std::istringstream in(text);
    for (std::string line; std::getline(in, line);) {
        if (line.empty() || line[0] == '#') continue;
        auto space = line.rfind(' ');
        out[line.substr(0, space)] = std::stod(line.substr(space + 1));
    }
    return out;
}

std::string metric(const std::string& protocol, const std::string& transport, const std::string& command,
                   const std::string& code) {
    return "slmp_frontend_requests_total{protocol=\"" + protocol + "\",transport=\"" + transport + "\",command=\"" +
           command + "\",code=\"" + code + "\"}";
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
const std::string kSharpJw = R"({"kind": "sharp-jw", "jw51cm": {"tcp_port": 0, "udp_port": 0}})";

std::uint16_t hostlink_port(const SimProcess& sim) { return sim.ready().at("hostlink").at(0).get<std::uint16_t>(); }
std::uint16_t jw_tcp(const SimProcess& sim) { return sim.ready().at("jw51cm").at("tcp").at(0).get<std::uint16_t>(); }
std::uint16_t jw_udp(const SimProcess& sim) { return sim.ready().at("jw51cm").at("udp").at(0).get<std::uint16_t>(); }

// The recording's exchange lines of one protocol.
std::vector<json> exchanges(const std::filesystem::path& file, const std::string& protocol) {
    std::vector<json> out;
    for (const auto& line : lines_of(read_text(file))) {
        auto j = json::parse(line);
        if (j.value("event", "") == "exchange" && j.value("protocol", "slmp") == protocol) out.push_back(j);
    }
    return out;
}

}  // namespace

TEST_CASE("host link requests: metrics with a protocol label, request events, recording", "[hostlink][frontend]") {
    TempDir dir;
    auto file = dir.path() / "session.jsonl";
    SimProcess sim(station(kLadderMotion, {"--record", file.string()}));
    EventReader events(sim.http_port());
    auto client = TcpClient::open(hostlink_port(sim));

    const auto write = record("@00WD0100ABCD1234");
    CHECK(ask(client, write) == record("@00WD00"));
    auto call = events.next_of("request").data;
    CHECK(call["protocol"] == "hostlink");
    CHECK(call["command"] == "WD");
    CHECK(call["subcommand"].is_null());
    CHECK(call["end_code"] == "00");
    CHECK(call["reaction"] == "answered");
    CHECK(call["transport"] == "tcp");
    CHECK(call["request"] == hex_of(write));
    CHECK(call["response"] == hex_of(record("@00WD00")));
    CHECK(call["bytes_in"] == write.size());
    // The writes the record made are published under its protocol, peer and connection.
    auto devices = events.next_of("devices").data;
    CHECK(devices["device"] == "D100");
    CHECK(devices["values"] == json({0xABCD, 0x1234}));
    CHECK(devices["source"] == "hostlink");
    CHECK(devices["connection"] == call["connection"]);

    CHECK(ask(client, record("@00RD01000002")) == record("@00RD00ABCD1234"));
    CHECK(ask(client, record("@00ZZ")) == record("@00IC"));
    call = events.next_of("request").data;
    CHECK(call["command"] == "RD");
    call = events.next_of("request").data;
    CHECK(call["command"] == "ZZ");
    CHECK(call["end_code"] == "IC");
    CHECK(ask(client, "@00RD0100000200*\r") == record("@00RD01"));   // bad FCS

    auto m = samples(http_get(sim.http_port(), "/metrics").body);
    CHECK(m[metric("hostlink", "tcp", "WD", "00")] == 1);
    CHECK(m[metric("hostlink", "tcp", "RD", "00")] == 1);
    CHECK(m[metric("hostlink", "tcp", "RD", "01")] == 1);
    CHECK(m[metric("hostlink", "tcp", "other", "IC")] == 1);   // unknown commands share one label value

    auto lines = exchanges(file, "hostlink");
    REQUIRE(lines.size() == 4);
    CHECK(lines[0]["command"] == "WD");
    CHECK(lines[0]["code"] == "00");
    CHECK(lines[0]["request"] == hex_of(write));
    CHECK(lines[0]["response"] == hex_of(record("@00WD00")));
    CHECK(lines[2]["code"] == "IC");
    CHECK(exchanges(file, "slmp").empty());
}

TEST_CASE("JW-51CM requests: metrics, request events and the recording, TCP and UDP", "[jw51cm][frontend]") {
    TempDir dir;
    auto file = dir.path() / "session.jsonl";
    SimProcess sim(station(kSharpJw, {"--record", file.string()}));
    EventReader events(sim.http_port());
    auto client = TcpClient::open(jw_tcp(sim));

    REQUIRE(client.send(jw_request({0xE9})));
    CHECK(client.read_exactly(45) == jw_response({0xE9, 0x00, 0x00}));
    auto call = events.next_of("request").data;
    CHECK(call["protocol"] == "jw51cm");
    CHECK(call["command"] == "E9");
    CHECK(call["end_code"] == "00");
    CHECK(call["request"] == hex_of(jw_request({0xE9})));
    // Mode 0: a register write is refused with RSLT 10.
    REQUIRE(client.send(jw_request({0x34, 0x00, 0x00, 0x08, 0x01, 0x00, 0x12})));
    CHECK(client.read_exactly(44) == jw_response({0x34, 0x10}));
    call = events.next_of("request").data;
    CHECK(call["command"] == "34");
    CHECK(call["end_code"] == "10");

    UdpClient udp;
    REQUIRE(udp.send_to(jw_udp(sim), jw_request({0xE9})));
    auto answer = udp.receive();
    REQUIRE(answer);
    CHECK(*answer == jw_response({0xE9, 0x00, 0x00}));
    call = events.next_of("request").data;
    CHECK(call["transport"] == "udp");

    auto m = samples(http_get(sim.http_port(), "/metrics").body);
    CHECK(m[metric("jw51cm", "tcp", "E9", "00")] == 1);
    CHECK(m[metric("jw51cm", "tcp", "34", "10")] == 1);
    CHECK(m[metric("jw51cm", "udp", "E9", "00")] == 1);
    auto lines = exchanges(file, "jw51cm");
    REQUIRE(lines.size() == 3);
    CHECK(lines[1]["command"] == "34");
    CHECK(lines[1]["code"] == "10");
    CHECK(lines[2]["transport"] == "udp");
}

TEST_CASE("scenario faults on host-link records: a chosen code, a delay, no answer, close", "[hostlink][frontend][faults]") {
    TempDir dir;
    auto scenario = dir.write("faults.json", R"({"faults": [
        {"do": "end_code", "end_code": "15", "match": {"protocol": "hostlink", "command": "WD"}},
        {"do": "delay", "delay_ms": 300, "match": {"protocol": "hostlink", "command": "RR"}},
        {"do": "no_response", "count": 1, "match": {"protocol": "hostlink", "command": "MM"}},
        {"do": "close", "match": {"protocol": "hostlink", "command": "RH"}},
        {"do": "end_code", "end_code": "C051", "match": {"command": "0401"}}]})");
    SimProcess sim(station(kLadderMotion, {"--scenario", scenario.string()}));
    auto client = TcpClient::open(hostlink_port(sim));

    // The forced code is answered and nothing is written.
    CHECK(ask(client, record("@00WD01000001")) == record("@00WD15"));
    CHECK(ask(client, record("@00RD01000001")) == record("@00RD000000"));
    CHECK(http_get(sim.http_port(), "/api/devices/D100").json()["values"] == json::array({0}));

    auto start = std::chrono::steady_clock::now();
    CHECK(ask(client, record("@00RR00000001")) == record("@00RR000000"));
    CHECK(std::chrono::steady_clock::now() - start >= 300ms);

    // MM is swallowed once: the next answer to arrive is the second MM's.
    REQUIRE(client.send(record("@00MM")));
    CHECK(ask(client, record("@00MM")) == record("@00MM0011"));

    REQUIRE(client.send(record("@00RH00000001")));
    CHECK(client.recv_some(10s).status == RecvStatus::Eof);

    auto faults = http_get(sim.http_port(), "/api/faults").json()["faults"];
    REQUIRE(faults.size() == 5);
    CHECK(faults[0]["fired"] == 1);
    CHECK(faults[4]["matched"] == 0);   // an SLMP fault never sees host-link records
}

TEST_CASE("scenario faults on JW-51CM requests: a chosen RSLT, no answer, reset, over TCP and UDP", "[jw51cm][frontend][faults]") {
    TempDir dir;
    auto scenario = dir.write("faults.json", R"({"faults": [
        {"do": "end_code", "end_code": "0F", "match": {"protocol": "jw51cm", "command": ["24", "e9"]}, "count": 2},
        {"do": "no_response", "count": 1, "match": {"protocol": "jw51cm", "command": "A2", "transport": "udp"}},
        {"do": "reset", "match": {"protocol": "jw51cm", "command": "A3"}}]})");
    SimProcess sim(station(kSharpJw, {"--scenario", scenario.string()}));
    auto client = TcpClient::open(jw_tcp(sim));
    REQUIRE(client.send(jw_request({0xE9})));
    CHECK(client.read_exactly(44) == jw_response({0xE9, 0x0F}));
    UdpClient udp;
    REQUIRE(udp.send_to(jw_udp(sim), jw_request({0x24, 0x00, 0x00, 0x08, 0x01, 0x00})));
    auto answer = udp.receive();
    REQUIRE(answer);
    CHECK(*answer == jw_response({0x24, 0x0F}));
    // count 2 reached: the unit answers again.
    REQUIRE(client.send(jw_request({0xE9})));
    CHECK(client.read_exactly(45) == jw_response({0xE9, 0x00, 0x00}));

    // A2 over UDP is dropped once; the next datagram's answer is the first to arrive.
    REQUIRE(udp.send_to(jw_udp(sim), jw_request({0xA2})));
    REQUIRE(udp.send_to(jw_udp(sim), jw_request({0xE9})));
    answer = udp.receive();
    REQUIRE(answer);
    CHECK(*answer == jw_response({0xE9, 0x00, 0x00}));

    REQUIRE(client.send(jw_request({0xA3})));
    auto got = client.recv_some(10s);
    CHECK(got.status == RecvStatus::Error);
    CHECK(got.error == ECONNRESET);
}

TEST_CASE("a front end's fault is checked when the scenario loads", "[frontend][faults][options]") {
    TempDir dir;
    auto bad = dir.write("bad.json", R"({"faults": [{"do": "split", "chunks": 2, "match": {"protocol": "hostlink"}}]})");
    auto r = run_sim({"--scenario", bad.string(), "--tcp-port", "0", "--no-http"});
    CHECK(r.exit_code != 0);
    CHECK(r.err.find("/faults/0/do") != std::string::npos);
    CHECK(r.err.find("does not act on hostlink requests") != std::string::npos);
    auto code = dir.write("code.json", R"({"faults": [{"do": "end_code", "end_code": "C051", "match": {"protocol": "jw51cm"}}]})");
    r = run_sim({"--scenario", code.string(), "--tcp-port", "0", "--no-http"});
    CHECK(r.exit_code != 0);
    CHECK(r.err.find("/faults/0/end_code") != std::string::npos);
    CHECK(r.err.find("write the RSLT as two hex digits") != std::string::npos);
}
