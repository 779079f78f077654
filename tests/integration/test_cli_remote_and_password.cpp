// The slmp CLI against slmp-sim for the commands that change the CPU's state:
// remote RUN/STOP/PAUSE/latch clear/RESET (checked through SD203, the
// operating-state register clients poll), the remote password, and random
// read/write. Behaviour of the simulator: docs/cpu-runtime.md.
#include <catch2/catch.hpp>

#include <string>

#include "cli_support.hpp"

using namespace slmp::test;
using Args = std::vector<std::string>;

namespace {

bool contains(const std::string& text, const std::string& part) { return text.find(part) != std::string::npos; }

// One word read through the CLI (exit code checked).
long read_word(const Args& base, const std::string& device) {
    auto json = json_of(run_cli(base + Args{"--json", "read", device}));
    return json["values"][0].get<long>();
}

void expect_end_code(const RunResult& r, const std::string& code) {
    INFO("stdout: " << r.out << "\nstderr: " << r.err);
    CHECK(r.exit_code == 1);
    CHECK(contains(r.err, "end code " + code + ": "));
}

}  // namespace

TEST_CASE("slmp stop, pause, run move the CPU's state (SD203)", "[cli][remote][no-proxy]") {
    SimProcess sim;
    auto codec = GENERATE(as<std::string>{}, "--ascii");
    Args base = target(sim.tcp_port());
    if (!codec.empty()) base.push_back(codec);

    CHECK(read_word(base, "SD203") == 0x0000);   // RUN
    auto stop = run_cli(base + Args{"stop"});
    CHECK(stop.exit_code == 0);
    CHECK(stop.out == "remote STOP: OK\n");
    CHECK(read_word(base, "SD203") == 0x0022);   // STOP by remote

    // Each slmp run is its own connection, so the STOP above belongs to another client.
    expect_end_code(run_cli(base + Args{"run"}), "4015");
    CHECK(read_word(base, "SD203") == 0x0022);
    auto run = json_of(run_cli(base + Args{"--json", "run", "--force", "--clear", "none"}));
    CHECK(run == nlohmann::json({{"command", "run"}, {"force", true}, {"clear", "none"}, {"ok", true}}));
    CHECK(read_word(base, "SD203") == 0x0000);

    CHECK(run_cli(base + Args{"pause"}).exit_code == 0);
    CHECK(read_word(base, "SD203") == 0x0023);   // PAUSE by remote
    CHECK(run_cli(base + Args{"run", "--force"}).exit_code == 0);
    CHECK(read_word(base, "SD203") == 0x0000);
}

TEST_CASE("slmp latch-clear needs STOP, slmp reset is refused unless enabled", "[cli][remote][no-proxy]") {
    SECTION("switch at RUN") {
        SimProcess sim;
        expect_end_code(run_cli(target(sim.tcp_port()) + Args{"latch-clear"}), "4013");
        expect_end_code(run_cli(target(sim.tcp_port()) + Args{"reset"}), "4014");
    }
    SECTION("switch at STOP: latch clear clears device memory") {
        SimProcess sim(with_args({"--switch", "STOP"}));
        auto base = target(sim.tcp_port());
        REQUIRE(run_cli(base + Args{"write", "D0", "5"}).exit_code == 0);
        auto r = run_cli(base + Args{"latch-clear"});
        CHECK(r.exit_code == 0);
        CHECK(r.out == "remote latch clear: OK\n");
        CHECK(read_word(base, "D0") == 0);
    }
    SECTION("remote reset enabled, in STOP: no answer, which the CLI reports as success") {
        SimOptions options;
        options.config_json = R"({"cpu": {"remote_reset": true, "switch": "STOP"}})";
        SimProcess sim(options);
        auto reset = json_of(run_cli(target(sim.tcp_port()) + Args{"--json", "reset"}));
        CHECK(reset == nlohmann::json({{"command", "reset"}, {"ok", true}, {"answered", false}}));
        CHECK(run_cli(target(sim.tcp_port()) + Args{"type"}).exit_code == 0);   // it came back
    }
}

TEST_CASE("slmp against a password-protected CPU: locked, --password, unlock", "[cli][password]") {
    SimOptions options;
    options.config_json = R"({"cpu": {"password": "secret1"}})";
    SimProcess sim(options);
    auto base = target(sim.tcp_port());

    auto locked = run_cli(base + Args{"read", "D0"});
    expect_end_code(locked, "C201");
    CHECK(contains(locked.err, "remote password is locked"));

    expect_end_code(run_cli(base + Args{"unlock", "wrong12"}), "C810");
    auto unlock = run_cli(base + Args{"unlock", "secret1"});
    CHECK(unlock.exit_code == 0);
    CHECK(unlock.out == "remote password unlock: OK\n");

    CHECK(run_cli(base + Args{"--password", "secret1", "write", "D0", "5"}).exit_code == 0);
    CHECK(read_word(base + Args{"--password", "secret1"}, "D0") == 5);
    CHECK(run_cli(base + Args{"--ascii", "--4e", "--password", "secret1", "type"}).exit_code == 0);
    // Lock while locked (a new connection starts locked) is a no-op without a password check.
    CHECK(run_cli(base + Args{"lock", "secret1"}).exit_code == 0);
}

TEST_CASE("slmp random write and random read against the simulator", "[cli][random]") {
    SimProcess sim;
    auto which = GENERATE(0, 1, 2);
    Args base = which == 0 ? target(sim.tcp_port())
                : which == 1 ? target(sim.tcp_port()) + Args{"--ascii"}
                             : target(sim.udp_port(), true) + Args{"--iqr", "--4e"};
    INFO("variant " << which);

    auto w = run_cli(base + Args{"random", "write", "D0=1", "D1=-1", "--dword", "D10=70000"});
    INFO(w.err);
    REQUIRE(w.exit_code == 0);
    CHECK(w.out == "wrote 3 device(s)\n");
    REQUIRE(run_cli(base + Args{"random", "write", "--bits", "M5=1", "Y2F=1"}).exit_code == 0);

    auto json = json_of(run_cli(base + Args{"--json", "random", "read", "D0", "D1", "M0", "--dword", "D10"}));
    CHECK(json["values"] == nlohmann::json({{{"device", "D0"}, {"access", "word"}, {"value", 1}},
                                            {{"device", "D1"}, {"access", "word"}, {"value", 65535}},
                                            {{"device", "M0"}, {"access", "word"}, {"value", 0x0020}},
                                            {{"device", "D10"}, {"access", "dword"}, {"value", 70000}}}));
    auto bits = json_of(run_cli(base + Args{"--json", "read", "Y2E", "2", "--bits"}));
    CHECK(bits["values"] == nlohmann::json({0, 1}));
}

TEST_CASE("slmp random read over the iQ-R limit: C054 and its meaning", "[cli][random][errors]") {
    SimProcess sim;
    Args args = target(sim.tcp_port()) + Args{"--iqr", "random", "read"};
    for (int i = 0; i < 97; ++i) args.push_back("D" + std::to_string(i));
    auto r = run_cli(args);
    expect_end_code(r, "C054");
    CHECK(contains(r.err, "random/monitor word point count out of range"));
}
