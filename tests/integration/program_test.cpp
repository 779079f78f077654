// The CPU runs the user's program (docs/program.md) — the worked examples of
// the program spec (copied into tests/data/programs/, text form and the GX
// Works CSV list) against the real binary: frozen clock, inputs written over
// SLMP, scans stepped through POST /api/clock/step, outputs read over SLMP,
// each expected value scan by scan. The text form is driven over binary TCP,
// the CSV form over ASCII UDP, so both codecs and transports carry them.
#include <catch2/catch.hpp>

#include <fstream>
#include <map>
#include <memory>
#include <sstream>
#include <string>
#include <vector>

#include "frames.hpp"
#include "protocol/client_commands.hpp"
#include "http_client.hpp"
#include "link.hpp"
#include "sim_process.hpp"
#include "sockets.hpp"

using namespace slmp::test;
namespace client = slmp::protocol::client;
using nlohmann::json;

namespace {

std::string data_file(const std::string& name) {
    std::ifstream in(std::string(SLMP_SOURCE_DIR) + "/tests/data/programs/" + name, std::ios::binary);
    REQUIRE(in);
    std::ostringstream bytes;
    bytes << in.rdbuf();
    return bytes.str();
}

struct Form {
    std::string file;   // "example_8_1.il"
    Wire wire;
    bool udp;
};

std::vector<Form> forms_of(const std::string& example) {
    std::vector<Form> forms{{"example_" + example + ".il", Wire{FrameKind::E3, Codec::Binary, 0}, false}};
    std::ifstream csv(std::string(SLMP_SOURCE_DIR) + "/tests/data/programs/example_" + example + ".csv");
    if (csv) forms.push_back({"example_" + example + ".csv", Wire{FrameKind::E3, Codec::Ascii, 0}, true});
    return forms;
}

// One simulator running one program on a frozen clock, driven the way an HMI
// drives a CPU: device writes and reads over SLMP.
class ProgramRig {
public:
    ProgramRig(const Form& form, const std::string& profile = "R08CPU", const std::string& program_json = "",
               const std::string& cpu_json = "")
        : form_(form), sim_(options(form, profile, program_json, cpu_json)) {
        if (form.udp)
            link_ = std::make_unique<UdpLink>(sim_.udp_port());
        else
            link_ = std::make_unique<TcpLink>(sim_.tcp_port());
    }

    SimProcess& sim() { return sim_; }
    std::uint16_t http_port() { return sim_.http_port(); }

    void scans(unsigned n) {
        auto r = http(sim_.http_port(), "POST", "/api/clock/step", "{\"scans\": " + std::to_string(n) + "}");
        REQUIRE(r.status == 200);
    }
    // Scans until `scan` scans have run since RUN (scan numbers of the spec).
    void run_to(unsigned scan) {
        REQUIRE(scan >= done_);
        if (scan > done_) scans(scan - done_);
        done_ = scan;
    }
    void set(const std::string& device, bool on) {
        const std::uint8_t v = on ? 1 : 0;
        expect_ok(client::write_bits(form_.wire.options(), addr(device), std::span(&v, 1)));
    }
    void set_word(const std::string& device, std::uint16_t value) {
        expect_ok(client::write_words(form_.wire.options(), addr(device), std::span(&value, 1)));
    }
    bool bit(const std::string& device) {
        auto response = expect_ok(client::read_bits(form_.wire.options(), addr(device), 1));
        return response.reader().bits(1, "bit")[0] != 0;
    }
    std::uint16_t word(const std::string& device) {
        auto response = expect_ok(client::read_words(form_.wire.options(), addr(device), 1));
        return response.reader().words(1, "word")[0];
    }
    Link& link() { return *link_; }
    client::Response exchange(const Bytes& request) {
        auto bytes = link_->exchange(request);
        auto response = client::parse_response(bytes);
        REQUIRE(response);
        return *response;
    }
    client::Response expect_ok(const Bytes& request) {
        auto response = exchange(request);
        REQUIRE(response.end_code == 0);
        return response;
    }
    json program() { return http_get(sim_.http_port(), "/api/program").json(); }
    json state() { return http_get(sim_.http_port(), "/api/state").json(); }

private:
    static SimOptions options(const Form& form, const std::string& profile, const std::string& program_json,
                              const std::string& cpu_json) {
        SimOptions o;
        o.config_json = R"({"profile": ")" + profile + R"(", "cpu": {"scan_time_ms": 10)" + cpu_json + R"(, "program": {"file": ")" +
                        std::string(SLMP_SOURCE_DIR) + "/tests/data/programs/" + form.file + "\"" + program_json + "}}}";
        o.args = {"--clock", "frozen"};
        return o;
    }

    Form form_;
    SimProcess sim_;
    std::unique_ptr<Link> link_;
    unsigned done_ = 0;
};

}  // namespace

TEST_CASE("program §8.1 self-holding circuit, scan by scan", "[program]") {
    for (const auto& form : forms_of("8_1")) {
        INFO(form.file);
        ProgramRig rig(form);
        // scan: X0, X1, Y0 after
        const std::vector<std::tuple<bool, bool, bool>> rows{{0, 0, 0}, {1, 0, 1}, {0, 0, 1}, {0, 1, 0}, {0, 0, 0}, {1, 1, 0}};
        unsigned scan = 0;
        for (auto [x0, x1, y0] : rows) {
            rig.set("X0", x0);
            rig.set("X1", x1);
            rig.run_to(++scan);
            INFO("after scan " << scan);
            CHECK(rig.bit("Y0") == y0);
        }
    }
}

TEST_CASE("program §8.2 on-delay timer K20 at 10 ms scans: value counted at OUT, contact in scan 201", "[program]") {
    for (const auto& form : forms_of("8_2")) {
        INFO(form.file);
        ProgramRig rig(form);
        rig.set("X0", true);
        struct Row { unsigned scan; std::uint16_t tn; bool ts, y; };
        for (auto row : {Row{1, 0, 0, 0}, Row{11, 1, 0, 0}, Row{200, 19, 0, 0}, Row{201, 20, 1, 1}, Row{250, 20, 1, 1}}) {
            rig.run_to(row.scan);
            INFO("after scan " << row.scan);
            CHECK(rig.word("TN0") == row.tn);
            CHECK(rig.bit("TS0") == row.ts);
            CHECK(rig.bit("Y0") == row.y);
        }
        rig.set("X0", false);
        rig.run_to(251);
        CHECK(rig.word("TN0") == 0);
        CHECK(rig.bit("TS0") == false);
        CHECK(rig.bit("Y0") == false);
    }
}

TEST_CASE("program §8.3 counter K3 with reset", "[program]") {
    for (const auto& form : forms_of("8_3")) {
        INFO(form.file);
        ProgramRig rig(form);
        const std::map<unsigned, bool> x0{{1, 0}, {2, 1}, {3, 1}, {4, 0}, {5, 1}, {6, 0}, {7, 1}, {8, 0}, {9, 1}, {10, 0}};
        const std::map<unsigned, bool> x1{{10, 1}, {12, 0}};
        struct Row { std::uint16_t cn; bool cs, y; };
        const std::map<unsigned, Row> expected{{2, {1, 0, 0}}, {3, {1, 0, 0}}, {5, {2, 0, 0}}, {7, {3, 1, 1}},
                                               {9, {3, 1, 1}}, {10, {0, 0, 1}}, {11, {0, 0, 0}}};
        for (unsigned scan = 1; scan <= 11; ++scan) {
            if (auto it = x0.find(scan); it != x0.end()) rig.set("X0", it->second);
            if (auto it = x1.find(scan); it != x1.end()) rig.set("X1", it->second);
            rig.run_to(scan);
            if (auto it = expected.find(scan); it != expected.end()) {
                INFO("after scan " << scan);
                CHECK(rig.word("CN0") == it->second.cn);
                CHECK(rig.bit("CS0") == it->second.cs);
                CHECK(rig.bit("Y0") == it->second.y);
            }
        }
    }
}

TEST_CASE("program §8.4 branches (MPS/MRD/MPP) and blocks (ANB/ORB)", "[program]") {
    for (const auto& form : forms_of("8_4")) {
        INFO(form.file);
        ProgramRig rig(form);
        const std::vector<std::string> inputs{"X0", "X1", "X2", "X3", "X4", "X5", "X6", "X7", "X8", "X10"};
        struct Row { std::vector<std::string> on; bool y0, y1, y2, y3; };
        const std::vector<Row> rows{{{"X0", "X1"}, 1, 0, 0, 0}, {{"X0", "X2"}, 0, 1, 1, 0}, {{"X1", "X2"}, 0, 0, 0, 0},
                                    {{"X3", "X6"}, 0, 0, 0, 1}, {{"X3"}, 0, 0, 0, 0},       {{"X7", "X10"}, 0, 0, 0, 1},
                                    {{"X7", "X8"}, 0, 0, 0, 0}};
        unsigned scan = 0;
        for (const auto& row : rows) {
            for (const auto& x : inputs) rig.set(x, std::find(row.on.begin(), row.on.end(), x) != row.on.end());
            rig.run_to(++scan);
            INFO("inputs ON: " << row.on.front());
            CHECK(rig.bit("Y0") == row.y0);
            CHECK(rig.bit("Y1") == row.y1);
            CHECK(rig.bit("Y2") == row.y2);
            CHECK(rig.bit("Y3") == row.y3);
        }
    }
}

TEST_CASE("program §8.5 master control", "[program]") {
    for (const auto& form : forms_of("8_5")) {
        INFO(form.file);
        ProgramRig rig(form);
        for (auto x : {"X0", "X1", "X2"}) rig.set(x, true);
        struct Row { unsigned scan; bool m100, y0; std::uint16_t tn; bool ts, m0, y1; };
        auto check = [&](const Row& r) {
            rig.run_to(r.scan);
            INFO("after scan " << r.scan);
            CHECK(rig.bit("M100") == r.m100);
            CHECK(rig.bit("Y0") == r.y0);
            CHECK(rig.word("TN0") == r.tn);
            CHECK(rig.bit("TS0") == r.ts);
            CHECK(rig.bit("M0") == r.m0);
            CHECK(rig.bit("Y1") == r.y1);
        };
        check({1, 1, 1, 0, 0, 1, 1});
        check({51, 1, 1, 5, 1, 1, 1});
        rig.set("X0", false);
        check({61, 0, 0, 0, 0, 1, 0});
        rig.set("X0", true);
        check({62, 1, 1, 0, 0, 1, 1});
    }
}

TEST_CASE("program §8.6 conditional jump over a block", "[program]") {
    for (const auto& form : forms_of("8_6")) {
        INFO(form.file);
        ProgramRig rig(form);
        rig.set("X0", false);
        rig.set("X1", true);
        rig.run_to(3);
        CHECK(rig.bit("Y0"));
        CHECK(rig.word("D1") == 3);
        CHECK(rig.word("D2") == 3);
        rig.set("X0", true);
        rig.set("X1", false);
        rig.run_to(6);
        CHECK(rig.bit("Y0"));   // the skipped OUT keeps its state
        CHECK(rig.word("D1") == 3);
        CHECK(rig.word("D2") == 6);
        rig.set("X0", false);
        rig.run_to(7);
        CHECK_FALSE(rig.bit("Y0"));
        CHECK(rig.word("D1") == 4);
        CHECK(rig.word("D2") == 7);
    }
}

TEST_CASE("program §8.7 subroutine call", "[program]") {
    for (const auto& form : forms_of("8_7")) {
        INFO(form.file);
        ProgramRig rig(form);
        rig.set("X0", true);
        rig.run_to(5);
        CHECK(rig.word("D0") == 5);
        CHECK(rig.bit("Y1"));
        rig.set("X0", false);
        rig.run_to(8);
        CHECK(rig.word("D0") == 5);
        CHECK(rig.bit("Y1"));
    }
}

TEST_CASE("program §8.8 32-bit move and addition overflow wrap with no error", "[program]") {
    for (const auto& form : forms_of("8_8")) {
        INFO(form.file);
        ProgramRig rig(form);
        rig.run_to(1);
        CHECK(rig.word("D0") == 0x0000);
        CHECK(rig.word("D1") == 0x8000);
        CHECK(rig.word("D10") == 0x0000);
        CHECK(rig.word("D11") == 0x8000);
        CHECK(rig.word("D20") == 0x93E0);
        CHECK(rig.word("D21") == 0x0004);
        CHECK_FALSE(rig.bit("SM0"));
        rig.run_to(2);
        CHECK(rig.word("D0") == 0x0001);
        CHECK(rig.word("D1") == 0x8000);
        CHECK(rig.word("D10") == 0x0001);
        CHECK(rig.word("D11") == 0x8000);
        CHECK_FALSE(rig.bit("SM0"));
    }
}

TEST_CASE("program §8.9 division with remainder, multiplication, BCD", "[program]") {
    for (const auto& form : forms_of("8_9")) {
        INFO(form.file);
        ProgramRig rig(form);
        rig.run_to(1);
        const std::vector<std::pair<std::string, std::uint16_t>> expected{
            {"D0", 0xFFF9}, {"D1", 0x0001}, {"D2", 0xFFF9}, {"D3", 0xFFFF}, {"D4", 0xD4C0}, {"D5", 0x0001},
            {"D6", 0x37CD}, {"D7", 0},      {"D8", 0x0005}, {"D9", 0},      {"D20", 0x1234}, {"D21", 0x03DB},
            {"D22", 0x5678}, {"D23", 0x1234}};
        for (const auto& [device, value] : expected) {
            INFO(device);
            CHECK(rig.word(device) == value);
        }
    }
}

TEST_CASE("program §8.10 digit designation", "[program]") {
    for (const auto& form : forms_of("8_10")) {
        INFO(form.file);
        ProgramRig rig(form);
        rig.run_to(1);
        CHECK(rig.word("M0") == 0x1234);   // M2, M4, M5, M9, M12 ON
        CHECK(rig.word("D0") == 0x1234);
        CHECK(rig.word("D1") == 0x0003);
        for (int i = 0; i < 4; ++i) CHECK(rig.bit("Y" + std::to_string(i)));
        CHECK_FALSE(rig.bit("Y4"));
        CHECK(rig.word("M16") == 0x0FF0);  // M20-M27 ON
        CHECK(rig.word("D2") == 0x1234);
        CHECK(rig.word("D3") == 0x0FF0);
    }
}

TEST_CASE("program §8.11 index modification", "[program]") {
    for (const auto& form : forms_of("8_11")) {
        INFO(form.file);
        ProgramRig rig(form);
        rig.run_to(1);
        CHECK(rig.word("Z0") == 3);
        CHECK(rig.word("D13") == 100);
        CHECK(rig.word("D20") == 100);
        CHECK(rig.word("D21") == 13);
        CHECK(rig.word("Z1") == 5);
        CHECK(rig.word("M0") == 0x0020);   // M5 ON, M6-M20 OFF
        CHECK(rig.word("M16") == 0);
        CHECK(rig.word("D30") == 100);
        CHECK(rig.word("D31") == 0);
    }
}

TEST_CASE("program §8.12 division by zero: stop error by default, continue when configured", "[program]") {
    for (const auto& form : forms_of("8_12")) {
        INFO(form.file);
        SECTION("stop") {
            ProgramRig rig(form);
            rig.run_to(1);
            CHECK(rig.word("SD203") == 0x0042);
            CHECK(rig.bit("SM0"));
            CHECK(rig.bit("SM1"));
            CHECK(rig.word("SD0") == 0x3400);
            CHECK(rig.word("D2") == 0);
            CHECK(rig.word("D10") == 0);
            CHECK_FALSE(rig.bit("Y0"));
            // Remote RUN is refused until a RESET (C05F on the stop error).
            auto answer = rig.exchange(client::remote_run(Wire{FrameKind::E3, form.udp ? Codec::Ascii : Codec::Binary, 0}.options(),
                                                          client::RemoteMode::Normal, client::ClearMode::None));
            CHECK(answer.end_code == 0xC05F);
            auto program = rig.program();
            CHECK(program["last_error"]["code"] == "3400");
            CHECK(program["last_error"]["mnemonic"] == "/");
        }
        SECTION("continue") {
            ProgramRig rig(form, "R08CPU", R"(, "operation_error": "continue")");
            rig.run_to(1);
            CHECK(rig.word("SD203") == 0x0000);
            CHECK(rig.bit("SM0"));
            CHECK(rig.bit("SM1"));
            CHECK(rig.word("SD0") == 0x3400);
            CHECK(rig.word("D2") == 0);
            CHECK(rig.word("D10") == 1);
            CHECK(rig.bit("Y0"));
        }
        SECTION("Q26UDEHCPU: SD0 holds 4100 as a binary number") {
            ProgramRig rig(form, "Q26UDEHCPU", R"(, "operation_error": "continue")");
            rig.run_to(1);
            CHECK(rig.word("SD0") == 4100);
            CHECK(rig.bit("SM56"));
        }
    }
}

TEST_CASE("program §8.13 floating point", "[program]") {
    for (const auto& form : forms_of("8_13")) {
        INFO(form.file);
        ProgramRig rig(form);
        rig.run_to(1);
        const std::vector<std::pair<std::string, std::uint16_t>> expected{
            {"D0", 0}, {"D1", 0x4120}, {"D2", 0}, {"D3", 0x4148}, {"D4", 0}, {"D5", 0x41C8}, {"D6", 0}, {"D7", 0x4048},
            {"D8", 25}, {"D10", 0}, {"D11", 0xC020}, {"D12", 0xFFFD}, {"D14", 0x5000}, {"D15", 0x47C3}};
        for (const auto& [device, value] : expected) {
            INFO(device);
            CHECK(rig.word(device) == value);
        }
    }
}

TEST_CASE("program §8.14 edges: PLS, FF, LDP/LDF, INCP", "[program]") {
    for (const auto& form : forms_of("8_14")) {
        INFO(form.file);
        ProgramRig rig(form);
        struct Row { bool x0, x1, x2, m0, y0, y1; std::uint16_t d0; };
        const std::vector<Row> rows{{0, 0, 1, 0, 0, 0, 1}, {1, 0, 1, 1, 1, 0, 1}, {1, 0, 0, 0, 1, 0, 1},
                                    {0, 1, 0, 0, 1, 1, 1}, {1, 1, 1, 1, 0, 1, 2}, {1, 0, 1, 0, 0, 0, 2},
                                    {0, 0, 0, 0, 0, 0, 2}};
        unsigned scan = 0;
        for (const auto& r : rows) {
            rig.set("X0", r.x0);
            rig.set("X1", r.x1);
            rig.set("X2", r.x2);
            rig.run_to(++scan);
            INFO("after scan " << scan);
            CHECK(rig.bit("M0") == r.m0);
            CHECK(rig.bit("Y0") == r.y0);
            CHECK(rig.bit("Y1") == r.y1);
            CHECK(rig.word("D0") == r.d0);
        }
    }
}

TEST_CASE("program §8.15 watchdog on an endless loop stops the CPU with 5001 (Q26UDEHCPU)", "[program]") {
    ProgramRig rig(forms_of("8_15").front(), "Q26UDEHCPU", R"(, "wdt_ms": 10)");
    rig.run_to(1);
    CHECK(rig.word("SD203") == 0x0042);
    CHECK(rig.bit("SM0"));
    CHECK(rig.bit("SM1"));
    CHECK(rig.word("SD0") == 5001);
}

TEST_CASE("program §8.16 STOP/RUN around the self-holding circuit: output mode at RUN", "[program]") {
    const auto form = forms_of("8_1").front();
    const auto options = Wire{FrameKind::E3, Codec::Binary, 0}.options();
    for (std::string mode : {"previous", "recalculate"}) {
        INFO(mode);
        ProgramRig rig(form, "R08CPU", R"(, "output_mode_at_run": ")" + mode + "\"");
        rig.set("X0", true);
        rig.run_to(2);
        rig.set("X0", false);
        rig.run_to(3);
        REQUIRE(rig.bit("Y0"));
        rig.expect_ok(client::remote_stop(options));
        CHECK_FALSE(rig.bit("Y0"));
        rig.expect_ok(client::remote_run(options, client::RemoteMode::Normal, client::ClearMode::None));
        CHECK(rig.bit("Y0") == (mode == "previous"));
        CHECK(rig.bit("SM402"));
        rig.scans(1);
        CHECK(rig.bit("Y0") == (mode == "previous"));
        CHECK_FALSE(rig.bit("SM402"));
    }
}

TEST_CASE("program: an SLMP write to a device the program drives is overwritten at its next OUT", "[program]") {
    ProgramRig rig(forms_of("8_2").front());   // LD T0 OUT Y0
    rig.run_to(1);
    rig.set("Y0", true);            // accepted, as on the real CPU
    CHECK(rig.bit("Y0"));
    rig.scans(1);                   // T0 is off -> OUT Y0 writes 0 again
    CHECK_FALSE(rig.bit("Y0"));
}

TEST_CASE("program: a program that does not load stops the start with exit code 2, one line per problem", "[program]") {
    TempDir dir;
    auto file = dir.write("line1.il", "LD X0\nMOVV K1 D0\n/ K1 D0\nLD X1\nCJ P12\nEND\n");
    auto result = run_sim({"--program", file.string(), "--tcp-port", "0", "--no-http"});
    CHECK(result.exit_code == 2);
    CHECK(result.err.find("slmp-sim: error: line1.il: line 2: 'MOVV' is no instruction of R08CPU (family iQ-R)") != std::string::npos);
    CHECK(result.err.find("slmp-sim: error: line1.il: line 3: '/' needs 3 operands") != std::string::npos);
    CHECK(result.err.find("slmp-sim: error: line1.il: line 5: 'CJ P12' jumps to a pointer that is not defined") != std::string::npos);
    // --check-config checks the program as a start would.
    auto config = dir.write("plc.json", R"({"cpu": {"program": {"file": "line1.il"}}})");
    auto check = run_sim({"--check-config", config.string()});
    CHECK(check.exit_code == 2);
    CHECK(check.err.find("'MOVV' is no instruction of R08CPU") != std::string::npos);
    // A timer both the program and the "cpu" section drive has two owners.
    dir.write("timer.il", "LD X0\nOUT T0 K20\nEND\n");
    auto both = dir.write("both.json", R"({"cpu": {"timers": [{"device": "T0", "preset": 20}], "program": {"file": "timer.il"}}})");
    auto shared = run_sim({"--check-config", both.string()});
    CHECK(shared.exit_code == 2);
    CHECK(shared.err.find("timer.il: line 2: T0 is driven by the program and is also in the configuration's "
                          "cpu.timers/cpu.counters; remove it from one of them") != std::string::npos);
    auto missing = run_sim({"--program", (dir.path() / "nope.csv").string(), "--tcp-port", "0", "--no-http"});
    CHECK(missing.exit_code == 2);
    CHECK(missing.err.find("nope.csv cannot be read") != std::string::npos);
}

TEST_CASE("program API: read back both formats, replace in STOP only, unload, load errors as 422", "[program][http]") {
    ProgramRig rig(forms_of("8_1").front());
    const auto port = rig.http_port();
    rig.scans(3);
    auto metrics = http_get(port, "/metrics").body;
    CHECK(metrics.find("slmp_program_scans_total 3\n") != std::string::npos);
    CHECK(metrics.find("slmp_program_execution_seconds{kind=\"last\"} ") != std::string::npos);
    auto info = rig.program();
    CHECK(info["state"] == "loaded");
    CHECK(info["file"] == "example_8_1.il");
    CHECK(info["format"] == "text");
    CHECK(info["steps"] == 5);

    auto text = http_get(port, "/api/program/source?format=text");
    CHECK(text.status == 200);
    CHECK(text.body.find("LD X0\nOR Y0\nANI X1\nOUT Y0\nEND\n") != std::string::npos);
    auto csv = http_get(port, "/api/program/source?format=csv");
    CHECK(csv.status == 200);
    REQUIRE(csv.body.size() > 2);
    CHECK(static_cast<unsigned char>(csv.body[0]) == 0xFF);
    CHECK(static_cast<unsigned char>(csv.body[1]) == 0xFE);

    // Write to PLC needs STOP.
    auto in_run = http(port, "PUT", "/api/program?file=other.il", "LD X1\nOUT Y1\nEND\n");
    CHECK(in_run.status == 409);
    REQUIRE(http_put(port, "/api/state", R"({"switch": "STOP"})").status == 200);
    auto bad = http(port, "PUT", "/api/program?file=bad.il", "LD X1\nOUT Y1\n");
    CHECK(bad.status == 422);
    CHECK(bad.json()["problems"][0] == "bad.il: no END instruction");
    CHECK(rig.program()["file"] == "example_8_1.il");   // a refused write changes nothing
    auto good = http(port, "PUT", "/api/program?file=other.il", "LD X1\nOUT Y1\nEND\n");
    REQUIRE(good.status == 200);
    CHECK(good.json()["file"] == "other.il");
    REQUIRE(http_put(port, "/api/state", R"({"switch": "RUN"})").status == 200);
    rig.set("X1", true);
    rig.scans(1);
    CHECK(rig.bit("Y1"));

    REQUIRE(http_put(port, "/api/state", R"({"switch": "STOP"})").status == 200);
    CHECK(http(port, "DELETE", "/api/program").status == 200);
    CHECK(rig.program()["state"] == "none");
    CHECK(http_get(port, "/api/program/source").status == 404);
    CHECK(http(port, "POST", "/api/program/reload").status == 200);
    CHECK(rig.program()["file"] == "example_8_1.il");
}

TEST_CASE("program: a snapshot holds the program's timers and edges, restore goes on from there", "[program][snapshot]") {
    ProgramRig rig(forms_of("8_2").front());
    const auto port = rig.http_port();
    rig.set("X0", true);
    rig.run_to(50);
    CHECK(rig.word("TN0") == 4);
    REQUIRE(http(port, "POST", "/api/snapshots", R"({"name": "at50"})").status == 201);
    rig.scans(120);
    CHECK(rig.word("TN0") == 16);
    REQUIRE(http(port, "POST", "/api/snapshots/at50/restore", "").status == 200);
    CHECK(rig.word("TN0") == 4);
    rig.scans(150);                 // scan 200 again: 19, not yet up
    CHECK(rig.word("TN0") == 19);
    CHECK_FALSE(rig.bit("TS0"));
    rig.scans(1);                   // scan 201: the contact, exactly as without the detour
    CHECK(rig.word("TN0") == 20);
    CHECK(rig.bit("Y0"));
}

TEST_CASE("program: PAUSE holds the outputs, latch clear and Remote RESET keep the program", "[program][no-proxy]") {
    ProgramRig rig(forms_of("8_1").front(), "R08CPU", "", R"(, "remote_reset": true)");
    const auto options = Wire{FrameKind::E3, Codec::Binary, 0}.options();
    rig.set("X0", true);
    rig.scans(1);
    rig.set("X0", false);
    REQUIRE(rig.bit("Y0"));
    // PAUSE: the program does not run and Y stay as they are.
    rig.expect_ok(client::remote_pause(options, client::RemoteMode::Normal));
    rig.set("X1", true);
    rig.scans(3);
    CHECK(rig.bit("Y0"));
    rig.expect_ok(client::remote_run(options, client::RemoteMode::Normal, client::ClearMode::None));
    rig.scans(1);
    CHECK_FALSE(rig.bit("Y0"));   // runs again: the stop button drops the self-hold
    rig.set("X1", false);
    // Latch clear (in STOP) clears devices, never the program.
    rig.expect_ok(client::remote_stop(options));
    rig.expect_ok(client::remote_latch_clear(options));
    rig.expect_ok(client::remote_run(options, client::RemoteMode::Normal, client::ClearMode::None));
    CHECK(rig.program()["state"] == "loaded");
    rig.set("X0", true);
    rig.scans(1);
    CHECK(rig.bit("Y0"));
    // Remote RESET restarts the CPU (every connection closes); the program is in
    // program memory and runs again from step 0 with SM402 in scan 1.
    rig.expect_ok(client::remote_stop(options));
    {
        TcpLink reset(rig.sim().tcp_port());
        CHECK(reset.exchange(client::remote_reset(options)).empty());   // no answer: the CPU restarts, connections close
    }
    CHECK(rig.program()["state"] == "loaded");
    TcpLink after(rig.sim().tcp_port());   // the rig's connection was closed by the RESET
    auto sm402 = client::parse_response(after.exchange(client::read_bits(options, addr("SM402"), 1)));
    REQUIRE(sm402);
    CHECK(sm402->reader().bits(1, "SM402")[0] == 1);
    const std::vector<std::uint8_t> on{1};
    REQUIRE(client::parse_response(after.exchange(client::write_bits(options, addr("X0"), on)))->end_code == 0);
    rig.scans(1);
    auto y0 = client::parse_response(after.exchange(client::read_bits(options, addr("Y0"), 1)));
    REQUIRE(y0);
    CHECK(y0->reader().bits(1, "Y0")[0] == 1);
}
