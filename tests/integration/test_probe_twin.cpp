// slmp probe and slmp diff against the real slmp-sim (docs/twin.md): each
// built-in profile of a different family is probed into a profile file, a
// second slmp-sim runs that file, and slmp diff sends several hundred generated
// requests (every command and subcommand, limits ±1, area edges, bad devices,
// 3E/4E, binary/ASCII) to both — there must be no difference. A profile changed
// on purpose is found by the probe, and slmp diff shows it against the original.
// One TEST_CASE a profile, so ctest runs them in parallel.
#include <catch2/catch.hpp>

#include <fstream>
#include <sstream>

#include "cli_support.hpp"

using namespace slmp::test;
using Args = std::vector<std::string>;

namespace {

// Silence is a real answer of some ports (4E on a Q/L built-in port); on
// loopback a short wait tells it apart. Bounds only, never waits.
const Args kQuick{"--timeout", "2s", "--silence", "250ms"};

RunResult run_tool(const Args& args) { return run_binary(under_test(SLMP_CLI_BINARY), args, scaled_bound(60)); }

nlohmann::json read_json(const std::filesystem::path& file) {
    std::ifstream in(file);
    std::stringstream text;
    text << in.rdbuf();
    return nlohmann::json::parse(text.str());
}

// Probes `profile` (a built-in name or a file) served by a fresh slmp-sim;
// returns the probed profile's JSON, written to `out`.
nlohmann::json probe(const std::string& profile, const std::filesystem::path& out) {
    SimProcess original(with_args({"--profile", profile}));
    auto started = std::chrono::steady_clock::now();
    auto run = run_tool(target(original.tcp_port()) + kQuick +
                        Args{"--json", "probe", "--out", out.string(), "--allow-writes", "D7000-D7999,M7000-M7299"});
    auto seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - started).count();
    INFO("probe of " << profile << "\nstdout: " << run.out << "\nstderr: " << run.err);
    REQUIRE(run.exit_code == 0);
    WARN("probe of " << profile << ": " << seconds << " s wall");   // reported, never asserted
    return read_json(out);
}

// slmp diff between a server running `a` and one running `b`, the requests
// generated from `a`'s limits and sizes.
RunResult diff(const std::string& a, const std::string& b) {
    SimProcess first(with_args({"--profile", a}));
    SimProcess second(with_args({"--profile", b}));
    return run_tool(target(first.tcp_port()) + kQuick +
                    Args{"--json", "diff", "--against", "127.0.0.1:" + std::to_string(second.tcp_port()), "--profile", a});
}

void probe_and_compare(const std::string& profile) {
    TempDir dir;
    auto probed_file = dir.path() / (profile + ".probed.json");
    auto probed = probe(profile, probed_file);
    auto run = diff(profile, probed_file.string());
    INFO("diff " << profile << " vs its probed twin\nprobed: " << probed.dump(2) << "\nstdout: " << run.out
                 << "\nstderr: " << run.err);
    REQUIRE(run.exit_code == 0);
    auto result = json_of(run);
    CHECK(result["differences"].empty());
    CHECK(result["sent"].get<int>() >= 300);
}

}  // namespace

TEST_CASE("probe twin: R08CPU probed, its twin answers every generated request the same", "[probe][twin]") {
    probe_and_compare("R08CPU");
}
TEST_CASE("probe twin: R120PCPU probed, its twin answers every generated request the same", "[probe][twin]") {
    probe_and_compare("R120PCPU");
}
TEST_CASE("probe twin: Q26UDEHCPU probed, its twin answers every generated request the same", "[probe][twin]") {
    probe_and_compare("Q26UDEHCPU");
}
TEST_CASE("probe twin: Q06UDVCPU-QJ71E71 probed, its twin answers every generated request the same", "[probe][twin]") {
    probe_and_compare("Q06UDVCPU-QJ71E71");
}
TEST_CASE("probe twin: L26CPU-BT probed, its twin answers every generated request the same", "[probe][twin]") {
    probe_and_compare("L26CPU-BT");
}
TEST_CASE("probe twin: FX5U-32MR probed, its twin answers every generated request the same", "[probe][twin]") {
    probe_and_compare("FX5U-32MR");
}

TEST_CASE("probe twin: a profile changed on purpose (a limit, a refused command) is found", "[probe][twin]") {
    TempDir dir;
    auto changed = dir.write("R08CPU-changed.json", R"({
        "name": "R08CPU-changed", "extends": "R08CPU", "description": "R08CPU with a smaller word limit, no 0619",
        "limits": {"batch_words": {"max": 480, "end_code": "C051"}, "random_read_points": {"q": 100, "iqr": 50, "end_code": "C054"}},
        "unsupported_commands": ["0619"],
        "device_sizes": {"D": 12000},
        "pipeline": {"buffer": 7, "over_limit": "CEE0"},
        "max_connections": 5
    })");
    auto probed = probe(changed.string(), dir.path() / "probed.json");
    CHECK(probed["extends"] == "R08CPU");
    CHECK(probed["limits"]["batch_words"]["max"] == 480);
    CHECK(probed["limits"]["batch_words"]["end_code"] == "C051");
    CHECK(probed["limits"]["random_read_points"]["q"] == 100);
    CHECK(probed["limits"]["random_read_points"]["iqr"] == 50);
    CHECK(probed["unsupported_commands"] == nlohmann::json::array({"0619"}));
    CHECK(probed["device_sizes"]["D"] == 12000);
    CHECK(probed["pipeline"]["buffer"] == 7);
    CHECK(probed["max_connections"] == 5);

    // And slmp diff tells the original from the changed one.
    auto run = diff("R08CPU", changed.string());
    INFO("stdout: " << run.out << "\nstderr: " << run.err);
    CHECK(run.exit_code == 1);
    auto lines = lines_of(run.out);   // the result, then the error line of --json
    REQUIRE(lines.size() == 2);
    auto result = nlohmann::json::parse(lines[0]);
    std::string all = result["differences"].dump();
    CHECK(all.find("0401/0000 D0 x961") == std::string::npos);   // 961 is over both limits
    CHECK(all.find("0401/0000 D0 x960 (word limit)") != std::string::npos);
    CHECK(all.find("0619/0000 loopback 1 bytes") != std::string::npos);
    CHECK(all.find("D10240 x1 (first point past the end)") != std::string::npos);
    // Each named by its kind, as slmp-sim --compare and slmp-replay name it: the original serves 960
    // words, the changed profile refuses them.
    bool word_limit = false;
    for (const auto& d : result["differences"]) {
        if (d["frame"] != "3E binary" || d["request"] != "0401/0000 D0 x960 (word limit)") continue;
        CHECK(d["kind"] == "end_code");
        word_limit = true;
    }
    CHECK(word_limit);
}

TEST_CASE("probe: read-only without --allow-writes, --out required, --record keeps every exchange",
          "[probe][twin]") {
    SimProcess sim(with_args({"--profile", "R08CPU"}));
    TempDir dir;
    CHECK(run_tool(target(sim.tcp_port()) + Args{"probe"}).exit_code == 2);
    CHECK(run_tool(target(sim.tcp_port()) + Args{"probe", "--out", "x.json", "--allow-writes", "D10"}).exit_code == 2);
    auto out = dir.path() / "p.json", record = dir.path() / "p.jsonl";
    auto run = run_tool(target(sim.tcp_port()) + kQuick +
                        Args{"--json", "probe", "--out", out.string(), "--record", record.string()});
    INFO(run.err);
    REQUIRE(run.exit_code == 0);
    auto result = json_of(run);
    auto probed = read_json(out);
    // The write facts are left to the base, and said so.
    CHECK_FALSE(probed.contains("mixed_block_write"));
    bool said = false;
    for (const auto& f : result["facts"])
        if (f["fact"] == "mixed_block_write") said = f["found"] == false;
    CHECK(said);
    // Nothing that writes was sent: every recorded request is a read-only command.
    std::ifstream lines(record);
    std::string line;
    std::size_t exchanges = 0;
    while (std::getline(lines, line)) {
        auto json = nlohmann::json::parse(line);
        if (json.value("event", "") != "exchange") continue;
        ++exchanges;
        auto request = json["request"].get<std::string>();
        if (request.rfind("5000", 0) != 0 || request.size() < 30) continue;   // 3E binary: command at byte 11
        auto command = request.substr(24, 2) + request.substr(22, 2);
        INFO(line);
        CHECK(command.rfind("14", 0) != 0);   // no 14xx write
        CHECK(command.rfind("10", 0) != 0);   // no remote operation
        CHECK(command.rfind("16", 0) != 0);   // no 1601/1613/1617/163x
        CHECK(command != "1820");
    }
    CHECK(exchanges == result["requests"].get<std::size_t>());
}
