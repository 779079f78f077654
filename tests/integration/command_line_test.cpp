// The slmp-sim command line and process lifecycle: exit codes, error
// messages that name the bad key, the ready file, clean shutdown on signals.
#include <catch2/catch.hpp>

#include <signal.h>

#include <algorithm>
#include <cctype>
#include <string>

#include "frames.hpp"
#include "link.hpp"
#include "sim_process.hpp"
#include "sockets.hpp"

using namespace slmp::test;

namespace {

std::string lower(std::string s) {
    std::transform(s.begin(), s.end(), s.begin(), [](unsigned char c) { return std::tolower(c); });
    return s;
}

// Exit code 2 and exactly one line on stderr that mentions every word of `names`.
void expect_usage_error(const RunResult& r, std::initializer_list<std::string> names) {
    INFO("stdout: " << r.out << "\nstderr: " << r.err);
    CHECK(r.exit_code == 2);
    auto lines = lines_of(r.err);
    CHECK(lines.size() == 1);
    for (const auto& name : names) CHECK(lower(r.err).find(lower(name)) != std::string::npos);
}

}  // namespace

TEST_CASE("Unknown option: exit code 2 and a message naming it", "[cli]") {
    expect_usage_error(run_sim({"--no-such-option"}), {"no-such-option"});
}

TEST_CASE("Bad option values: exit code 2 and a message naming the option", "[cli]") {
    SECTION("port that is not a number") { expect_usage_error(run_sim({"--tcp-port", "http"}), {"tcp-port"}); }
    SECTION("port out of range") { expect_usage_error(run_sim({"--udp-port", "70000"}), {"udp-port"}); }
    SECTION("data code") { expect_usage_error(run_sim({"--data-code", "ebcdic", "--tcp-port", "0"}), {"data-code"}); }
    SECTION("log level") { expect_usage_error(run_sim({"--log-level", "loud", "--tcp-port", "0"}), {"log-level"}); }
    SECTION("idle timeout") { expect_usage_error(run_sim({"--idle-timeout", "soon", "--tcp-port", "0"}), {"idle-timeout"}); }
    SECTION("profile") { expect_usage_error(run_sim({"--profile", "NOSUCHCPU", "--tcp-port", "0"}), {"NOSUCHCPU"}); }
}

TEST_CASE("Bad config file: exit code 2 and a message naming the key", "[cli][config]") {
    TempDir dir;
    SECTION("unknown transport") {
        auto file = dir.write("c.json", R"({"ports": [{"transport": "sctp", "port": 0}]})");
        expect_usage_error(run_sim({"--config", file.string()}), {"transport"});
    }
    SECTION("wrong type for a device size") {
        auto file = dir.write("c.json", R"({"device_sizes": {"D": "lots"}, "ports": [{"transport": "tcp", "port": 0}]})");
        expect_usage_error(run_sim({"--config", file.string()}), {"device_sizes"});
    }
    SECTION("unknown device in initial values") {
        auto file = dir.write("c.json", R"({"devices": {"QQ100": [1]}, "ports": [{"transport": "tcp", "port": 0}]})");
        expect_usage_error(run_sim({"--config", file.string()}), {"QQ100"});
    }
    SECTION("unknown top-level key") {
        auto file = dir.write("c.json", R"({"prots": [], "ports": [{"transport": "tcp", "port": 0}]})");
        expect_usage_error(run_sim({"--config", file.string()}), {"prots"});
    }
    SECTION("unknown log level") {
        auto file = dir.write("c.json", R"({"log_level": "loud", "ports": [{"transport": "tcp", "port": 0}]})");
        expect_usage_error(run_sim({"--config", file.string()}), {"log_level"});
    }
    SECTION("not JSON at all") {
        auto file = dir.write("c.json", "ports = 5000\n");
        expect_usage_error(run_sim({"--config", file.string()}), {"c.json"});
    }
    SECTION("missing file") {
        expect_usage_error(run_sim({"--config", (dir.path() / "absent.json").string()}), {"absent.json"});
    }
}

TEST_CASE("Help, version and list-profiles options print and exit 0", "[cli]") {
    auto help = run_sim({"--help"});
    CHECK(help.exit_code == 0);
    CHECK(help.out.find("--tcp-port") != std::string::npos);
    CHECK(help.out.find("--ready-file") != std::string::npos);

    auto version = run_sim({"--version"});
    CHECK(version.exit_code == 0);
    CHECK(!lines_of(version.out).empty());

    auto profiles = run_sim({"--list-profiles"});
    CHECK(profiles.exit_code == 0);
    // One line a profile: the --profile name, what 0101 answers, the family, the description.
    CHECK(lines_of(profiles.out).size() >= 22);
    CHECK(profiles.out.find("R16CPU               R16CPU           4802  iQ-R     MELSEC iQ-R R16CPU") !=
          std::string::npos);
    CHECK(profiles.out.find("FX5UC-32MT           FX5UC-32MT/D     4A91  iQ-F") != std::string::npos);
}

TEST_CASE("The ready file lists every bound port and the pid", "[cli][ready]") {
    SimOptions options;
    options.tcp_ports = 2;
    options.udp_ports = 2;
    SimProcess sim(options);
    CHECK(sim.ready().at("pid").get<long>() == static_cast<long>(sim.pid()));
    REQUIRE(sim.tcp_ports().size() == 2);
    REQUIRE(sim.udp_ports().size() == 2);
    CHECK(sim.tcp_port(0) != sim.tcp_port(1));
    CHECK(sim.udp_port(0) != sim.udp_port(1));
    for (auto p : sim.tcp_ports()) {
        INFO("TCP port " << p);
        TcpLink link(p);
        CHECK(link.exchange(slmp::protocol::client::build_request({}, 0x0101, 0)).size() == 11 + 18);
    }
    for (auto p : sim.udp_ports()) {
        INFO("UDP port " << p);
        UdpLink link(p);
        CHECK(link.exchange(slmp::protocol::client::build_request({}, 0x0101, 0)).size() == 11 + 18);
    }
}

TEST_CASE("Ports from a config file are bound and reported", "[cli][ready][config]") {
    SimOptions options;
    options.tcp_ports = 0;
    options.udp_ports = 0;
    options.config_json = R"({"ports": [{"transport": "tcp", "port": 0, "data_code": "auto", "max_connections": 4,
                                         "idle_timeout_ms": 60000},
                                        {"transport": "udp", "port": 0}],
                              "max_request_bytes": 4096, "log_level": "warn"})";
    SimProcess sim(options);
    REQUIRE(sim.tcp_ports().size() == 1);
    REQUIRE(sim.udp_ports().size() == 1);
    TcpLink tcp(sim.tcp_port());
    UdpLink udp(sim.udp_port());
    auto request = slmp::protocol::client::build_request({}, 0x0101, 0);
    CHECK(tcp.exchange(request).size() == 29);
    CHECK(udp.exchange(request).size() == 29);
}

TEST_CASE("SIGINT and SIGTERM shut the server down cleanly with exit code 0", "[cli][signals]") {
    SECTION("SIGINT while a client is connected") {
        SimProcess sim;
        auto c = TcpClient::open(sim.tcp_port());
        TcpLink link(sim.tcp_port());
        REQUIRE(link.exchange(slmp::protocol::client::build_request({}, 0x0101, 0)).size() == 29);
        CHECK(sim.stop(SIGINT) == 0);
        CHECK(c.wait_closed(std::chrono::seconds(5)));
    }
    SECTION("SIGTERM when idle") {
        SimProcess sim;
        CHECK(sim.stop(SIGTERM) == 0);
    }
}
