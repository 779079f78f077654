// slmp nodes (0E30) and slmp status (0E44/0E53) against the real slmp-sim:
// a station whose profile has "node_commands" (an SLMP-compatible device,
// docs/nodes.md) over UDP and TCP, binary and ASCII; the identity it reports
// is the documented derivation (host name = station name, MAC 02:00 + FNV-1a
// of "<name>:<first port>", IP = the bind address, model code = the profile's).
// A built-in CPU profile refuses both with C059.
#include <catch2/catch.hpp>

#include <sstream>
#include <string>

#include "cli_support.hpp"
#include "plant_ports.hpp"

using namespace slmp::test;
using Args = std::vector<std::string>;

namespace {

// A profile file like a user would write: R08CPU's memory, the node commands served.
std::string node_config(const TempDir& dir) {
    auto profile = dir.write("node-profile.json", R"({"name": "R08CPU-NODE", "extends": "R08CPU", "node_commands": true,
        "description": "an R08CPU-sized SLMP-compatible device, for the tests"})");
    return R"({"name": "cam-1", "profile": ")" + profile.string() + R"("})";
}

std::vector<std::string> words_of(const std::string& line) {
    std::istringstream in(line);
    std::vector<std::string> words;
    for (std::string w; in >> w;) words.push_back(w);
    return words;
}

// fnv1a("cam-1:0") = 37D9438C: the first port of the station is "--tcp-port 0".
const std::string kMac = "02:00:37:D9:43:8C";

}  // namespace

TEST_CASE("slmp nodes and slmp status against a node station, UDP and TCP, binary and ASCII", "[cli][node][no-proxy]") {
    TempDir dir;
    SimOptions options;
    options.config_json = node_config(dir);
    SimProcess sim(options);
    const bool udp = GENERATE(false, true);
    const bool ascii = GENERATE(false, true);
    const auto port = udp ? sim.udp_port() : sim.tcp_port();
    auto base = target(port, udp) + (ascii ? Args{"--ascii"} : Args{});
    INFO((udp ? "UDP" : "TCP") << (ascii ? " ASCII" : " binary"));

    auto json = json_of(run_cli(base + Args{"--json", "nodes"}));
    CHECK(json["ip"] == "127.0.0.1");
    CHECK(json["mac"] == kMac);
    CHECK(json["station"] == "cam-1");
    CHECK(json["model_code"] == "00004801");
    CHECK(json["vendor_code"] == "0000");
    CHECK(json["version"] == "0001");
    CHECK(json["status"] == "0000");
    CHECK(json["port"] == port);
    CHECK(json["subnet_mask"] == "255.255.255.0");
    CHECK(json["gateway"] == "0.0.0.0");
    CHECK(json["partner"] == "0.0.0.0");

    auto table = run_cli(base + Args{"nodes"});
    INFO(table.err);
    REQUIRE(table.exit_code == 0);
    auto lines = lines_of(table.out);
    REQUIRE(lines.size() == 2);
    CHECK(words_of(lines[0]) == Args{"ip", "mac", "station", "model", "code", "vendor", "version", "status", "port"});
    CHECK(words_of(lines[1]) == Args{"127.0.0.1", kMac, "cam-1", "00004801", "0000", "0001", "0000", std::to_string(port)});

    auto status = json_of(run_cli(base + Args{"--json", "status"}));
    CHECK(status == nlohmann::json{{"status", "0000"}, {"state", "normal"}, {"ip", "127.0.0.1"}, {"partner", "0.0.0.0"},
                                   {"operating_state", "00"}});
    auto status_table = run_cli(base + Args{"status"});
    REQUIRE(status_table.exit_code == 0);
    auto status_lines = lines_of(status_table.out);
    REQUIRE(status_lines.size() == 2);
    CHECK(words_of(status_lines[0]) == Args{"status", "state", "ip", "partner"});
    CHECK(words_of(status_lines[1]) == Args{"0000", "normal", "127.0.0.1", "0.0.0.0"});
}

TEST_CASE("slmp nodes and slmp status against an R08CPU: C059, exit 1", "[cli][node]") {
    SimProcess sim;
    const bool udp = GENERATE(false, true);
    auto base = target(udp ? sim.udp_port() : sim.tcp_port(), udp);
    for (const auto* command : {"nodes", "status"}) {
        auto r = run_cli(base + Args{command});
        INFO(command << ": " << r.err);
        CHECK(r.exit_code == 1);
        CHECK(r.err.find("C059") != std::string::npos);
        CHECK(r.err.find("0E") != std::string::npos);
    }
}

TEST_CASE("a plant: each node station answers node search on its own UDP port, a CPU station refuses", "[cli][node][plant]") {
    TempDir dir;
    auto profile = dir.write("node-profile.json", R"({"name": "R08CPU-NODE", "extends": "R08CPU", "node_commands": true, "description": "an SLMP-compatible device"})");
    SimOptions options;
    options.plant = true;
    options.config_json = R"({"bind": "127.0.0.1", "stations": [
        {"template": {"profile": ")" + profile.string() + R"("}, "count": 3, "name": "cam-{i}", "tcp_port": 0, "udp_port": 0},
        {"name": "press", "profile": "R08CPU", "tcp_port": 0, "udp_port": 0}]})";
    SimProcess sim(options);
    // fnv1a("cam-<i>:0"): each station's first port is configured as 0.
    const std::vector<std::pair<std::string, std::string>> expected{
        {"cam-1", "02:00:37:D9:43:8C"}, {"cam-2", "02:00:D8:04:DB:41"}, {"cam-3", "02:00:F1:77:5E:BA"}};
    for (const auto& [name, mac] : expected) {
        const auto& station = station_in(sim, name);
        const auto port = station["udp"][0].get<std::uint16_t>();
        auto json = json_of(run_cli(target(port, true) + Args{"--json", "nodes"}));
        CHECK(json["station"] == name);
        CHECK(json["mac"] == mac);
        CHECK(json["ip"] == "127.0.0.1");
        CHECK(json["port"] == port);
    }
    auto press = run_cli(target(station_in(sim, "press")["udp"][0].get<std::uint16_t>(), true) + Args{"nodes"});
    CHECK(press.exit_code == 1);
    CHECK(press.err.find("C059") != std::string::npos);
}
