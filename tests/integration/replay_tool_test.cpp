// slmp-replay, the client-side replay (docs/scenarios.md "Record & replay"):
// a session recorded against slmp-sim replays against a fresh simulator with
// no differences (exit 0), against one whose D200 holds another value with the
// differing exchange named by its kind (exit 1; --json in /api/compare's
// shape), and against nothing with exit 2. --to-scenario turns a committed
// recording's reads into a scenario that answers the same reads at the same
// times (docs/twin.md, "Recording → scenario").
#include <catch2/catch.hpp>

#include <cmath>
#include <map>

#include "ask.hpp"
#include "http_client.hpp"
#include "scenario_support.hpp"

#ifndef SLMP_REPLAY_BINARY
#error "SLMP_REPLAY_BINARY must name the slmp-replay executable under test"
#endif

using namespace slmp::test;
using namespace std::chrono_literals;
namespace client = slmp::protocol::client;

namespace {

// The recorded simulator's D200-D201; the "different" one has another D201.
const std::string kConfig = R"({"devices": {"D200": [5, 6]}})";
const std::string kOtherConfig = R"({"devices": {"D200": [5, 7]}})";

SimOptions sim_with(const std::string& config, std::vector<std::string> args = {}) {
    SimOptions options;
    options.config_json = config;
    options.args = std::move(args);
    options.args.push_back("--no-http");
    return options;
}

// TCP: read D200-D201 (#1), write and read D100, the type name, a 4E read; UDP: read D100.
void run_session(const SimProcess& sim) {
    TcpLink tcp(sim.tcp_port());
    REQUIRE_FALSE(tcp.exchange(read_request(kBinary3E, "D200", 2)).empty());
    REQUIRE_FALSE(tcp.exchange(write_request(kBinary3E, "D100", {11, 22, 33})).empty());
    REQUIRE_FALSE(tcp.exchange(read_request(kBinary3E, "D100", 3)).empty());
    REQUIRE_FALSE(tcp.exchange(client::read_type_name(kBinary3E.options())).empty());
    REQUIRE_FALSE(tcp.exchange(read_request(Wire{FrameKind::E4, Codec::Binary, 0x0102}, "D101", 2)).empty());
    UdpLink udp(sim.udp_port());
    REQUIRE_FALSE(udp.exchange(read_request(kBinary3E, "D100", 3)).empty());
}

// Bytes as slmp-replay prints them (and the recording holds them).
std::string lower_hex(const Bytes& bytes) {
    static constexpr char digits[] = "0123456789abcdef";
    std::string text;
    for (auto b : bytes) text += {digits[b >> 4], digits[b & 0xF]};
    return text;
}

RunResult replay(const std::filesystem::path& recording, const SimProcess& sim) {
    return run_binary(under_test(SLMP_REPLAY_BINARY),
                      {recording.string(), "--host", "127.0.0.1", "--port", std::to_string(sim.tcp_port()), "--udp-port",
                       std::to_string(sim.udp_port())},
                      30s);
}

}  // namespace

TEST_CASE("slmp-replay: a recorded session replays against slmp-sim, differences are named", "[scenario][replay][replay-tool]") {
    TempDir dir;
    auto recording = dir.path() / "session.jsonl";
    {
        SimProcess sim(sim_with(kConfig, {"--record", recording.string()}));
        run_session(sim);
    }
    REQUIRE(lines_of(read_text(recording)).size() >= 7);   // header + 6 exchanges (+ open/close)

    SECTION("a simulator like the recorded one: no differences, exit 0") {
        SimProcess sim(sim_with(kConfig));
        auto r = replay(recording, sim);
        INFO(r.out << r.err);
        CHECK(r.exit_code == 0);
        CHECK(r.out.find("6 exchange(s): 6 identical, 0 different") != std::string::npos);
    }
    SECTION("a simulator with another value in D201: the exchange that reads it differs, exit 1") {
        SimProcess sim(sim_with(kOtherConfig));
        auto r = replay(recording, sim);
        INFO(r.out << r.err);
        CHECK(r.exit_code == 1);
        CHECK(r.out.find("#1 (connection") != std::string::npos);
        CHECK(r.out.find("request " + lower_hex(read_request(kBinary3E, "D200", 2))) != std::string::npos);
        CHECK(r.out.find("6 exchange(s): 5 identical, 1 different (bytes 1)") != std::string::npos);
        // D201 is the second data word: from offset 13 in a 3E binary answer.
        CHECK(r.out.find("  bytes: recorded vs now: same end code 0000, bytes differ from offset 13 (15 vs 15 bytes)") !=
              std::string::npos);
    }
    SECTION("--json: every difference in GET /api/compare's shape, recorded vs now") {
        SimProcess sim(sim_with(kOtherConfig));
        auto r = run_binary(SLMP_REPLAY_BINARY, {recording.string(), "--port", std::to_string(sim.tcp_port()), "--udp-port",
                                                 std::to_string(sim.udp_port()), "--json"}, 30s);
        INFO(r.out << r.err);
        CHECK(r.exit_code == 1);
        auto report = nlohmann::json::parse(r.out);
        CHECK(report["exchanges"] == 6);
        CHECK(report["same"] == 5);
        CHECK(report["different"] == 1);
        CHECK(report["kinds"] == nlohmann::json{{"close", 0}, {"silence", 0}, {"end_code", 0}, {"bytes", 1}, {"time", 0}});
        const auto& d = report["differences"].at(0);
        CHECK(d["exchange"] == 1);
        CHECK(d["kind"] == "bytes");
        CHECK(d["first_byte"] == 13);
        CHECK(d["request"] == lower_hex(read_request(kBinary3E, "D200", 2)));
        CHECK(d["recorded"]["bytes"] == lower_hex(expected_response(kBinary3E, word_data(kBinary3E, {5, 6}))));
        CHECK(d["now"]["bytes"] == lower_hex(expected_response(kBinary3E, word_data(kBinary3E, {5, 7}))));
        CHECK(d["now"]["end_code"] == "0000");
        CHECK(d["now"]["ms"].is_null());   // a replay compares no times
    }
}

TEST_CASE("slmp-replay: no server, a missing recording or a bad option is exit 2", "[scenario][replay][replay-tool]") {
    TempDir dir;
    auto recording = dir.path() / "session.jsonl";
    std::uint16_t gone_tcp = 0, gone_udp = 0;
    {
        SimProcess sim(sim_with(kConfig, {"--record", recording.string()}));
        run_session(sim);
        gone_tcp = sim.tcp_port();
        gone_udp = sim.udp_port();
    }
    // The simulator has exited: its ports are free again (nothing listens there).
    auto r = run_binary(under_test(SLMP_REPLAY_BINARY), {recording.string(), "--port", std::to_string(gone_tcp), "--udp-port",
                                             std::to_string(gone_udp)}, 30s);
    CHECK(r.exit_code == 2);
    CHECK(r.err.find("cannot connect") != std::string::npos);

    r = run_binary(under_test(SLMP_REPLAY_BINARY), {(dir.path() / "nope.jsonl").string()});
    CHECK(r.exit_code == 2);
    CHECK(r.err.find("nope.jsonl: cannot open the recording") != std::string::npos);
    CHECK(run_binary(under_test(SLMP_REPLAY_BINARY), {recording.string(), "--port", "70000"}).exit_code == 2);
    CHECK(run_binary(under_test(SLMP_REPLAY_BINARY), {}).exit_code == 2);

    auto help = run_binary(under_test(SLMP_REPLAY_BINARY), {"--help"});
    CHECK(help.exit_code == 0);
    for (const char* option : {"--host", "--port", "--udp-port", "--timeout-ms", "--silence-ms", "--pace", "Exit status"})
        CHECK(help.out.find(option) != std::string::npos);
}

namespace {

// The scenario clock of the one running scenario (it starts with the first scan).
double scenario_clock(std::uint16_t http_port) {
    auto r = http_get(http_port, "/api/scenarios");
    REQUIRE(r.status == 200);
    return r.json()["scenarios"].at(0)["clock_ms"].get<double>();
}

// Runs `scenario` in slmp-sim on a frozen clock, steps the clock to each
// exchange's recorded time (from the first exchange) and sends its request
// again: the answer must be the recorded one, byte for byte. Returns how many
// exchanges were sent.
std::size_t replay_at_recorded_times(const std::filesystem::path& recording, const std::filesystem::path& scenario) {
    SimProcess sim(with_args({"--scenario", scenario.string(), "--clock", "frozen"}));
    const auto http_port = sim.http_port();
    std::map<std::uint64_t, TcpClient> tcp;
    UdpClient udp;
    std::optional<double> first;
    std::size_t replayed = 0;
    for (const auto& line : lines_of(read_text(recording))) {
        auto entry = nlohmann::json::parse(line);
        if (entry.value("event", "") != "exchange") continue;
        const double t = entry["t_ms"].get<double>();
        if (!first) first = t;
        const double target = t - *first;
        for (double now = scenario_clock(http_port); now < target; now = scenario_clock(http_port))
            REQUIRE(http(http_port, "POST", "/api/clock/step",
                         "{\"ms\": " + std::to_string(std::max(1.0, std::ceil(target - now))) + "}").status == 200);
        const auto request = hex(entry["request"].get<std::string>());
        const auto recorded = hex(entry["response"].get<std::string>());
        INFO("exchange at " << t << " ms: " << entry["request"]);
        if (entry["transport"] == "udp") {
            CHECK(show(ask(udp, sim.udp_port(), request)) == show(recorded));
        } else {
            auto conn = entry["conn"].get<std::uint64_t>();
            if (!tcp.count(conn)) tcp.emplace(conn, TcpClient::open(sim.tcp_port()));
            CHECK(show(ask(tcp.at(conn), request)) == show(recorded));
        }
        ++replayed;
    }
    return replayed;
}

}  // namespace

TEST_CASE("slmp-replay --to-scenario: a recording's reads become a scenario that answers them again at their times",
          "[scenario][replay][replay-tool][to-scenario]") {
    // tests/data/hmi_session.jsonl: an HMI polling an R08CPU recorded by slmp-sim --record while the values
    // changed (its times made round afterwards): 0401 word and bit reads in 3E binary, one in ASCII, a bit
    // device read in words, a 4E random read 0403 of words and a double word, a write, a read refused 4031,
    // and one read over UDP.
    const auto recording = std::filesystem::path(SLMP_SOURCE_DIR) / "tests" / "data" / "hmi_session.jsonl";
    TempDir dir;
    const auto out = dir.path() / "day.json";
    auto r = run_binary(SLMP_REPLAY_BINARY, {"--to-scenario", recording.string(), "--out", out.string()}, 30s);
    INFO(r.out << r.err);
    REQUIRE(r.exit_code == 0);
    CHECK(r.out.empty());
    CHECK(r.err == "slmp-replay: 9 read(s) of 21 device(s): 5 timeline step(s) (1 ramp(s)) in " + out.string() +
                       "\n  1 read(s) not used: answered 4031\n");

    // Byte for byte what tests/data/hmi_session.scenario.json holds (which the schema test checks too).
    CHECK(read_text(out) == read_text(recording.parent_path() / "hmi_session.scenario.json"));
    const auto scenario = nlohmann::json::parse(read_text(out));
    CHECK(scenario["name"] == "hmi_session");
    nlohmann::json initial = {{"D100", 10}, {"D101", 20}, {"D102", 30}, {"D200", 2}, {"D201", 1}, {"M0", 1}, {"M3", 1}};
    for (int m : {1, 2, 4, 5, 6, 7, 8, 9, 10, 11, 12, 13, 14, 15}) initial["M" + std::to_string(m)] = 0;
    CHECK(scenario["initial"]["devices"] == initial);
    // D100 read 10, 11, 12, 13 at 0, 100, 250 and 400 ms: each on the ramp from 10 to 13 over 400 ms.
    CHECK(scenario["timeline"]["steps"] == nlohmann::json::parse(R"([
        {"at_ms": 0, "ramp": "D100", "from": 10, "to": 13, "over_ms": 400},
        {"at_ms": 400, "set": {"D102": 31}}, {"at_ms": 500, "set": {"M0": 0}},
        {"at_ms": 750, "set": {"D101": 21}}, {"at_ms": 800, "set": {"D101": 22}}])"));

    // The scenario as slmp-sim loads it, on a frozen clock: step to each recorded time (from the first
    // exchange) and send the recorded request again; the answer is the recorded one, byte for byte.
    CHECK(replay_at_recorded_times(recording, out) == 11);
}

TEST_CASE("slmp-replay --to-scenario: values that rose or fell linearly become ramps, a staircase stays steps",
          "[scenario][replay][replay-tool][to-scenario]") {
    // tests/data/hmi_ramp.jsonl: an HMI polling D300-D301 of an R08CPU at uneven times (hand-made, like a
    // recording of slmp-sim --record): D300, a tank level, rises 0.1 a ms (100 at 0 ms ... 180 at 800 ms),
    // then falls 0.05 a ms (to 150 at 1400 ms); D301 counts batches, 5, 6 at 650 ms, 7 at 1400 ms.
    const auto recording = std::filesystem::path(SLMP_SOURCE_DIR) / "tests" / "data" / "hmi_ramp.jsonl";
    TempDir dir;
    const auto out = dir.path() / "ramp.json";
    auto r = run_binary(SLMP_REPLAY_BINARY, {"--to-scenario", recording.string(), "--out", out.string()}, 30s);
    INFO(r.out << r.err);
    REQUIRE(r.exit_code == 0);
    CHECK(r.err == "slmp-replay: 8 read(s) of 2 device(s): 4 timeline step(s) (2 ramp(s)) in " + out.string() + "\n");
    const auto scenario = nlohmann::json::parse(read_text(out));
    CHECK(scenario["initial"]["devices"] == nlohmann::json::parse(R"({"D300": 100, "D301": 5})"));
    // The rise and the fall each one ramp through every read of them; the counter's reads (5, 5, 5, 6 ...)
    // lie on no line with a value between its ends: its changes stay steps.
    CHECK(scenario["timeline"]["steps"] == nlohmann::json::parse(R"([
        {"at_ms": 0, "ramp": "D300", "from": 100, "to": 180, "over_ms": 800},
        {"at_ms": 650, "set": {"D301": 6}},
        {"at_ms": 800, "ramp": "D300", "from": 180, "to": 150, "over_ms": 600},
        {"at_ms": 1400, "set": {"D301": 7}}])"));
    CHECK(replay_at_recorded_times(recording, out) == 8);
}
