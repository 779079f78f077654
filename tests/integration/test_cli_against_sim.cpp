// The slmp CLI against the real slmp-sim binary: every subcommand the simulator
// serves, in binary and ASCII, over TCP and UDP, 3E and 4E; exit codes; --json
// output parsed; table output checked; end-code meanings printed.
#include <catch2/catch.hpp>

#include <signal.h>

#include <string>

#include "cli_support.hpp"

using namespace slmp::test;
using Args = std::vector<std::string>;

namespace {

bool contains(const std::string& text, const std::string& part) { return text.find(part) != std::string::npos; }

// The codec/transport/frame combinations every device test runs in.
Args variant(const SimProcess& sim, int which) {
    switch (which) {
        case 0: return target(sim.tcp_port());
        case 1: return target(sim.tcp_port()) + Args{"--ascii"};
        case 2: return target(sim.udp_port(), true) + Args{"--4e", "--serial", "0x1234"};
        default: return target(sim.udp_port(), true) + Args{"--ascii", "--4e", "--iqr"};
    }
}

}  // namespace

TEST_CASE("slmp write/read words: exit 0, JSON values, table rows", "[cli][device]") {
    SimProcess sim;
    auto which = GENERATE(0, 1, 2, 3);
    auto base = variant(sim, which);
    INFO("variant " << which);

    auto w = run_cli(base + Args{"write", "D100", "1", "-2", "0x1234"});
    INFO(w.err);
    REQUIRE(w.exit_code == 0);
    CHECK(contains(w.out, "wrote 3 word(s) D100-D102"));

    auto json = json_of(run_cli(base + Args{"--json", "read", "D100", "3"}));
    CHECK(json["device"] == "D100");
    CHECK(json["unit"] == "word");
    CHECK(json["points"] == 3);
    CHECK(json["devices"] == nlohmann::json({"D100", "D101", "D102"}));
    CHECK(json["values"] == nlohmann::json({1, 65534, 0x1234}));

    auto table = run_cli(base + Args{"read", "D100", "3"});
    REQUIRE(table.exit_code == 0);
    auto lines = lines_of(table.out);
    REQUIRE(lines.size() == 4);
    CHECK(lines[0] == "device  value  signed  hex");
    CHECK(lines[1] == "D100    1      1       0001");
    CHECK(lines[2] == "D101    65534  -2      FFFE");
    CHECK(lines[3] == "D102    4660   4660    1234");
}

TEST_CASE("slmp write/read bits, and bit devices read as words", "[cli][device]") {
    SimProcess sim;
    auto which = GENERATE(0, 1, 2, 3);
    auto base = variant(sim, which);
    INFO("variant " << which);

    REQUIRE(run_cli(base + Args{"write", "M0", "1", "0", "1", "--bits"}).exit_code == 0);
    auto bits = json_of(run_cli(base + Args{"--json", "read", "M0", "4", "--bits"}));
    CHECK(bits["unit"] == "bit");
    CHECK(bits["devices"] == nlohmann::json({"M0", "M1", "M2", "M3"}));
    CHECK(bits["values"] == nlohmann::json({1, 0, 1, 0}));

    auto words = json_of(run_cli(base + Args{"--json", "read", "M0", "2"}));
    CHECK(words["devices"] == nlohmann::json({"M0", "M16"}));
    CHECK(words["values"] == nlohmann::json({5, 0}));

    auto table = run_cli(base + Args{"read", "X1E", "2", "--bits"});
    REQUIRE(table.exit_code == 0);
    CHECK(lines_of(table.out) == std::vector<std::string>{"device  value", "X1E     0", "X1F     0"});
}

TEST_CASE("slmp type and selftest", "[cli][misc]") {
    SimProcess sim;
    auto which = GENERATE(0, 1, 2, 3);
    auto base = variant(sim, which);
    INFO("variant " << which);

    auto type = json_of(run_cli(base + Args{"--json", "type"}));
    CHECK(type == nlohmann::json({{"model", "R08CPU"}, {"model_code", "4801"}}));
    auto table = run_cli(base + Args{"type"});
    CHECK(lines_of(table.out) == std::vector<std::string>{"model   model code", "R08CPU  4801"});

    auto self = json_of(run_cli(base + Args{"--json", "selftest", "ABCDE"}));
    CHECK(self == nlohmann::json({{"sent", "ABCDE"}, {"received", "ABCDE"}, {"match", true}}));
    auto plain = run_cli(base + Args{"selftest"});
    CHECK(plain.exit_code == 0);
    CHECK(plain.out == "loopback OK: 16 byte(s) echoed\n");
}

TEST_CASE("slmp prints the meaning of an error end code and exits 1", "[cli][errors]") {
    SimProcess sim;

    SECTION("C051: too many word points") {
        auto r = run_cli(target(sim.tcp_port()) + Args{"read", "D0", "961"});
        CHECK(r.exit_code == 1);
        CHECK(r.out.empty());
        CHECK(r.err == "slmp: the PLC answered end code C051: word point count out of range "
                       "(command 0401/0000, answered by network 00 station FF module I/O 03FF multidrop 00)\n");
    }
    SECTION("4031 through JSON, ASCII") {
        auto r = run_cli(target(sim.tcp_port()) + Args{"--ascii", "--json", "read", "D10240"});
        CHECK(r.exit_code == 1);
        auto json = json_of(r);
        CHECK(json["error"]["kind"] == "end_code");
        CHECK(json["error"]["end_code"] == "4031");
        CHECK(json["error"]["meaning"] == "device number or span outside the configured device size");
        CHECK(json["error"]["command"] == "0401");
        CHECK(json["error"]["subcommand"] == "0000");
    }
    SECTION("a route to another network: 4A01, and the route is echoed") {
        auto r = run_cli(target(sim.tcp_port()) + Args{"--network", "1", "--station", "2", "type"});
        CHECK(r.exit_code == 1);
        CHECK(contains(r.err, "4A01"));
        CHECK(contains(r.err, "network 01 station 02"));
    }
    SECTION("a command the port refuses: C059") {
        SimProcess q(with_args({"--profile", "Q26UDEHCPU"}));
        auto r = run_cli(target(q.tcp_port()) + Args{"selftest"});
        CHECK(r.exit_code == 1);
        CHECK(contains(r.err, "C059: command or subcommand not supported"));
    }
}

TEST_CASE("slmp usage errors exit 2 with one line naming the problem", "[cli][usage]") {
    struct Case {
        Args args;
        std::string says;
    };
    auto c = GENERATE(values<Case>({
        {{"frobnicate"}, "unknown command 'frobnicate'"},
        {{}, "no command given"},
        {{"read"}, "read needs DEVICE [POINTS]"},
        {{"read", "QQ100"}, "unknown device in address 'QQ100'"},
        {{"read", "X1G"}, "hexadecimal"},
        {{"read", "D100", "0"}, "point count"},
        {{"read", "D100", "--bits"}, "D100 is a word device"},
        {{"write", "D100", "70000"}, "'70000' is not a word value"},
        {{"write", "M0", "2", "--bits"}, "'2' is not a bit value"},
        {{"stop", "--force"}, "--force does not apply to 'stop'"},
        {{"run", "--clear", "some"}, "--clear 'some' must be none, nonlatch or all"},
        {{"monitor", "D100", "--interval", "500"}, "write it with a unit"},
        {{"monitor", "D10-D5"}, "is not a range"},
        {{"--serial", "1", "type"}, "--serial needs --4e"},
        {{"--module-io", "XYZ", "type"}, "--module-io 'XYZ'"},
        {{"--no-such-option", "type"}, "no-such-option"},
        {{"random", "read"}, "random read needs devices"},
        {{"random", "write", "D0"}, "is not DEVICE=VALUE"},
        {{"lock"}, "lock needs exactly one PASSWORD"},
        {{"selftest", std::string(961, 'A')}, "1..960 characters"},
    }));
    INFO(c.says);
    // Port 9 (discard) on loopback: a usage error must be found before any connection.
    auto r = run_cli(Args{"--port", "9"} + c.args);
    CHECK(r.exit_code == 2);
    CHECK(lines_of(r.err).size() == 1);
    CHECK(contains(r.err, c.says));
    CHECK(r.out.empty());
}

TEST_CASE("slmp connection failures exit 3", "[cli][connection][no-proxy]") {
    std::uint16_t closed_port;
    {
        SimProcess sim;   // a port that was just in use and is now closed
        closed_port = sim.tcp_port();
    }
    SECTION("TCP refused") {
        auto r = run_cli(target(closed_port) + Args{"type"});
        CHECK(r.exit_code == 3);
        CHECK(contains(r.err, "cannot connect to 127.0.0.1:"));
    }
    SECTION("TCP refused, JSON") {
        auto json = json_of(run_cli(target(closed_port) + Args{"--json", "type"}));
        CHECK(json["error"]["kind"] == "connection");
    }
    SECTION("a 4E request to a port that ignores 4E: no answer within --timeout") {
        SimProcess q(with_args({"--profile", "Q26UDEHCPU"}));
        auto r = run_cli(target(q.tcp_port()) + Args{"--4e", "--timeout", "300ms", "read", "D0"});
        CHECK(r.exit_code == 3);
        CHECK(contains(r.err, "no response from 127.0.0.1:"));
    }
}

TEST_CASE("slmp monitor polls --count times, table and JSON lines", "[cli][monitor]") {
    SimProcess sim;
    REQUIRE(run_cli(target(sim.tcp_port()) + Args{"write", "D100", "7", "8"}).exit_code == 0);
    REQUIRE(run_cli(target(sim.tcp_port()) + Args{"write", "M1", "1", "--bits"}).exit_code == 0);

    auto table = run_cli(target(sim.tcp_port()) + Args{"monitor", "D100-D101", "M0-M1", "--count", "3", "--interval", "0"});
    REQUIRE(table.exit_code == 0);
    auto lines = lines_of(table.out);
    REQUIRE(lines.size() == 4);
    CHECK(lines[0] == "time    D100    D101    M0      M1");
    for (int i = 1; i <= 3; ++i) CHECK(lines[i].substr(12) == "  7       8       0       1");

    auto json = run_cli(target(sim.udp_port(), true) + Args{"--ascii", "--json", "monitor", "D100", "M1", "--count", "2",
                                                            "--interval", "1ms"});
    REQUIRE(json.exit_code == 0);
    auto rows = lines_of(json.out);
    REQUIRE(rows.size() == 2);
    for (int i = 0; i < 2; ++i) {
        auto row = nlohmann::json::parse(rows[i]);
        CHECK(row["poll"] == i + 1);
        CHECK(row["values"] == nlohmann::json({{"D100", 7}, {"M1", 1}}));
        CHECK(row["time"].get<std::string>().back() == 'Z');
    }
}

TEST_CASE("slmp monitor stops cleanly on Ctrl-C (SIGINT): exit 0", "[cli][monitor]") {
    SimProcess sim;
    TempDir dir;
    auto out = dir.path() / "out";
    auto err = dir.path() / "err";
    pid_t pid = detail::spawn(target(sim.tcp_port()) + Args{"monitor", "D0", "--interval", "10ms"}, out, err,
                              under_test(SLMP_CLI_BINARY));
    // Wait (bounded) for the header and the first poll, then interrupt.
    auto deadline = std::chrono::steady_clock::now() + std::chrono::seconds(10);
    while (lines_of(read_text(out)).size() < 2 && std::chrono::steady_clock::now() < deadline)
        std::this_thread::sleep_for(std::chrono::milliseconds(10));
    ::kill(pid, SIGINT);
    auto status = detail::wait_for(pid, std::chrono::seconds(10));
    if (!status) {
        ::kill(pid, SIGKILL);
        ::waitpid(pid, nullptr, 0);
    }
    REQUIRE(status);
    INFO(read_text(err));
    CHECK(WIFEXITED(*status));
    CHECK(WEXITSTATUS(*status) == 0);
    CHECK(lines_of(read_text(out)).size() >= 2);
}

TEST_CASE("slmp --help lists every command and the exit codes, exit 0", "[cli]") {
    auto r = run_cli({"--help"});
    CHECK(r.exit_code == 0);
    for (auto name : {"read", "write", "random", "monitor", "run", "stop", "pause", "reset", "latch-clear", "type",
                      "selftest", "lock", "unlock", "--iqr", "--json", "--password"})
        CHECK(contains(r.out, name));
    CHECK(contains(r.out, "Exit status: 0 ok, 1 the PLC answered an error end code, 2 usage error, 3 connection"));
}
