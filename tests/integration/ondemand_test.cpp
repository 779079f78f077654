// Ondemand 2101 (issue 13, docs/timing.md) against the real binary: POST
// /api/ondemand, a scenario step and a trigger push the devices' words to
// connected clients, each in its own frame shape; TCP and UDP; the recording
// and the event stream show the push. Push bytes are asserted exactly.
#include <catch2/catch.hpp>

#include <fstream>
#include <string>
#include <vector>

#include "frames.hpp"
#include "http_client.hpp"
#include "link.hpp"
#include "sim_process.hpp"
#include "sockets.hpp"

using namespace slmp::test;
namespace client = slmp::protocol::client;
using nlohmann::json;

namespace {

const Wire kBin{FrameKind::E3, Codec::Binary, 0};

HttpResponse post(std::uint16_t port, const std::string& target, const std::string& body = "") {
    return http(port, "POST", target, body);
}

Bytes next_frame(TcpClient& c) {
    Bytes frame;
    std::string why;
    if (!c.response(&frame, kReplyTimeout, &why)) FAIL("no frame: " << why);
    return frame;
}

// D100 = 1234H, D101 = 5678H: 3E binary, own-station route, length 0A, end code 0000, 2101 0000, data.
const Bytes kPush3EBinary = hex("d000 00ff ff0300 0a00 0000 0121 0000 3412 7856");

}  // namespace

TEST_CASE("ondemand: POST /api/ondemand pushes the words to a TCP client, in its frame shape", "[ondemand]") {
    SimProcess sim;
    const auto port = sim.http_port();
    REQUIRE(http_put(port, "/api/devices/D100", R"({"values": [4660, 22136]})").status == 200);

    SECTION("3E binary; a client that has not sent a request yet gets 3E binary too") {
        auto c = TcpClient::open(sim.tcp_port());
        // The connection is known to the station once it is listed.
        for (int i = 0; i < 1000 && http_get(port, "/api/connections").json()["connections"].empty(); ++i) {}
        auto r = post(port, "/api/ondemand", R"({"data": "D100-D101", "to": "all"})");
        REQUIRE(r.status == 200);
        REQUIRE(r.json()["sent"].size() == 1);
        CHECK(r.json()["sent"][0]["transport"] == "tcp");
        CHECK(show(next_frame(c)) == show(kPush3EBinary));
    }
    SECTION("4E ASCII after a 4E ASCII request; the connection still answers requests afterwards") {
        const Wire w{FrameKind::E4, Codec::Ascii, 0x1234};
        TcpLink link(sim.tcp_port());
        REQUIRE(show(link.exchange(client::read_words(w.options(), addr("D100"), 1))) ==
                show(expected_response(w, word_data(w, {0x1234}))));
        auto r = post(port, "/api/ondemand", R"({"data": "D100-D101"})");
        REQUIRE(r.json()["sent"].size() == 1);
        const Wire push{FrameKind::E4, Codec::Ascii, 0};
        CHECK(show(next_frame(link.client())) == show(expected_response(push, text("2101000012345678"))));
        CHECK(show(link.exchange(client::read_words(w.options(), addr("D101"), 1))) ==
              show(expected_response(w, word_data(w, {0x5678}))));
    }
    SECTION("to one connection id only") {
        auto a = TcpClient::open(sim.tcp_port());
        auto b = TcpClient::open(sim.tcp_port());
        json list;
        for (int i = 0; i < 1000; ++i) {
            list = http_get(port, "/api/connections").json()["connections"];
            if (list.size() == 2) break;
        }
        REQUIRE(list.size() == 2);
        const auto second = list[1]["id"].get<std::uint64_t>();
        auto r = post(port, "/api/ondemand", R"({"data": "D100-D101", "to": )" + std::to_string(second) + "}");
        REQUIRE(r.json()["sent"].size() == 1);
        CHECK(r.json()["sent"][0]["connection"] == second);
        CHECK(show(next_frame(b)) == show(kPush3EBinary));
        CHECK(a.recv_some(std::chrono::milliseconds(0)).status == RecvStatus::Timeout);
    }
    SECTION("bad input: the error names the problem") {
        CHECK(post(port, "/api/ondemand", R"({"data": "D100-W5"})").error() ==
              "\"data\": the range mixes D and W; write a device range such as \"D100-D109\" (at most 960 words)");
        CHECK(post(port, "/api/ondemand", R"({"data": "D0-D999"})").error() ==
              "\"data\": more than 960 words (the Ondemand limit of 1920 bytes); write a device range such as \"D100-D109\" (at most 960 words)");
        CHECK(post(port, "/api/ondemand", R"({"data": "D100", "to": "everyone"})").error() ==
              "ondemand: unknown target 'everyone'; use \"all\", \"tcp\", \"udp\" or a TCP connection id");
        CHECK(post(port, "/api/ondemand", R"({"data": "D100", "to": "all"})").json()["sent"].empty());
    }
}

TEST_CASE("ondemand over UDP: the peers that have sent a request get a datagram", "[ondemand]") {
    SimProcess sim;
    const auto port = sim.http_port();
    REQUIRE(http_put(port, "/api/devices/D100", R"({"values": [4660, 22136]})").status == 200);
    UdpClient u;
    REQUIRE(u.send_to(sim.udp_port(), client::read_words(kBin.options(), addr("D100"), 1)));
    REQUIRE(u.receive());
    auto r = post(port, "/api/ondemand", R"({"data": "D100-D101", "to": "udp"})");
    REQUIRE(r.json()["sent"].size() == 1);
    CHECK(r.json()["sent"][0]["transport"] == "udp");
    auto push = u.receive();
    REQUIRE(push);
    CHECK(show(*push) == show(kPush3EBinary));
}

TEST_CASE("ondemand: a scenario step pushes at its time, the recording and the event stream show it", "[ondemand]") {
    TempDir dir;
    auto scenario = dir.write("push.json", R"({
        "name": "push",
        "initial": {"devices": {"D100": [4660, 22136]}},
        "timeline": {"steps": [{"at_ms": 100, "ondemand": {"data": "D100-D101", "to": "all"}}]},
        "triggers": [{"when": "M0 == 1", "times": 1, "do": [{"ondemand": {"data": "D101"}}]}]
    })");
    const auto recording = dir.path() / "rec.jsonl";
    SimOptions options;
    options.args = {"--clock", "frozen", "--scenario", scenario.string(), "--record", recording.string()};
    SimProcess sim(options);
    const auto port = sim.http_port();
    EventReader events(port, "?types=request");
    auto c = TcpClient::open(sim.tcp_port());
    for (int i = 0; i < 1000 && http_get(port, "/api/connections").json()["connections"].empty(); ++i) {}
    // The scenario's clock starts at the first scan: 200 ms of steps pass its 100 ms.
    REQUIRE(post(port, "/api/clock/step", R"({"ms": 200})").status == 200);
    CHECK(show(next_frame(c)) == show(kPush3EBinary));
    std::optional<ServerEvent> event;
    while ((event = events.next()) && event->type != "ondemand") {}
    REQUIRE(event);
    CHECK(event->data["frame"] == "d00000ffff03000a000000012100003412" "7856");
    CHECK(event->data["why"] == "timeline /timeline/steps/0");
    // The trigger: one word.
    REQUIRE(http_put(port, "/api/devices/M0", R"({"values": [1]})").status == 200);
    REQUIRE(post(port, "/api/clock/step", R"({"scans": 1})").status == 200);
    CHECK(show(next_frame(c)) == show(hex("d000 00ff ff0300 0800 0000 0121 0000 7856")));
    sim.stop(SIGTERM);
    std::ifstream in(recording);
    std::string line;
    std::vector<json> pushes;
    while (std::getline(in, line)) {
        auto j = json::parse(line);
        if (j.value("event", "") == "ondemand") pushes.push_back(j);
    }
    REQUIRE(pushes.size() == 2);
    CHECK(pushes[0]["response"] == "d00000ffff03000a000000012100003412" "7856");
    CHECK(pushes[0]["transport"] == "tcp");
}

TEST_CASE("slmp ondemand --wait prints the pushed words", "[ondemand][cli]") {
    SimProcess sim;
    const auto port = sim.http_port();
    REQUIRE(http_put(port, "/api/devices/D100", R"({"values": [4660, 22136]})").status == 200);
    TempDir dir;
    const std::vector<std::string> args = {"--port", std::to_string(sim.tcp_port()), "--timeout", "20s", "--json", "ondemand", "--wait"};
    const auto pid = detail::spawn(args, dir.path() / "out", dir.path() / "err", under_test(SLMP_CLI_BINARY));
    // The CLI is connected once the station lists its connection.
    json list;
    for (int i = 0; i < 2000; ++i) {
        list = http_get(port, "/api/connections").json()["connections"];
        if (!list.empty()) break;
    }
    REQUIRE(list.size() == 1);
    REQUIRE(post(port, "/api/ondemand", R"({"data": "D100-D101"})").json()["sent"].size() == 1);
    auto status = detail::wait_for(pid, std::chrono::seconds(20));
    REQUIRE(status);
    CHECK(WIFEXITED(*status));
    CHECK(WEXITSTATUS(*status) == 0);
    auto out = read_text(dir.path() / "out");
    INFO(out << read_text(dir.path() / "err"));
    CHECK(json::parse(out) == json{{"command", "2101"}, {"push", 1}, {"words", {4660, 22136}}});
}
