// Differential mode (docs/twin.md, "Compare"): slmp-sim B with --upstream A
// --compare serves each request from its own memory and profile (the twin)
// and through A (the "real PLC"), gives the client A's answer and reports
// every difference — at GET /api/compare, in /metrics and in its log. A differs
// from B on purpose: another value in D100, scenario faults (a forced end
// code, a drop, a close, a delay), or another profile.
#include <catch2/catch.hpp>

#include "ask.hpp"
#include "frames.hpp"
#include "http_client.hpp"
#include "plant_ports.hpp"
#include "protocol/client.hpp"
#include "protocol/client_commands.hpp"
#include "scenario_support.hpp"
#include "sim_process.hpp"
#include "sockets.hpp"

using namespace slmp::test;
namespace client = slmp::protocol::client;
using nlohmann::json;

namespace {

std::string upstream_of(const SimProcess& plc) { return "127.0.0.1:" + std::to_string(plc.tcp_port()); }

// B: an R08CPU twin comparing itself with `upstream`. The slack is large
// where a test asserts exact counts, so that a loaded machine's scheduling
// never makes a "time" difference of an ordinary answer.
SimProcess twin_of(const std::string& upstream, std::vector<std::string> more = {}) {
    std::vector<std::string> args = {"--profile", "R08CPU", "--upstream", upstream, "--compare"};
    args.insert(args.end(), more.begin(), more.end());
    return SimProcess(with_args(args));
}

std::string lower_hex(const Bytes& bytes) {
    std::string out;
    for (auto b : bytes) out += hex_digits(b, 2);
    for (auto& c : out) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
    return out;
}

std::string upper_hex(const Bytes& bytes) {
    std::string out;
    for (auto b : bytes) out += hex_digits(b, 2);
    return out;
}

bool names_cpu(const Bytes& answer, const std::string& cpu) {
    return std::string(answer.begin(), answer.end()).find(cpu) != std::string::npos;
}

json compare_report(const SimProcess& sim) {
    auto r = http_get(sim.http_port(), "/api/compare");
    REQUIRE(r.status == 200);
    return r.json();
}

// The value of one sample line of /metrics ("name{labels} value"); -1 when absent.
double metric(const std::string& text, const std::string& series) {
    auto at = text.find("\n" + series + " ");
    if (at == std::string::npos) return -1;
    return std::stod(text.substr(at + series.size() + 2));
}

Bytes cf71(const Wire& w, std::uint16_t command, std::uint16_t subcommand) {
    return expected_response(w, error_info(w, command, subcommand), 0xCF71);
}

const Wire kBin = kBinary3E;

}  // namespace

TEST_CASE("compare: each kind of difference, exactly, at /api/compare, /metrics and in the log — the client gets A's answers",
          "[compare][proxy]") {
    // A, the "real PLC": D100 holds 5, and its faults answer D300 C051, drop D400, close on D500.
    ScenarioSim plc({R"({"faults": [{"do": "end_code", "end_code": "C051", "match": {"command": "0401", "devices": "D300"}},
                                    {"do": "no_response", "match": {"devices": "D400"}},
                                    {"do": "close", "match": {"devices": "D500"}}]})"},
                    {"--profile", "R08CPU"}, R"({"devices": {"D100": 5}})");
    auto twin = twin_of(upstream_of(*plc.sim), {"--compare-slack", "600", "--upstream-timeout", "0.3"});
    auto via = TcpClient::open(twin.tcp_port());

    const auto read_d0 = read_request(kBin, "D0"), read_d100 = read_request(kBin, "D100"),
               read_d300 = read_request(kBin, "D300"), read_d400 = read_request(kBin, "D400"),
               read_d500 = read_request(kBin, "D500"), read_d200 = read_request(kBin, "D200");
    const auto write_d200 = write_request(kBin, "D200", {7});
    const auto zero = expected_response(kBin, word_data(kBin, {0}));
    CHECK(show(ask(via, read_d0)) == show(zero));                                                         // #1 same
    CHECK(show(ask(via, read_d100)) == show(expected_response(kBin, word_data(kBin, {5}))));            // #2 bytes
    const auto c051 = expected_response(kBin, error_info(kBin, 0x0401, 0x0000), 0xC051);
    CHECK(show(ask(via, read_d300)) == show(c051));                                                       // #3 end_code
    CHECK(show(ask(via, write_d200)) == show(expected_response(kBin, {})));                               // #4 same
    CHECK(show(ask(via, read_d200)) == show(expected_response(kBin, word_data(kBin, {7}))));            // #5 same
    CHECK(show(ask(via, read_d400)) == show(cf71(kBin, 0x0401, 0x0000)));                                 // #6 silence
    CHECK(show(ask(via, read_d500)) == show(cf71(kBin, 0x0401, 0x0000)));                                 // #7 close
    CHECK(names_cpu(ask(via, client::read_type_name(kBin.options())), "R08CPU"));                        // #8 same

    auto report = compare_report(twin);
    INFO(report.dump(2));
    CHECK(report["upstream"] == upstream_of(*plc.sim));
    CHECK(report["slack_ms"] == 600000.0);
    CHECK(report["compared"] == 8);
    CHECK(report["same"] == 4);
    CHECK(report["different"] == 4);
    CHECK(report["kinds"] == json{{"close", 1}, {"silence", 1}, {"end_code", 1}, {"bytes", 1}, {"time", 0}});
    const auto& list = report["differences"];
    REQUIRE(list.size() == 4);

    CHECK(list[0]["number"] == 2);
    CHECK(list[0]["kind"] == "bytes");
    CHECK(list[0]["first_byte"] == 11);   // 3E binary: the first data byte
    CHECK(list[0]["command"] == "0401");
    CHECK(list[0]["subcommand"] == "0000");
    CHECK(list[0]["request"] == lower_hex(read_d100));
    CHECK(list[0]["upstream"]["kind"] == "answer");
    CHECK(list[0]["upstream"]["end_code"] == "0000");
    CHECK(list[0]["upstream"]["bytes"] == lower_hex(expected_response(kBin, word_data(kBin, {5}))));
    CHECK(list[0]["twin"]["bytes"] == lower_hex(zero));
    CHECK(list[0]["upstream"]["ms"].is_number());
    CHECK(list[0]["twin"]["ms"].is_number());
    CHECK(list[0]["peer"].get<std::string>().rfind("tcp:127.0.0.1:", 0) == 0);

    CHECK(list[1]["number"] == 3);
    CHECK(list[1]["kind"] == "end_code");
    CHECK(list[1]["first_byte"] == 7);   // the length field: 11 bytes of error information vs 4
    CHECK(list[1]["upstream"]["end_code"] == "C051");
    CHECK(list[1]["upstream"]["bytes"] == lower_hex(c051));
    CHECK(list[1]["twin"]["end_code"] == "0000");
    CHECK(list[1]["text"] == "end code C051, 20 bytes vs end code 0000, 13 bytes");

    CHECK(list[2]["number"] == 6);
    CHECK(list[2]["kind"] == "silence");
    CHECK(list[2]["request"] == lower_hex(read_d400));
    CHECK(list[2]["upstream"] == json{{"kind", "silence"}, {"end_code", nullptr}, {"bytes", nullptr}, {"ms", list[2]["upstream"]["ms"]}});
    CHECK(list[2]["upstream"]["ms"].get<double>() >= 300.0);   // the upstream timeout ran out
    CHECK(list[2]["twin"]["bytes"] == lower_hex(zero));
    CHECK(list[2]["first_byte"].is_null());

    CHECK(list[3]["number"] == 7);
    CHECK(list[3]["kind"] == "close");
    CHECK(list[3]["upstream"]["kind"] == "close");
    CHECK(list[3]["twin"]["kind"] == "answer");
    CHECK(list[3]["text"] == "connection closed vs end code 0000, 13 bytes");

    // The twin's memory took the write the client made through it (the PLC's did too).
    auto d200 = http_get(twin.http_port(), "/api/devices/D200");
    REQUIRE(d200.status == 200);
    CHECK(d200.json()["values"] == json{7});

    const auto metrics = http_get(twin.http_port(), "/metrics").body;
    CHECK(metric(metrics, "slmp_compare_total{result=\"same\"}") == 4);
    CHECK(metric(metrics, "slmp_compare_total{result=\"different\"}") == 4);
    for (const char* kind : {"close", "silence", "end_code", "bytes"})
        CHECK(metric(metrics, std::string("slmp_compare_differences_total{kind=\"") + kind + "\"}") == 1);
    CHECK(metric(metrics, "slmp_compare_differences_total{kind=\"time\"}") == 0);

    // DELETE starts counting afresh.
    auto cleared = http(twin.http_port(), "DELETE", "/api/compare");
    REQUIRE(cleared.status == 200);
    CHECK(cleared.json()["compared"] == 0);
    CHECK(cleared.json()["differences"].empty());

    // One warning a difference, the upstream's side first.
    REQUIRE(twin.stop() == 0);
    const auto logs = twin.logs();
    CHECK(logs.find("compare: #2 0401/0000 from tcp:127.0.0.1:") != std::string::npos);
    CHECK(logs.find(": bytes: upstream vs twin: same end code 0000, bytes differ from offset 11 (13 vs 13 bytes)") != std::string::npos);
    CHECK(logs.find(": end_code: upstream vs twin: end code C051, 20 bytes vs end code 0000, 13 bytes; request " +
                    upper_hex(read_d300)) != std::string::npos);
    CHECK(logs.find(": silence: upstream vs twin: no answer vs end code 0000, 13 bytes") != std::string::npos);
    CHECK(logs.find(": close: upstream vs twin: connection closed vs end code 0000, 13 bytes") != std::string::npos);
    std::size_t warnings = 0;
    for (auto at = logs.find("compare: #"); at != std::string::npos; at = logs.find("compare: #", at + 1)) ++warnings;
    CHECK(warnings == 4);
}

TEST_CASE("compare: the same PLC twice finds no difference — 3E/4E, binary/ASCII, TCP and UDP, writes and reads",
          "[compare][proxy]") {
    SimProcess plc(with_args({"--profile", "Q06UDVCPU-QJ71E71", "--no-http"}));
    auto twin = SimProcess(with_args({"--profile", "Q06UDVCPU-QJ71E71", "--upstream", upstream_of(plc), "--compare",
                                      "--compare-slack", "600"}));
    auto via = TcpClient::open(twin.tcp_port());
    UdpClient via_udp;
    const Wire wires[] = {{FrameKind::E3, Codec::Binary, 0}, {FrameKind::E3, Codec::Ascii, 0},
                          {FrameKind::E4, Codec::Binary, 0x1234}, {FrameKind::E4, Codec::Ascii, 0xBEEF}};
    std::size_t sent = 0;
    for (const auto& w : wires) {
        INFO(w.name());
        const std::vector<Bytes> requests = {
            client::write_words(w.options(), addr("D100"), std::vector<std::uint16_t>{0x1111, 0x2222}),
            client::read_words(w.options(), addr("D100"), 2),
            client::write_bits(w.options(), addr("M10"), std::vector<std::uint8_t>{1, 0, 1}),
            client::read_bits(w.options(), addr("M10"), 3),
            client::read_words(w.options(), addr("D100"), 961),   // the word limit's end code
            client::read_words(w.options(), addr("ZR0"), 2),
            client::read_type_name(w.options()),
        };
        for (const auto& request : requests) {
            ask(via, request);
            ask(via_udp, twin.udp_port(), request);
            sent += 2;
        }
    }
    // 1E, which this profile's QJ71E71 port takes: a word read of D100.
    REQUIRE(via.send(hex("01 FF 0A 00 64 00 00 00 20 44 02 00")));
    CHECK(show(via.read_exactly(6)) == show(hex("81 00 11 11 22 22")));
    ++sent;

    auto report = compare_report(twin);
    INFO(report.dump(2));
    CHECK(report["compared"] == sent);
    CHECK(report["same"] == sent);
    CHECK(report["different"] == 0);
    CHECK(report["differences"].empty());
}

TEST_CASE("compare: a twin of another profile — its own port decides (a 1E frame, the type name)", "[compare][proxy]") {
    // A: Q06UDVCPU behind a QJ71E71, which takes 1E; the twin: R08CPU, whose port does not.
    SimProcess plc(with_args({"--profile", "Q06UDVCPU-QJ71E71", "--no-http"}));
    auto twin = twin_of(upstream_of(plc), {"--compare-slack", "600"});
    auto via = TcpClient::open(twin.tcp_port());
    const auto type_name = client::read_type_name(kBin.options());
    const auto from_plc = ask(via, type_name);
    CHECK(names_cpu(from_plc, "Q06UDVCPU"));   // the client gets the PLC's answer
    REQUIRE(via.send(hex("01 FF 0A 00 64 00 00 00 20 44 01 00")));
    CHECK(show(via.read_exactly(4)) == show(hex("81 00 00 00")));

    auto report = compare_report(twin);
    INFO(report.dump(2));
    CHECK(report["compared"] == 2);
    CHECK(report["different"] == 2);
    const auto& list = report["differences"];
    REQUIRE(list.size() == 2);
    CHECK(list[0]["kind"] == "bytes");   // both 0000, another model name
    CHECK(list[0]["command"] == "0101");
    CHECK(list[0]["upstream"]["bytes"] == lower_hex(from_plc));
    CHECK(list[1]["request"] == "01ff0a006400000020440100");
    CHECK(list[1]["upstream"]["bytes"] == "81000000");
    CHECK(list[1]["twin"]["kind"] != "answer");   // R08CPU's port: no 1E frame
    CHECK(list[1]["kind"] == list[1]["twin"]["kind"]);
}

TEST_CASE("compare: an answer far slower than the twin's is a time difference", "[compare][proxy][timing]") {
    ScenarioSim plc({R"({"faults": [{"do": "delay", "delay_ms": 400, "match": {"devices": "D600"}}]})"}, {"--profile", "R08CPU"});
    auto twin = twin_of(upstream_of(*plc.sim), {"--compare-slack", "0.1"});
    auto via = TcpClient::open(twin.tcp_port());
    CHECK(show(ask(via, read_request(kBin, "D600"))) == show(expected_response(kBin, word_data(kBin, {0}))));

    auto report = compare_report(twin);
    INFO(report.dump(2));
    CHECK(report["slack_ms"] == 100.0);
    CHECK(report["compared"] == 1);
    CHECK(report["kinds"]["time"] == 1);
    const auto& d = report["differences"].at(0);
    CHECK(d["kind"] == "time");
    CHECK(d["upstream"]["bytes"] == d["twin"]["bytes"]);
    CHECK(d["upstream"]["ms"].get<double>() >= 400.0);
    CHECK(d["text"].get<std::string>().find("(far apart: more than twice the shorter plus 100.000 ms)") != std::string::npos);
}

TEST_CASE("compare: in timing mode model the twin's answer time is its modelled one", "[compare][proxy][timing]") {
    SimOptions plc_options = with_args({"--profile", "R08CPU", "--no-http"});
    plc_options.config_json = R"({"devices": {"D100": 5}})";
    SimProcess plc(plc_options);
    SimOptions options = with_args({"--profile", "R08CPU", "--upstream", upstream_of(plc), "--compare", "--compare-slack", "600"});
    options.config_json = R"({"timing": {"mode": "model", "ke_ms": 40, "kdt_ms": 0, "scan_wait": false, "jitter": 0}})";
    SimProcess twin(options);
    auto via = TcpClient::open(twin.tcp_port());
    CHECK(show(ask(via, read_request(kBin, "D100"))) == show(expected_response(kBin, word_data(kBin, {5}))));

    auto report = compare_report(twin);
    INFO(report.dump(2));
    const auto& d = report["differences"].at(0);
    CHECK(d["kind"] == "bytes");
    CHECK(d["twin"]["ms"] == 40.0);   // Ke + Kdt × 1 word, no scan wait, no jitter
}

TEST_CASE("compare: a plant station with \"compare\": true, its metric carries the station label", "[compare][proxy][plant]") {
    SimProcess plc(with_args({"--profile", "R08CPU", "--no-http"}));
    {
        auto direct = TcpClient::open(plc.tcp_port());
        REQUIRE(show(ask(direct, write_request(kBin, "D100", {9}))) == show(expected_response(kBin, {})));
    }
    SimOptions options;
    options.plant = true;
    options.config_json = R"({"bind": "127.0.0.1", "http": {"port": 0}, "stations": [
        {"name": "own", "profile": "R08CPU", "tcp_port": 0},
        {"name": "twin", "profile": "R08CPU", "tcp_port": 0, "upstream": ")" + upstream_of(plc) +
                          R"(", "compare": true, "compare_slack_ms": 600000}]})";
    SimProcess plant(options);
    auto twin = TcpClient::open(tcp_of(plant, "twin"));
    CHECK(show(ask(twin, read_request(kBin, "D100"))) == show(expected_response(kBin, word_data(kBin, {9}))));
    CHECK(show(ask(twin, read_request(kBin, "D0"))) == show(expected_response(kBin, word_data(kBin, {0}))));

    auto report = http_get(plant.http_port(), "/api/stations/twin/compare");
    REQUIRE(report.status == 200);
    CHECK(report.json()["compared"] == 2);
    CHECK(report.json()["kinds"]["bytes"] == 1);
    CHECK(report.json()["slack_ms"] == 600000.0);
    auto own = http_get(plant.http_port(), "/api/stations/own/compare");
    CHECK(own.status == 404);
    CHECK(own.error().find("--upstream HOST:PORT --compare") != std::string::npos);

    const auto metrics = http_get(plant.http_port(), "/metrics").body;
    CHECK(metric(metrics, "slmp_compare_total{station=\"twin\",result=\"same\"}") == 1);
    CHECK(metric(metrics, "slmp_compare_total{station=\"twin\",result=\"different\"}") == 1);
    CHECK(metric(metrics, "slmp_compare_differences_total{station=\"twin\",kind=\"bytes\"}") == 1);
    CHECK(metrics.find("slmp_compare_total{station=\"own\"") == std::string::npos);
}

TEST_CASE("compare: without an upstream it is refused, naming the fix", "[compare][proxy]") {
    auto r = run_sim({"--compare", "--no-http"});
    CHECK(r.exit_code == 2);
    CHECK(r.err.find("--compare without --upstream") != std::string::npos);

    TempDir dir;
    auto bad = dir.write("bad.json", R"({"stations": [{"name": "twin", "tcp_port": 0, "compare": true}]})");
    auto checked = run_sim({"--check-config", bad.string()});
    CHECK(checked.exit_code == 2);
    CHECK(checked.err.find("station 'twin': /compare: \"compare\" without \"upstream\"") != std::string::npos);
    CHECK(checked.err.find("give \"upstream\": \"HOST:PORT\" too") != std::string::npos);
}

TEST_CASE("compare: /api/info names the mode and the upstream, each difference is a compare event, a same answer none",
          "[compare][proxy][events]") {
    SimProcess plc(with_args({"--profile", "R08CPU"}));
    REQUIRE(http(plc.http_port(), "PUT", "/api/devices/D100", R"({"values": [5]})").status == 200);
    auto twin = twin_of(upstream_of(plc), {"--compare-slack", "600"});

    auto info = http_get(twin.http_port(), "/api/info").json();
    CHECK(info["mode"] == "compare");
    CHECK(info["upstream"] == json{{"address", upstream_of(plc)}, {"timeout_ms", 3000}, {"compare", true},
                                   {"compare_slack_ms", 600000.0}});
    CHECK(http_get(plc.http_port(), "/api/info").json()["mode"] == "serve");
    CHECK(http_get(plc.http_port(), "/api/info").json()["upstream"].is_null());

    EventReader events(twin.http_port(), "?types=compare");
    auto via = TcpClient::open(twin.tcp_port());
    const auto same = client::read_words(kBin.options(), addr("D200"), 1);      // 0 on both sides
    const auto different = client::read_words(kBin.options(), addr("D100"), 1);   // 5 upstream, 0 in the twin
    CHECK(show(ask(via, same)) == show(expected_response(kBin, Bytes{0x00, 0x00})));
    CHECK(show(ask(via, different)) == show(expected_response(kBin, Bytes{0x05, 0x00})));

    // The first event is the second request's: the first answered the same and gave none.
    auto event = events.next();
    REQUIRE(event);
    CHECK(event->type == "compare");
    INFO(event->data.dump(2));
    CHECK(event->data["number"] == 2);
    CHECK(event->data["kind"] == "bytes");
    CHECK(event->data["command"] == "0401");
    CHECK(event->data["subcommand"] == "0000");
    CHECK(event->data["request"] == lower_hex(different));
    CHECK(event->data["upstream"]["bytes"] == lower_hex(expected_response(kBin, Bytes{0x05, 0x00})));
    CHECK(event->data["twin"]["bytes"] == lower_hex(expected_response(kBin, Bytes{0x00, 0x00})));
    // As /api/compare lists it.
    auto listed = compare_report(twin)["differences"].at(0);
    for (const char* field : {"number", "kind", "text", "request", "first_byte", "peer", "connection"})
        CHECK(event->data[field] == listed[field]);
    CHECK_FALSE(events.next(std::chrono::milliseconds(300)));
}
