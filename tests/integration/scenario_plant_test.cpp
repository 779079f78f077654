// Scenarios that move values and run logic, seen by a client of the real
// simulator: the timeline, a trigger that stops the CPU with an error, the
// rung program, the shipped conveyor example, a password-locked PLC.
#include <catch2/catch.hpp>

#include "scenario_support.hpp"

using namespace slmp::test;
using namespace std::chrono_literals;
namespace client = slmp::protocol::client;

TEST_CASE("scenario: initial values and timeline steps reach the devices", "[scenario][plant]") {
    ScenarioSim s({R"({"initial": {"devices": {"D10": 5, "D20": "AB"}},
                       "timeline": {"steps": [{"at_ms": 0, "set": {"D100": 42}}, {"after_ms": 200, "set": {"D101": 7}}]}})"});
    auto c = TcpClient::open(s.sim->tcp_port());
    CHECK(read_word(c, "D10") == 5);
    CHECK(read_word(c, "D20") == 0x4241);
    CHECK(wait_for_word(c, "D100", 42));
    CHECK(wait_for_word(c, "D101", 7));
}

TEST_CASE("scenario: a condition held long enough stops the CPU with an error", "[scenario][plant]") {
    ScenarioSim s({R"({"triggers": [{"when": "D100 >= 50", "for_ms": 200, "do": [{"error": {"code": "3100", "stop": true}}]}]})"});
    auto c = TcpClient::open(s.sim->tcp_port());
    CHECK(read_word(c, "SD203").value_or(0xFF) % 16 == 0);   // RUN
    REQUIRE(c.send(write_request(kBinary3E, "D100", {60})));
    REQUIRE(c.response());
    CHECK(wait_for_word(c, "SD0", 0x3100));
    CHECK(read_word(c, "SD203").value_or(0) % 16 == 2);      // STOP
}

TEST_CASE("scenario: the conveyor example — start button, motor latch, delay timer, part counter", "[scenario][plant][examples]") {
    std::string example = read_text(std::filesystem::path(SLMP_SOURCE_DIR) / "scenarios/examples/conveyor.json");
    ScenarioSim s({example});
    auto c = TcpClient::open(s.sim->tcp_port());
    // The scenario presses M0 at 0.5 s: Y0 (motor) latches, Y1 follows 2 s later, C0 counts parts into D0.
    auto y = [&]() -> std::uint16_t { return read_word(c, "Y0").value_or(0); };   // Y0-Y0F as one word
    auto deadline = std::chrono::steady_clock::now() + 15s;
    while ((y() & 0x3) != 0x3 && std::chrono::steady_clock::now() < deadline) std::this_thread::sleep_for(20ms);
    CHECK((y() & 0x3) == 0x3);
    CHECK(wait_for_word(c, "D0", 2, 15s));   // two parts counted
    // Stop button: the motor stops and stays stopped.
    std::uint8_t on[] = {1};
    REQUIRE(c.send(client::write_bits(kBinary3E.options(), addr("M1"), on)));
    REQUIRE(c.response());
    deadline = std::chrono::steady_clock::now() + 15s;
    while ((y() & 0x1) != 0 && std::chrono::steady_clock::now() < deadline) std::this_thread::sleep_for(20ms);
    CHECK((y() & 0x1) == 0);
}

TEST_CASE("scenario: a password-locked PLC", "[scenario][plant][examples]") {
    std::string example = read_text(std::filesystem::path(SLMP_SOURCE_DIR) / "scenarios/examples/password_locked.json");
    ScenarioSim s({example});
    TcpLink link(s.sim->tcp_port());
    CHECK(show(link.exchange(read_request(kBinary3E, "D1000"))) ==
          show(expected_response(kBinary3E, error_info(kBinary3E, 0x0401, 0x0000), 0xC201)));
    CHECK(show(link.exchange(client::unlock(kBinary3E.options(), "plant-2024"))) == show(expected_response(kBinary3E, {})));
    CHECK(show(link.exchange(read_request(kBinary3E, "D1000", 4))) ==
          show(expected_response(kBinary3E, word_data(kBinary3E, {0x4957, 0x4744, 0x5445, 0x412D}))));   // "WIDGET-A"
}
