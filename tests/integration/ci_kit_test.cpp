// The CI user's kit against the real binary (issue 18, docs/ci.md): station
// snapshots and reset over HTTP, checked over SLMP and HTTP; the frozen and
// stepped clock; waiting for a value; --check-config. No sleeps for time to
// pass: a wait is bounded by its own timeout and by the reply timeout of the
// test socket, and a poll for readiness by the reply timeout.
#include <catch2/catch.hpp>

#include <string>
#include <thread>
#include <vector>

#include "frames.hpp"
#include "protocol/client_labels.hpp"
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

std::string ask(TcpLink& link, const Bytes& request) { return show(link.exchange(request)); }
Bytes ok(const Wire& w) { return expected_response(w, {}); }
Bytes ok_words(const Wire& w, std::initializer_list<std::uint16_t> values) { return expected_response(w, word_data(w, values)); }
Bytes refused(const Wire& w, std::uint16_t code, std::uint16_t command) {
    return expected_response(w, error_info(w, command, 0), code);
}
Bytes password(const Wire& w, std::uint16_t command, const std::string& text) {
    return client::build_request(w.options(), command, 0x0000, [&](slmp::protocol::FieldWriter& f) {
        f.u16(static_cast<std::uint16_t>(text.size()));
        f.raw(slmp::test::text(text));
    });
}
Bytes remote_stop(const Wire& w) {
    return client::build_request(w.options(), 0x1002, 0x0000, [](slmp::protocol::FieldWriter& f) { f.u16(0x0001); });
}

json words(std::uint16_t port, const std::string& target) { return http_get(port, target).json()["values"]; }

// An HTTP request whose answer is read later: the test goes on meanwhile.
TcpClient send_request(std::uint16_t port, const std::string& target) {
    auto c = TcpClient::open(port);
    std::string request = "GET " + target + " HTTP/1.1\r\nHost: 127.0.0.1\r\nConnection: close\r\n\r\n";
    REQUIRE(c.send(request));
    return c;
}

// True once /api/info counts `pending` waits (false after the reply timeout).
bool wait_counted(std::uint16_t port, int pending) {
    const auto deadline = std::chrono::steady_clock::now() + kReplyTimeout;
    while (std::chrono::steady_clock::now() < deadline) {
        if (http_get(port, "/api/info").json()["waits"] == pending) return true;
        std::this_thread::sleep_for(std::chrono::milliseconds(5));
    }
    return false;
}

HttpResponse read_response(TcpClient& c) {
    std::string data;
    for (;;) {
        auto got = c.recv_some(kReplyTimeout);
        if (got.status == RecvStatus::Eof) break;
        if (got.status != RecvStatus::Data) FAIL("no complete response within the reply timeout; got: " << data);
        data.append(got.data.begin(), got.data.end());
    }
    HttpResponse response;
    auto body_start = detail::parse_head(data, &response);
    REQUIRE(body_start != std::string::npos);
    response.body = data.substr(body_start);
    return response;
}

const char* kConfig = R"({
  "modules": [{"start_io": "0030", "model": "Q62DA", "buffer_words": 4096}],
  "devices": {"D0": [11, 12]},
  "cpu": {"password": "secret7", "password_lockout": {"attempts": 2, "seconds": 600}, "scan_time_ms": 100,
          "timers": [{"device": "T0", "preset": 20, "base_ms": 100}]}
})";

const char* kRamp = R"({"name": "ramp", "timeline": {"steps": [{"at_ms": 0, "ramp": "D500", "from": 0, "to": 1000, "over_ms": 10000}]}})";

}  // namespace

TEST_CASE("snapshots: change everything, restore, every value back over SLMP and HTTP", "[ci][snapshot]") {
    SimOptions options;
    options.config_json = kConfig;
    options.args = {"--clock", "frozen"};
    SimProcess sim(options);
    const auto port = sim.http_port();
    TcpLink link(sim.tcp_port());
    REQUIRE(ask(link, password(kBin, 0x1630, "secret7")) == show(ok(kBin)));

    REQUIRE(http_put(port, "/api/devices/D100", R"({"values": [1, 2, 3]})").status == 200);
    REQUIRE(http_put(port, "/api/buffer/U3/G10", R"({"values": [77]})").status == 200);
    auto taken = post(port, "/api/snapshots", R"({"name": "clean"})");
    REQUIRE(taken.status == 201);
    CHECK(taken.json()["name"] == "clean");
    CHECK(taken.json()["replaced"] == false);
    const auto sd203 = ask(link, client::read_words(kBin.options(), addr("SD203"), 1));

    // Change everything: devices, buffer memory, STOP, a password lock-out, a running scenario.
    REQUIRE(ask(link, client::write_words(kBin.options(), addr("D100"), std::vector<std::uint16_t>{9, 9, 9})) == show(ok(kBin)));
    REQUIRE(http_put(port, "/api/devices/M5", R"({"values": [1]})").status == 200);
    REQUIRE(http_put(port, "/api/buffer/U3/G10", R"({"values": [5]})").status == 200);
    REQUIRE(ask(link, remote_stop(kBin)) == show(ok(kBin)));
    CHECK(http_get(port, "/api/state").json()["state"] == "STOP");
    {
        TcpLink other(sim.tcp_port());
        CHECK(ask(other, password(kBin, 0x1630, "wrong11")) == show(refused(kBin, 0xC810, 0x1630)));
        CHECK(ask(other, password(kBin, 0x1630, "wrong11")) == show(refused(kBin, 0xC810, 0x1630)));
        CHECK(ask(other, password(kBin, 0x1630, "secret7")) == show(refused(kBin, 0xC815, 0x1630)));
    }
    REQUIRE(post(port, "/api/scenarios", kRamp).status == 201);
    REQUIRE(post(port, "/api/clock/step", R"({"ms": 5000})").status == 200);
    CHECK(words(port, "/api/devices/D500")[0] != 0);

    auto restored = post(port, "/api/snapshots/clean/restore");
    REQUIRE(restored.status == 200);
    CHECK(restored.json()["restored"] == "clean");

    // Over SLMP, on the connection that stayed open (it stays unlocked: per connection).
    CHECK(ask(link, client::read_words(kBin.options(), addr("D100"), 3)) == show(ok_words(kBin, {1, 2, 3})));
    CHECK(ask(link, client::read_words(kBin.options(), addr("D0"), 2)) == show(ok_words(kBin, {11, 12})));
    CHECK(ask(link, client::read_words(kBin.options(), addr("D500"), 1)) == show(ok_words(kBin, {0})));
    CHECK(ask(link, client::read_words(kBin.options(), addr("SD203"), 1)) == sd203);
    // Over HTTP.
    CHECK(words(port, "/api/devices/D100?count=3") == json{1, 2, 3});
    CHECK(words(port, "/api/devices/M5") == json{0});
    CHECK(words(port, "/api/buffer/U3/G10") == json{77});
    CHECK(http_get(port, "/api/state").json()["state"] == "RUN");
    CHECK(http_get(port, "/api/scenarios").json()["scenarios"].empty());
    // The lock-out is over: the right password opens a new connection again.
    {
        TcpLink other(sim.tcp_port());
        CHECK(ask(other, password(kBin, 0x1630, "secret7")) == show(ok(kBin)));
    }
    // A snapshot with a scenario running brings the scenario back (started afresh).
    REQUIRE(post(port, "/api/scenarios", kRamp).status == 201);
    REQUIRE(post(port, "/api/snapshots", R"({"name": "with-ramp"})").status == 201);
    REQUIRE(http(port, "DELETE", "/api/scenarios/ramp").status == 200);
    REQUIRE(post(port, "/api/snapshots/with-ramp/restore").status == 200);
    CHECK(http_get(port, "/api/scenarios").json()["scenarios"][0]["name"] == "ramp");

    auto list = http_get(port, "/api/snapshots").json()["snapshots"];
    REQUIRE(list.size() == 2);
    CHECK(list[0]["name"] == "clean");
    CHECK(http(port, "DELETE", "/api/snapshots/clean").json() == json{{"deleted", "clean"}});
    auto gone = post(port, "/api/snapshots/clean/restore");
    CHECK(gone.status == 404);
    CHECK(gone.error() == "no snapshot 'clean'; the saved ones are with-ramp");
    CHECK(post(port, "/api/snapshots", R"({"name": "a b"})").error() ==
          "snapshot name 'a b': use 1-64 letters, digits, '-', '_' or '.'");
}

TEST_CASE("reset: back to the configuration's initial state, drop_connections closes the clients", "[ci][snapshot]") {
    SimOptions options;
    options.config_json = kConfig;
    SimProcess sim(options);
    const auto port = sim.http_port();
    TcpLink link(sim.tcp_port());
    REQUIRE(ask(link, password(kBin, 0x1630, "secret7")) == show(ok(kBin)));
    REQUIRE(ask(link, client::write_words(kBin.options(), addr("D0"), std::vector<std::uint16_t>{1, 1, 1})) == show(ok(kBin)));
    REQUIRE(http_put(port, "/api/buffer/U3/G0", R"({"values": [3]})").status == 200);
    REQUIRE(http_put(port, "/api/state", R"({"switch": "STOP"})").status == 200);

    auto reset = post(port, "/api/reset");
    REQUIRE(reset.status == 200);
    CHECK(reset.json()["reset"] == true);
    CHECK(ask(link, client::read_words(kBin.options(), addr("D0"), 3)) == show(ok_words(kBin, {11, 12, 0})));
    CHECK(words(port, "/api/buffer/U3/G0") == json{0});
    CHECK(http_get(port, "/api/state").json()["switch"] == "RUN");

    REQUIRE(post(port, "/api/reset", R"({"drop_connections": true})").status == 200);
    auto closed = link.client().recv_some(kReplyTimeout);
    CHECK((closed.status == RecvStatus::Eof || closed.status == RecvStatus::Error));
    CHECK(post(port, "/api/reset", R"({"drop": true})").error() ==
          "unknown key \"drop\" in the body; send {\"drop_connections\": true} (or no body)");
}

TEST_CASE("snapshot file: saved with the API, started from with --snapshot", "[ci][snapshot]") {
    TempDir dir;
    auto file = (dir.path() / "clean.snap").string();
    {
        SimProcess sim;
        REQUIRE(http_put(sim.http_port(), "/api/devices/D7", R"({"values": [4242]})").status == 200);
        REQUIRE(http_put(sim.http_port(), "/api/state", R"({"switch": "STOP"})").status == 200);
        auto r = post(sim.http_port(), "/api/snapshots", R"({"name": "clean", "file": ")" + file + R"("})");
        REQUIRE(r.status == 201);
        auto fetched = http_get(sim.http_port(), "/api/snapshots/clean/file");
        CHECK(fetched.header("content-type") == "application/octet-stream");
        std::ifstream in(file, std::ios::binary);
        CHECK(std::string(std::istreambuf_iterator<char>(in), {}) == fetched.body);
    }
    SimProcess sim(with_args({"--snapshot", file}));
    CHECK(words(sim.http_port(), "/api/devices/D7") == json{4242});
    CHECK(http_get(sim.http_port(), "/api/state").json()["switch"] == "STOP");
    // Reset goes back to the configuration, not to the file.
    REQUIRE(post(sim.http_port(), "/api/reset").status == 200);
    CHECK(words(sim.http_port(), "/api/devices/D7") == json{0});

    auto bad = run_sim({"--snapshot", dir.write("bad.snap", "nonsense").string(), "--tcp-port", "0", "--udp-port", "0",
                        "--http-port", "0"});
    CHECK(bad.exit_code == 2);
    CHECK(bad.err.find("not a slmp-sim station snapshot (bad magic)") != std::string::npos);
}

TEST_CASE("frozen clock: timers do not move, 20 steps of 100 ms set a K20 timer's contact at the 20th", "[ci][clock]") {
    SimOptions options;
    options.config_json = kConfig;
    options.args = {"--clock", "frozen"};
    SimProcess sim(options);
    const auto port = sim.http_port();
    auto clock = http_get(port, "/api/clock").json();
    CHECK(clock["mode"] == "frozen");
    CHECK(clock["scan_time_ms"] == 100);
    const double start_ms = clock["clock_ms"];

    REQUIRE(http_put(port, "/api/devices/TC0", R"({"values": [1]})").status == 200);
    // The scan that first sees the coil starts timing (from 0), as OUT T0 does.
    REQUIRE(post(port, "/api/clock/step", R"({"scans": 1})").status == 200);
    CHECK(words(port, "/api/devices/TN0") == json{0});
    // Nothing moves while frozen, however long the test takes.
    CHECK(http_get(port, "/api/clock").json()["clock_ms"] == start_ms + 100);
    CHECK(words(port, "/api/devices/TN0") == json{0});
    for (int step = 1; step <= 20; ++step) {
        INFO("step " << step);
        auto r = post(port, "/api/clock/step", R"({"scans": 1})");
        REQUIRE(r.status == 200);
        CHECK(words(port, "/api/devices/TN0") == json{step});
        CHECK(words(port, "/api/devices/TS0") == json{step == 20 ? 1 : 0});
    }
    CHECK(http_get(port, "/api/clock").json()["clock_ms"] == start_ms + 2100);

    // Stepping by time: 1500 ms is 15 scans of 100 ms.
    auto r = post(port, "/api/clock/step", R"({"ms": 1500})");
    CHECK(r.json()["clock_ms"] == start_ms + 3600);
    CHECK(r.json()["mode"] == "frozen");

    CHECK(post(port, "/api/clock/step", R"({"scans": 0})").error() == "\"scans\" must be a whole number from 1 to 1000000");
    CHECK(http_put(port, "/api/clock", R"({"mode": "sleepy"})").error() ==
          "\"mode\" must be \"realtime\" or \"frozen\"; send {\"mode\": \"realtime\", \"speed\": 10} or {\"mode\": \"frozen\"}");
    auto running = http_put(port, "/api/clock", R"({"mode": "realtime", "speed": 10})").json();
    CHECK(running["mode"] == "realtime");
    CHECK(running["speed"] == 10);
    auto refused_step = post(port, "/api/clock/step", R"({"scans": 1})");
    CHECK(refused_step.status == 409);
}

TEST_CASE("frozen clock: a scenario ramp advances only by steps, the same on every run", "[ci][clock]") {
    auto run = [] {
        SimProcess sim(with_args({"--clock", "frozen"}));
        const auto port = sim.http_port();
        REQUIRE(post(port, "/api/scenarios", kRamp).status == 201);
        std::vector<json> seen;
        for (int i = 0; i < 4; ++i) {
            seen.push_back(words(port, "/api/devices/D500")[0]);
            seen.push_back(words(port, "/api/devices/D500")[0]);   // no step: no change
            REQUIRE(post(port, "/api/clock/step", R"({"ms": 1000})").status == 200);
        }
        seen.push_back(words(port, "/api/devices/D500")[0]);
        return seen;
    };
    auto first = run();
    for (std::size_t i = 0; i + 2 < first.size(); i += 2) CHECK(first[i] == first[i + 1]);
    CHECK(first.back() != first.front());
    CHECK(run() == first);
}

TEST_CASE("wait: answers when an SLMP write lands, 408 with the last value at the timeout", "[ci][wait]") {
    SimProcess sim;
    const auto port = sim.http_port();
    TcpLink link(sim.tcp_port());

    // Far longer than the reply timeout: an answer within it came from the write.
    auto pending = send_request(port, "/api/devices/D100/wait?equals=5&timeout_ms=600000");
    // The server keeps serving others meanwhile.
    CHECK(http_get(port, "/api/info").status == 200);
    REQUIRE(ask(link, client::write_words(kBin.options(), addr("D100"), std::vector<std::uint16_t>{5})) == show(ok(kBin)));
    auto answered = read_response(pending);
    CHECK(answered.status == 200);
    CHECK(answered.json()["value"] == 5);
    CHECK(answered.json()["device"] == "D100");
    CHECK(answered.json()["condition"] == "equals 5");

    auto bit = send_request(port, "/api/devices/M3/wait?equals=1&timeout_ms=600000");
    REQUIRE(ask(link, client::write_bits(kBin.options(), addr("M3"), std::vector<std::uint8_t>{1})) == show(ok(kBin)));
    CHECK(read_response(bit).json()["value"] == 1);

    auto greater = http_get(port, "/api/devices/D100/wait?greater=4&timeout_ms=10");
    CHECK(greater.status == 200);

    auto timeout = http_get(port, "/api/devices/D100/wait?equals=6&timeout_ms=50");
    CHECK(timeout.status == 408);
    CHECK(timeout.json()["value"] == 5);
    CHECK(timeout.error() ==
          "D100 did not meet 'equals 6' within 50 ms; its last value is 5 (raise timeout_ms, or check what should write it)");
    CHECK(http_get(port, "/api/devices/D100/wait?changes&timeout_ms=20").status == 408);

    CHECK(http_get(port, "/api/devices/D100/wait").error() ==
          "say what to wait for: equals=N, not_equals=N, greater=N, less=N or changes (and timeout_ms=N)");
    CHECK(http_get(port, "/api/devices/D100/wait?equals=five").error() ==
          "'five' is not a number; give an integer such as 5, -1 or, for bits, 0/1");
    CHECK(http_get(port, "/api/devices/D100/wait?equals=1&less=3").error() ==
          "give one condition: equals and less were both given; wait twice for two conditions");
    CHECK(http_get(port, "/api/devices/D100/wait?equals=1&timeout_ms=soon").status == 400);
    CHECK(http_get(port, "/api/devices/D100/wait?equals=1&timeout=5").error() ==
          "unknown query parameter 'timeout' for /api/devices/D100/wait; use equals, not_equals, greater, less, changes, "
          "timeout_ms, as");
}

TEST_CASE("wait on a label: in the label area and on a device, woken by 141B, FLOAT refused", "[ci][wait][labels]") {
    SimOptions options;
    options.config_json = R"({"labels": [{"name": "Count", "type": "Word [Signed]"},
                                         {"name": "LabelW", "type": "Word [Signed]", "device": "D9000"},
                                         {"name": "Speed", "type": "FLOAT [Single Precision]"}]})";
    SimProcess sim(options);
    const auto port = sim.http_port();
    TcpLink link(sim.tcp_port());
    auto write_label = [&](const std::string& name, std::uint16_t value) {
        client::LabelWrite write{name, {slmp::devicemodel::BasicType::Word, {value}}};
        return ask(link, client::label_write_random(kBin.options(), std::span(&write, 1)));
    };

    // A label in the label area: only the label area changes, and that wakes the wait.
    auto area = send_request(port, "/api/labels/Count/wait?equals=-1&timeout_ms=600000");
    REQUIRE(write_label("Count", 0xFFFF) == show(ok(kBin)));
    auto answered = read_response(area);
    CHECK(answered.status == 200);
    CHECK(answered.json()["label"] == "Count");
    CHECK(answered.json()["condition"] == "equals -1");

    // A label on D9000: the device write wakes it.
    // "changes" counts from when the wait began: the write must come after it,
    // and the two connections are served in no fixed order.
    auto on_device = send_request(port, "/api/labels/LabelW/wait?changes&timeout_ms=600000");
    REQUIRE(wait_counted(port, 1));
    REQUIRE(write_label("LabelW", 7) == show(ok(kBin)));
    CHECK(read_response(on_device).status == 200);
    CHECK(words(port, "/api/devices/D9000") == json::array({7}));

    auto timeout = http_get(port, "/api/labels/LabelW/wait?equals=8&timeout_ms=50");
    CHECK(timeout.status == 408);
    CHECK(timeout.json()["value"] == 7);
    CHECK(http_get(port, "/api/labels/Speed/wait?equals=1").error() ==
          "label 'Speed' holds a FLOAT, which cannot be waited on; wait on a bit, integer or TIME label");
    CHECK(http_get(port, "/api/labels/Nope/wait?equals=1").status == 404);

    // Labels are in a snapshot: both kinds come back with a restore.
    REQUIRE(post(port, "/api/snapshots", R"({"name": "labels"})").status == 201);
    REQUIRE(write_label("Count", 42) == show(ok(kBin)));
    REQUIRE(write_label("LabelW", 43) == show(ok(kBin)));
    REQUIRE(post(port, "/api/snapshots/labels/restore").status == 200);
    CHECK(http_get(port, "/api/labels/Count").json()["values"] == json::array({-1}));
    CHECK(http_get(port, "/api/labels/LabelW").json()["values"] == json::array({7}));
}

TEST_CASE("check-config: exit 0 for a good file, 2 with the one-line error for a bad one", "[ci][cli]") {
    TempDir dir;
    auto good = dir.write("good.json", kConfig);
    auto r = run_sim({"--check-config", good.string()});
    CHECK(r.exit_code == 0);
    CHECK(r.out == "slmp-sim: configuration OK\n");

    auto bad = dir.write("bad.json", R"({"devices": {"Q100": 1}})");
    r = run_sim({"--check-config", bad.string()});
    CHECK(r.exit_code == 2);
    CHECK(r.err.find("bad.json: /devices/Q100: unknown device") != std::string::npos);
    CHECK(lines_of(r.err).size() == 1);

    // The scenarios it is given are checked against the CPU too.
    auto scenario = dir.write("s.json", R"({"name": "x", "timeline": {"steps": [{"at_ms": 0, "set": {"D99999": 1}}]}})");
    r = run_sim({"--check-config", good.string(), "--scenario", scenario.string()});
    CHECK(r.exit_code == 2);
    CHECK(r.err.find("s.json") != std::string::npos);
    CHECK(lines_of(r.err).size() == 1);
    auto fine = dir.write("fine.json", kRamp);
    CHECK(run_sim({"--check-config", good.string(), "--scenario", fine.string()}).exit_code == 0);
}
