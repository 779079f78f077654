// FX5 X/Y numbered in octal against the real binary (issue 14): X7 and X10 are
// adjacent over SLMP (ASCII digits in octal, binary numbers the bit index),
// the HTTP API, the slmp CLI, the configuration and scenarios; X8 is refused
// with a message that says why. An iQ-R beside it keeps hexadecimal.
#include <catch2/catch.hpp>

#include <string>

#include "cli_support.hpp"
#include "frames.hpp"
#include "http_client.hpp"
#include "link.hpp"
#include "sim_process.hpp"

using namespace slmp::test;
using nlohmann::json;
using Args = std::vector<std::string>;

namespace {

const std::string kX8Message =
    "bad device number '8' in address 'X8' (X is numbered in octal on this CPU: X7 is followed by X10)";

// An ASCII 3E request to the own station: header, length, timer 0010, payload.
Bytes ascii_request(const std::string& payload) {
    return text("500000FF03FF00" + hex_digits(static_cast<std::uint32_t>(payload.size() + 4), 4) + "0010" + payload);
}

json device_json(std::uint16_t http_port, const std::string& target) {
    auto r = http_get(http_port, target);
    INFO(target << ": " << r.body);
    REQUIRE(r.status == 200);
    return r.json();
}

}  // namespace

TEST_CASE("FX5U: X7 and X10 are adjacent over SLMP, HTTP and the CLI, X8 is refused", "[octal][http][cli]") {
    SimProcess sim(with_args({"--profile", "FX5U-32MR"}));
    TcpLink link(sim.tcp_port());
    const auto api_port = sim.http_port();

    SECTION("SLMP ASCII writes X7-X10; HTTP and SLMP binary read bits 7 and 8") {
        CHECK(show(link.exchange(ascii_request("14010001X*0000070002" "11"))) == show(text("D00000FF03FF0000040000")));
        CHECK(device_json(api_port, "/api/devices/X6?as=bits&count=4") ==
              json{{"device", "X6"}, {"as", "bits"}, {"count", 4}, {"values", {0, 1, 1, 0}}});
        CHECK(device_json(api_port, "/api/devices/X10?as=bits")["values"] == json::array({1}));
        // Binary: number 8 (bit index), code 9C, 2 points: X10 on, X11 off.
        CHECK(show(link.exchange(hex("50 00 00 FF FF 03 00 0C 00 10 00 01 04 01 00 08 00 00 9C 02 00"))) ==
              show(hex("D0 00 00 FF FF 03 00 03 00 00 00 10")));
    }
    SECTION("SLMP ASCII X*000008 answers C050 and writes nothing") {
        CHECK(show(link.exchange(ascii_request("14010001X*0000080001" "1"))) ==
              show(text("D00000FF03FF000016C05000FF03FF0014010001")));
        CHECK(device_json(api_port, "/api/devices/X0?as=bits&count=16")["values"] == json(std::vector<int>(16, 0)));
    }
    SECTION("HTTP writes Y10; SLMP ASCII reads it as Y*000010") {
        auto put = http_put(api_port, "/api/devices/Y10?as=bits", R"({"values": [1]})");
        INFO(put.body);
        CHECK(put.status == 200);
        CHECK(put.json()["device"] == "Y10");
        CHECK(show(link.exchange(ascii_request("04010001Y*0000070002"))) == show(text("D00000FF03FF000006000001")));
        auto bad = http_get(api_port, "/api/devices/X8");
        CHECK(bad.status == 400);
        CHECK(bad.error() == kX8Message);
        auto info = device_json(api_port, "/api/info");
        for (const auto& d : info["devices"])
            if (d["symbol"] == "X" || d["symbol"] == "Y") CHECK(d["radix"] == 8);
            else if (d["symbol"] == "D") CHECK(d["radix"] == 10);
    }
    SECTION("the CLI with --octal-xy writes X7 X10 and names them in octal, binary and ASCII") {
        for (const auto& codec : {Args{}, Args{"--ascii"}}) {
            auto base = target(sim.tcp_port()) + codec + Args{"--octal-xy"};
            auto wrote = run_cli(base + Args{"write", "--bits", "X7", "1", "1"});
            INFO(wrote.err);
            REQUIRE(wrote.exit_code == 0);
            CHECK(wrote.out.find("wrote 2 bit(s) X7-X10") != std::string::npos);
            auto read = json_of(run_cli(base + Args{"--json", "read", "--bits", "X6", "3"}));
            CHECK(read["devices"] == json({"X6", "X7", "X10"}));
            CHECK(read["values"] == json({0, 1, 1}));
            CHECK(device_json(api_port, "/api/devices/X7?as=bits&count=2")["values"] == json({1, 1}));
            auto bad = run_cli(base + Args{"read", "X8"});
            CHECK(bad.exit_code == 2);
            CHECK(bad.err.find(kX8Message) != std::string::npos);
            REQUIRE(http_put(api_port, "/api/devices/X7?as=bits", R"({"values": [0, 0]})").status == 200);
        }
    }
}

TEST_CASE("FX5U: the configuration, scenarios and a plant's CLI lookup read X/Y in octal", "[octal][plant]") {
    SimOptions options;
    options.plant = true;
    options.config_json = R"({"bind": "127.0.0.1", "http": {"port": 0}, "stations": [
        {"name": "fx", "profile": "FX5U-32MR", "tcp_port": 0, "devices": {"Y10": 1}},
        {"name": "rq", "profile": "R08CPU", "tcp_port": 0, "devices": {"Y10": 1}}]})";
    SimProcess sim(options);
    const auto api_port = sim.http_port();
    // Y10 is bit 8 on the FX5U, bit 16 on the R08CPU.
    CHECK(device_json(api_port, "/api/stations/fx/devices/Y0?as=words")["values"] == json::array({0x0100}));
    CHECK(device_json(api_port, "/api/stations/rq/devices/Y10?as=words")["values"] == json::array({1}));
    CHECK(device_json(api_port, "/api/stations/fx/devices/Y10?as=bits")["device"] == "Y10");
    CHECK(device_json(api_port, "/api/stations")[0]["xy_radix"] == 8);

    SECTION("a scenario posted to the FX5U sets X10 (bit 8)") {
        auto posted = http(api_port, "POST", "/api/stations/fx/scenarios",
                           R"({"name": "octal", "initial": {"devices": {"X10": 1}}})");
        INFO(posted.body);
        REQUIRE(posted.status == 201);
        CHECK(device_json(api_port, "/api/stations/fx/devices/X0?as=words")["values"] == json::array({0x0100}));
        auto bad = http(api_port, "POST", "/api/stations/fx/scenarios", R"({"name": "bad", "initial": {"devices": {"X8": 1}}})");
        CHECK(bad.status == 400);
        CHECK(bad.error().find("octal") != std::string::npos);
    }
    SECTION("--plant-station finds an iQ-F station and numbers X/Y in octal without --octal-xy") {
        auto api = std::to_string(api_port);
        auto read = json_of(run_cli({"--plant-station", "fx", "--api-port", api, "--ascii", "--json", "read", "--bits", "Y7", "2"}));
        CHECK(read["devices"] == json({"Y7", "Y10"}));
        CHECK(read["values"] == json({0, 1}));
    }
}
