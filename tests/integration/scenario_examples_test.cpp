// The shipped examples (scenarios/examples/) do what docs/scenarios.md
// "Examples" says, seen by a client of the real simulator running the file as
// shipped. The examples run in real time (a tank cycle is 20 s, the stop error
// comes after ~19 s and the power cycle at 40 s; stop_on_error runs at
// --clock-speed 10), so these tests poll with generous deadlines and never
// check how fast anything happened.
// conveyor and password_locked: scenario_plant_test.cpp.
#include <catch2/catch.hpp>

#include <bit>
#include <regex>

#include "scenario_support.hpp"

using namespace slmp::test;
using namespace std::chrono_literals;
namespace client = slmp::protocol::client;

namespace {

std::string example(const std::string& name) {
    return read_text(std::filesystem::path(SLMP_SOURCE_DIR) / "scenarios/examples" / (name + ".json"));
}

// Polls `holds` (re-reading devices) until it is true or `limit` passes.
template <typename Condition>
bool eventually(Condition holds, std::chrono::milliseconds limit) {
    auto deadline = std::chrono::steady_clock::now() + limit;
    while (std::chrono::steady_clock::now() < deadline) {
        if (holds()) return true;
        std::this_thread::sleep_for(50ms);
    }
    return holds();
}

}  // namespace

TEST_CASE("example tank: fill/drain ramps in a loop, high/low alarms, a held-for trigger, a float random walk",
          "[scenario][examples][tank]") {
    ScenarioSim s({example("tank")});
    auto c = TcpClient::open(s.sim->tcp_port());
    auto level = [&] { return read_word(c, "D100").value_or(0xFFFF); };
    auto alarms = [&] { return read_word(c, "M100").value_or(0xFFFF) & 0x7; };   // M100 high, M101 low, M102 overflow
    auto high = [&] { return (alarms() & 1) != 0; };
    auto low = [&] { return (alarms() & 2) != 0; };
    auto warning = [&] { return (alarms() & 4) != 0; };

    // Filling from 0: the low alarm is on, the others off.
    CHECK(eventually([&] { return low() && !high(); }, 10s));
    CHECK(eventually([&] { return level() > 100 && level() != 0xFFFF && !low(); }, 15s));
    // Near the top: the high alarm; after 1.5 s held at >= 900 the overflow warning latches.
    REQUIRE(eventually([&] { return high(); }, 20s));
    CHECK(level() >= 900);
    CHECK(eventually([&] { return warning(); }, 10s));
    // Draining: the high alarm goes, the warning stays until an operator clears it.
    CHECK(eventually([&] { return !high() && level() < 900; }, 20s));
    CHECK(warning());
    std::uint8_t off[] = {0};
    REQUIRE(c.send(client::write_bits(kBinary3E.options(), addr("M102"), off)));
    REQUIRE(c.response());
    CHECK_FALSE(warning());
    // The timeline loops: the level reaches the bottom (low alarm) and fills again.
    CHECK(eventually([&] { return low(); }, 20s));
    CHECK(eventually([&] { return level() > 100 && level() != 0xFFFF; }, 20s));

    // The temperature: a float in D110-D111 (low word first) between 18 and 25 degrees.
    REQUIRE(c.send(read_request(kBinary3E, "D110", 2)));
    auto r = c.response();
    REQUIRE(r);
    REQUIRE(r->data.size() == 4);
    auto bits = static_cast<std::uint32_t>(r->data[0] | r->data[1] << 8 | r->data[2] << 16 | r->data[3] << 24);
    auto temperature = std::bit_cast<float>(bits);
    CHECK(temperature >= 18.0f);
    CHECK(temperature <= 25.0f);
}

TEST_CASE("example stop_on_error: a held condition raises stop error 3100, a timed power cycle recovers",
          "[scenario][examples][stop-on-error]") {
    // At --clock-speed 10 the 40 s story takes about 4 s; the deadlines stay generous.
    ScenarioSim s({example("stop_on_error")}, {"--clock-speed", "10"});
    auto c = TcpClient::open(s.sim->tcp_port());
    CHECK(read_word(c, "SD203").value_or(0xFF) % 16 == 0);   // RUN
    CHECK((read_word(c, "SM0").value_or(1) & 1) == 0);       // no error
    // D200 climbs 60 -> 130 over 20 s; >= 120 for 2 s raises the stop error.
    CHECK(wait_for_word(c, "SD0", 0x3100, 40s));
    CHECK((read_word(c, "SM0").value_or(0) & 1) == 1);
    CHECK(read_word(c, "SD203").value_or(0) % 16 == 2);      // STOP
    CHECK((read_word(c, "M200").value_or(0) & 1) == 1);      // the cooling-fault flag
    CHECK(read_word(c, "D200").value_or(0) >= 120);
    // A stop error is not cleared: 1617 is refused by the built-in port (C059), still STOP with the error.
    REQUIRE(c.send(request_frame(kBinary3E, {0x10, 0x00, 0x17, 0x16, 0x00, 0x00})));   // Clear Error 1617
    auto refused = c.response();
    REQUIRE(refused);
    CHECK(refused->end_code == 0xC059);
    CHECK(read_word(c, "SD0") == 0x3100);
    // At 40 s the maintenance trigger cycles the power: the connection drops,
    // then the CPU is back in RUN without the error and with its initial D200.
    CHECK(c.wait_closed(60s));
    auto back = connect_with_retry(s.sim->tcp_port(), 30s);
    REQUIRE(back);
    CHECK(read_word(*back, "SD203").value_or(0xFF) % 16 == 0);
    CHECK(read_word(*back, "SD0") == 0);
    CHECK((read_word(*back, "SM0").value_or(1) & 1) == 0);
    CHECK((read_word(*back, "M200").value_or(1) & 1) == 0);   // not latched: cleared
    CHECK(read_word(*back, "D200") == 60);                     // the initial value again
}

TEST_CASE("example power_cycle_writes: the 21st write to D0-D99 meets a power cut", "[scenario][examples][power-cycle]") {
    ScenarioSim s({example("power_cycle_writes")});
    auto writer = TcpClient::open(s.sim->tcp_port());
    auto other = TcpClient::open(s.sim->tcp_port());
    auto ok = show(expected_response(kBinary3E, {}));
    Bytes frame;
    REQUIRE(writer.send(write_request(kBinary3E, "D500", {99})));   // outside D0-D99: not counted
    REQUIRE(writer.response(&frame, 10s));
    CHECK(show(frame) == ok);
    REQUIRE(writer.send(write_request(kBinary3E, "D300", {7})));
    REQUIRE(writer.response(&frame, 10s));
    for (std::uint16_t i = 0; i < 20; ++i) {   // writes 1-20 pass
        REQUIRE(writer.send(write_request(kBinary3E, "D" + std::to_string(i), {static_cast<std::uint16_t>(100 + i)})));
        REQUIRE(writer.response(&frame, 10s));
        CHECK(show(frame) == ok);
    }
    CHECK(read_word(writer, "D19") == 119);
    // The 21st: no answer, and every connection drops.
    REQUIRE(writer.send(write_request(kBinary3E, "D20", {120})));
    Bytes unexpected;
    CHECK(writer.wait_closed(10s, &unexpected));
    CHECK(unexpected.empty());
    CHECK(other.wait_closed(10s));
    int error = 0;
    if (TcpClient::connect(s.sim->tcp_port(), &error)) UNSCOPED_INFO("connected during the power cut (it may have ended)");
    else CHECK(error == ECONNREFUSED);   // the port is closed while the power is off
    auto back = connect_with_retry(s.sim->tcp_port(), 15s);
    REQUIRE(back);
    CHECK(read_word(*back, "D500") == 1234);   // the initial value restored
    CHECK(read_word(*back, "D300") == 0);      // not latched: cleared
    CHECK(read_word(*back, "D0") == 0);
    CHECK(read_word(*back, "D19") == 0);
    CHECK(read_word(*back, "D20") == 0);       // the write that met the cut never happened
    // count 1: writes after the restart are answered.
    REQUIRE(back->send(write_request(kBinary3E, "D20", {120})));
    REQUIRE(back->response(&frame, 10s));
    CHECK(show(frame) == ok);
}

TEST_CASE("example flaky_network: seeded delays, lost answers, resets, split and coalesced responses",
          "[scenario][examples][flaky]") {
    SimOptions options;
    options.args = {"--scenario", (std::filesystem::path(SLMP_SOURCE_DIR) / "scenarios/examples/flaky_network.json").string(),
                    "--no-http", "--log-level", "info"};
    options.default_log_level = true;
    SimProcess sim(options);

    // A careful client: 4E frames with a serial each, one request or two
    // pipelined; answers are whole frames (split or coalesced ones assembled by
    // their length), matched by serial; no answer within 3 s is a lost one; a
    // reset means reconnecting.
    std::optional<TcpClient> c;
    std::uint16_t serial = 0;
    int answered = 0, lost = 0, resets = 0, slow = 0, wrong = 0;
    for (int i = 0; i < 1000 && (i < 150 || !lost || !resets || !slow); ++i) {
        if (!c) c = connect_with_retry(sim.tcp_port(), 10s);
        REQUIRE(c);
        std::vector<std::uint16_t> waiting;
        Bytes burst;
        for (int n = 0; n < (i % 2 ? 2 : 1); ++n) {
            waiting.push_back(++serial);
            auto request = read_request(Wire{FrameKind::E4, Codec::Binary, serial}, "D0");
            burst.insert(burst.end(), request.begin(), request.end());
        }
        auto start = std::chrono::steady_clock::now();
        REQUIRE(c->send(burst));
        while (!waiting.empty()) {
            Bytes frame;
            std::string why;
            auto r = c->response(&frame, 3s, &why);
            if (!r) {
                if (why == "timeout") ++lost;
                else {   // the fault's RST (an EOF would be wrong: flaky_network never closes with FIN)
                    CHECK(why == "error");
                    ++resets;
                    c.reset();
                }
                break;
            }
            auto it = std::find(waiting.begin(), waiting.end(), r->header.serial);
            if (it == waiting.end() ||
                frame != expected_response(Wire{FrameKind::E4, Codec::Binary, r->header.serial}, word_data(kBinary3E, {0})))
                ++wrong;
            else waiting.erase(it);
            ++answered;
        }
        if (i % 2 == 0 && waiting.empty() && since(start) >= 20ms) ++slow;   // a delay is at least 20 ms
    }
    CHECK(wrong == 0);
    CHECK(answered > 100);
    CHECK(lost > 0);
    CHECK(resets > 0);
    CHECK(slow > 0);
    c.reset();
    REQUIRE(sim.stop() == 0);
    // The simulator's summary at shutdown: every fault of the example fired.
    auto logs = sim.logs();
    INFO(logs.substr(logs.size() > 4000 ? logs.size() - 4000 : 0));
    for (const char* fault : {"'slow' \\(delay\\)", "'lost' \\(no_response\\)", "'reset' \\(reset\\)", "'split' \\(split\\)",
                              "'coalesce-4e' \\(coalesce\\)"})
        CHECK(std::regex_search(logs, std::regex(std::string("fault ") + fault + " matched [0-9]+ request\\(s\\), fired [1-9]")));
}

TEST_CASE("clock speed: --clock-speed runs the CPU's clock faster: SD412 counts CPU seconds", "[scenario][clock]") {
    // 20x: SD412 (seconds since power-on) passes 30 within 1.5 s of real time;
    // at real time it could not within the 10 s allowed here, so the test fails
    // if the factor is ignored.
    ScenarioSim s({R"({"name": "idle"})"}, {"--clock-speed", "20"});
    auto c = TcpClient::open(s.sim->tcp_port());
    CHECK(eventually([&] { auto v = read_word(c, "SD412"); return v && *v >= 30 && *v != 0xFFFF; }, 10s));
}
