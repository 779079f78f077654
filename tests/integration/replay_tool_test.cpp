// slmp-replay, the client-side replay (docs/scenarios.md "Record & replay"):
// a session recorded against slmp-sim replays against a fresh simulator with
// no differences (exit 0), against one whose D200 holds another value with the
// differing exchange named (exit 1), and against nothing with exit 2.
#include <catch2/catch.hpp>

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
        CHECK(r.out.find("6 exchange(s): 5 identical, 1 different") != std::string::npos);
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
