// Redundant pairs, multidrop stations and the file commands' restricted
// request destinations in a plant (docs/plants.md, "Redundant pairs",
// "Multidrop stations"; docs/end-codes.md). Every answer is compared byte for
// byte with the frame the docs give.
#include <catch2/catch.hpp>

#include <chrono>
#include <thread>

#include "ask.hpp"
#include "frames.hpp"
#include "http_client.hpp"
#include "plant_ports.hpp"
#include "protocol/client.hpp"
#include "protocol/client_commands.hpp"
#include "protocol/client_files.hpp"
#include "sim_process.hpp"
#include "sockets.hpp"

using namespace slmp::test;
namespace client = slmp::protocol::client;
using slmp::protocol::Codec;
using slmp::protocol::Route;

namespace {

// gw: the line's Ethernet module, station 1 of network 1; press-a (system A,
// station 2) and press-b (system B, station 3): a redundant pair whose switch
// takes 1000 ms on the new control system's clock. The pair tracks D0-D99
// only, so each CPU's D100 tells which CPU answered.
std::string pair_plant(const std::string& extra_a = "") {
    return R"({"bind": "127.0.0.1", "stations": [
        {"name": "gw", "profile": "RJ71EN71", "tcp_port": 0, "udp_port": 0, "networks": [{"number": 1, "station": 1}]},
        {"name": "press-a", "profile": "R08PCPU", "tcp_port": 0, "networks": [{"number": 1, "station": 2}],
         "redundant": {"pair": "press-b", "system": "A", "switchover_ms": 1000, "tracking": ["D0-D99"]})" + extra_a + R"(},
        {"name": "press-b", "profile": "R08PCPU", "tcp_port": 0, "networks": [{"number": 1, "station": 3}],
         "redundant": {"pair": "press-a", "system": "B"}}]})";
}

Route route(std::uint8_t network, std::uint8_t station, std::uint16_t module_io, std::uint8_t multidrop = 0) {
    return Route{network, station, module_io, multidrop};
}

client::FrameOptions with(const Route& r, Codec codec = Codec::Binary) {
    client::FrameOptions o;
    o.codec = codec;
    o.route = r;
    return o;
}

Bytes read_d100(const Route& r, Codec codec = Codec::Binary) { return client::read_words(with(r, codec), addr("D100"), 1); }
Bytes write_d100(std::uint16_t value) {
    const std::vector<std::uint16_t> words{value};
    return client::write_words(with(Route{}), addr("D100"), words);
}

std::string hex2(unsigned v) { return hex_digits(v & 0xFF, 2); }
std::string ascii_hex(unsigned v, int digits) {
    static const char* d = "0123456789ABCDEF";
    std::string s;
    for (int i = digits - 1; i >= 0; --i) s += d[(v >> (4 * i)) & 0xF];
    return s;
}
Bytes text(const std::string& s) { return Bytes(s.begin(), s.end()); }

std::string route_hex(const Route& r) {
    return hex2(r.network) + " " + hex2(r.station) + " " + hex2(r.module_io) + " " + hex2(r.module_io >> 8) + " " +
           hex2(r.multidrop);
}
std::string route_ascii(const Route& r) {
    return ascii_hex(r.network, 2) + ascii_hex(r.station, 2) + ascii_hex(r.module_io, 4) + ascii_hex(r.multidrop, 2);
}

// The 3E answer of a one-word read, and an error answer with its error information.
Bytes word_answer(const Route& r, std::uint16_t value, Codec codec = Codec::Binary) {
    if (codec == Codec::Ascii) return text("D000" + route_ascii(r) + "0008" + "0000" + ascii_hex(value, 4));
    return hex("D0 00 " + route_hex(r) + " 04 00 00 00 " + hex2(value) + " " + hex2(value >> 8));
}
Bytes error_answer(const Route& r, std::uint16_t code, std::uint16_t command, std::uint16_t subcommand,
                   Codec codec = Codec::Binary) {
    if (codec == Codec::Ascii)
        return text("D000" + route_ascii(r) + "0016" + ascii_hex(code, 4) + route_ascii(r) + ascii_hex(command, 4) +
                    ascii_hex(subcommand, 4));
    return hex("D0 00 " + route_hex(r) + " 0B 00 " + hex2(code) + " " + hex2(code >> 8) + " " + route_hex(r) + " " +
               hex2(command) + " " + hex2(command >> 8) + " " + hex2(subcommand) + " " + hex2(subcommand >> 8));
}

const Bytes kWritten = hex("D0 00 00 FF FF 03 00 02 00 00 00");

// Search Directory/File (iQ-R) for a file no drive has: a CPU that serves it answers 4022.
Bytes file_search(const Route& r, Codec codec = Codec::Binary) {
    return client::file_search(with(r, codec), client::FileTarget{true, 4, "NONE.CSV", ""});
}

nlohmann::json pair_state(const SimProcess& sim, const std::string& station) {
    auto answer = http_get(sim.http_port(), "/api/stations/" + station + "/redundant");
    REQUIRE(answer.status == 200);
    return answer.json();
}

// Waits (at most 5 s) until the pair's switch has ended; the state then.
nlohmann::json switched(const SimProcess& sim) {
    const auto deadline = std::chrono::steady_clock::now() + std::chrono::seconds(5);
    auto state = pair_state(sim, "press-a");
    while (state["switching"] == true && std::chrono::steady_clock::now() < deadline) {
        std::this_thread::sleep_for(std::chrono::milliseconds(10));
        state = pair_state(sim, "press-a");
    }
    return state;
}

}  // namespace

TEST_CASE("redundant pair: routes 03D0-03D3 before and after a system switch, binary and ASCII", "[route][plant][redundant]") {
    SimProcess sim(plant_options(pair_plant(), {"--clock", "frozen"}));
    auto a = TcpClient::open(tcp_of(sim, "press-a"));
    auto b = TcpClient::open(tcp_of(sim, "press-b"));
    REQUIRE(show(ask(a, write_d100(0x0A0A))) == show(kWritten));
    REQUIRE(show(ask(b, write_d100(0x0B0B))) == show(kWritten));
    auto gw = TcpClient::open(tcp_of(sim, "gw"));
    UdpClient gw_udp;

    // Before: system A is the control system. Through the module to either
    // CPU's station No.; and at a CPU's own port, over the tracking cable.
    struct Case {
        Route route;
        std::uint16_t value;
    };
    const Case before[] = {{route(1, 2, 0x03D0), 0x0A0A}, {route(1, 2, 0x03D1), 0x0B0B}, {route(1, 2, 0x03D2), 0x0A0A},
                           {route(1, 2, 0x03D3), 0x0B0B}, {route(1, 3, 0x03D0), 0x0A0A}, {route(1, 3, 0x03D1), 0x0B0B},
                           {route(1, 3, 0x03D2), 0x0A0A}, {route(1, 3, 0x03D3), 0x0B0B}};
    for (const auto& c : before)
        for (const auto codec : {Codec::Binary, Codec::Ascii}) {
            INFO("before, module I/O " << std::hex << c.route.module_io << " station " << int(c.route.station)
                                       << (codec == Codec::Ascii ? " ASCII" : " binary"));
            CHECK(show(ask(gw, read_d100(c.route, codec))) == show(word_answer(c.route, c.value, codec)));
            CHECK(show(ask(gw_udp, udp_of(sim, "gw"), read_d100(c.route, codec))) == show(word_answer(c.route, c.value, codec)));
        }
    CHECK(show(ask(b, read_d100(route(0, 0xFF, 0x03D0)))) == show(word_answer(route(0, 0xFF, 0x03D0), 0x0A0A)));
    CHECK(show(ask(a, read_d100(route(0, 0xFF, 0x03D1), Codec::Ascii))) ==
          show(word_answer(route(0, 0xFF, 0x03D1), 0x0B0B, Codec::Ascii)));
    auto state = pair_state(sim, "press-b");
    CHECK(state["system"] == "B");
    CHECK(state["role"] == "standby");
    CHECK(state["control"] == "press-a");

    // The switch, by the API. The clock is frozen, so the pair stays switching
    // until press-b's clock passes 1000 ms.
    auto posted = http(sim.http_port(), "POST", "/api/stations/press-a/redundant/switch");
    REQUIRE(posted.status == 200);
    CHECK(posted.json()["control"] == "press-b");
    CHECK(posted.json()["switching"] == true);
    CHECK(http(sim.http_port(), "POST", "/api/stations/press-b/redundant/switch").status == 409);

    // During the switch: by role 4248; by system served; a file command 4248 by any route.
    for (const auto codec : {Codec::Binary, Codec::Ascii}) {
        CHECK(show(ask(gw, read_d100(route(1, 2, 0x03D0), codec))) ==
              show(error_answer(route(1, 2, 0x03D0), 0x4248, 0x0401, 0x0000, codec)));
        CHECK(show(ask(gw, read_d100(route(1, 3, 0x03D1), codec))) ==
              show(error_answer(route(1, 3, 0x03D1), 0x4248, 0x0401, 0x0000, codec)));
        CHECK(show(ask(gw, read_d100(route(1, 2, 0x03D3), codec))) == show(word_answer(route(1, 2, 0x03D3), 0x0B0B, codec)));
        CHECK(show(ask(gw, file_search(route(1, 2, 0x03D2), codec))) ==
              show(error_answer(route(1, 2, 0x03D2), 0x4248, 0x1811, 0x0040, codec)));
        CHECK(show(ask(a, file_search(Route{}, codec))) == show(error_answer(Route{}, 0x4248, 0x1811, 0x0040, codec)));
    }
    // A file command by role is outside §3.1.4's table whatever the pair does: 4B02.
    CHECK(show(ask(gw, file_search(route(1, 2, 0x03D0)))) == show(error_answer(route(1, 2, 0x03D0), 0x4B02, 0x1811, 0x0040)));

    // The switch ends on press-b's clock.
    auto stepped = http(sim.http_port(), "POST", "/api/stations/press-b/clock/step", R"({"ms": 1000})");
    REQUIRE(stepped.status == 200);
    state = switched(sim);
    CHECK(state["switching"] == false);
    CHECK(state["control"] == "press-b");
    CHECK(state["role"] == "standby");   // press-a's
    CHECK(state["switches"] == 1);

    // After: 03D0/03D1 follow the new control system; 03D2/03D3 stay.
    const Case after[] = {{route(1, 2, 0x03D0), 0x0B0B}, {route(1, 2, 0x03D1), 0x0A0A}, {route(1, 2, 0x03D2), 0x0A0A},
                          {route(1, 2, 0x03D3), 0x0B0B}, {route(1, 3, 0x03D0), 0x0B0B}, {route(1, 3, 0x03D1), 0x0A0A}};
    for (const auto& c : after)
        for (const auto codec : {Codec::Binary, Codec::Ascii}) {
            INFO("after, module I/O " << std::hex << c.route.module_io << " station " << int(c.route.station)
                                      << (codec == Codec::Ascii ? " ASCII" : " binary"));
            CHECK(show(ask(gw, read_d100(c.route, codec))) == show(word_answer(c.route, c.value, codec)));
        }
    CHECK(show(ask(a, read_d100(route(0, 0xFF, 0x03D0)))) == show(word_answer(route(0, 0xFF, 0x03D0), 0x0B0B)));
    // File commands by system reach the CPU again (it has no such file: 4022).
    CHECK(show(ask(gw, file_search(route(1, 3, 0x03D2)))) == show(error_answer(route(1, 3, 0x03D2), 0x4022, 0x1811, 0x0040)));
}

TEST_CASE("redundant pair: the control system's power cut and a scenario's system_switch switch the systems",
          "[route][plant][redundant]") {
    TempDir dir;
    // press-a's power fails at its 3rd read (a scenario fault) for 60 s.
    const auto cut = dir.write("cut.json", R"({"stations": "press-a", "faults": [
        {"do": "power_cycle", "off_ms": 60000, "match": {"command": "0401"}, "skip": 2, "count": 1}]})");
    SimProcess sim(plant_options(R"({"bind": "127.0.0.1", "stations": [
        {"name": "gw", "profile": "RJ71EN71", "tcp_port": 0, "networks": [{"number": 1, "station": 1}]},
        {"name": "press-a", "profile": "R08PCPU", "tcp_port": 0, "networks": [{"number": 1, "station": 2}],
         "redundant": {"pair": "press-b", "switchover_ms": 0, "tracking": ["D0-D99"]}, "scenarios": [")" + cut.string() + R"("]},
        {"name": "press-b", "profile": "R08PCPU", "tcp_port": 0, "networks": [{"number": 1, "station": 3}],
         "redundant": {"pair": "press-a", "system": "B"}}]})"));
    auto b = TcpClient::open(tcp_of(sim, "press-b"));
    REQUIRE(show(ask(b, write_d100(0x0B0B))) == show(kWritten));
    auto gw = TcpClient::open(tcp_of(sim, "gw"));
    CHECK(show(ask(gw, read_d100(route(1, 2, 0x03D0)))) == show(word_answer(route(1, 2, 0x03D0), 0)));
    CHECK(show(ask(gw, read_d100(route(1, 2, 0x03D0)))) == show(word_answer(route(1, 2, 0x03D0), 0)));
    // The 3rd read cuts press-a's power: the module gets no answer (CF71 at the timer, 4 × 250 ms).
    auto third = read_d100(route(1, 2, 0x03D0));
    third[9] = 0x04;   // monitoring timer 0004
    CHECK(show(ask(gw, third)) == show(error_answer(route(1, 2, 0x03D0), 0xCF71, 0x0401, 0x0000)));
    // press-b is the control system now; the standby (press-a) is down: 4245 over the tracking cable.
    auto state = pair_state(sim, "press-b");
    CHECK(state["control"] == "press-b");
    CHECK(state["up"]["press-a"] == false);
    CHECK(show(ask(gw, read_d100(route(1, 3, 0x03D0)))) == show(word_answer(route(1, 3, 0x03D0), 0x0B0B)));
    CHECK(show(ask(gw, read_d100(route(1, 3, 0x03D1)))) == show(error_answer(route(1, 3, 0x03D1), 0x4245, 0x0401, 0x0000)));
    // The standby is down: no switch.
    CHECK(http(sim.http_port(), "POST", "/api/stations/press-b/redundant/switch").status == 409);
    // A scenario's system_switch on press-b: refused while press-a is down (logged), the roles stay.
    auto started = http(sim.http_port(), "POST", "/api/stations/press-b/scenarios",
                        R"({"name": "switch", "triggers": [{"when": {"at_ms": 0}, "do": [{"system_switch": true}]}]})");
    CHECK(started.status / 100 == 2);
    CHECK(pair_state(sim, "press-b")["control"] == "press-b");
}

TEST_CASE("redundant pair: a scenario's system_switch action switches the systems", "[route][plant][redundant]") {
    SimProcess sim(plant_options(pair_plant(R"(, "devices": {"D100": 2570})")));
    auto gw = TcpClient::open(tcp_of(sim, "gw"));
    CHECK(show(ask(gw, read_d100(route(1, 3, 0x03D0)))) == show(word_answer(route(1, 3, 0x03D0), 0x0A0A)));
    auto started = http(sim.http_port(), "POST", "/api/stations/press-a/scenarios",
                        R"({"name": "switch", "triggers": [{"when": {"at_ms": 0}, "do": [{"system_switch": true}]}]})");
    REQUIRE(started.status / 100 == 2);
    const auto deadline = std::chrono::steady_clock::now() + std::chrono::seconds(5);
    auto state = pair_state(sim, "press-a");
    while ((state["control"] != "press-b" || state["switching"] == true) && std::chrono::steady_clock::now() < deadline) {
        std::this_thread::sleep_for(std::chrono::milliseconds(10));
        state = pair_state(sim, "press-a");
    }
    CHECK(state["control"] == "press-b");
    CHECK(state["switching"] == false);
    CHECK(show(ask(gw, read_d100(route(1, 3, 0x03D0)))) == show(word_answer(route(1, 3, 0x03D0), 0)));
    CHECK(show(ask(gw, read_d100(route(1, 3, 0x03D1)))) == show(word_answer(route(1, 3, 0x03D1), 0x0A0A)));
}

TEST_CASE("multidrop: a station behind another station's serial module, reached through the module's route",
          "[route][plant][multidrop]") {
    // line: station 2 of network 1, with a serial module at start I/O 0040 (route module I/O 0004);
    // drop-3 and drop-7 hang on it as multidrop stations 3 and 7.
    SimProcess sim(plant_options(R"({"bind": "127.0.0.1", "http": {"enabled": false}, "stations": [
        {"name": "gw", "profile": "RJ71EN71", "tcp_port": 0, "udp_port": 0, "networks": [{"number": 1, "station": 1}]},
        {"name": "line", "profile": "R08CPU", "tcp_port": 0, "networks": [{"number": 1, "station": 2}], "devices": {"D100": 1}},
        {"name": "drop-3", "profile": "Q26UDEHCPU", "tcp_port": 0, "multidrop": {"via": "line", "start_io": "0040", "number": 3},
         "devices": {"D100": 3}},
        {"name": "drop-7", "profile": "R08CPU", "tcp_port": 0, "multidrop": {"via": "line", "start_io": "0040", "number": 7},
         "devices": {"D100": 7}}]})"));
    auto gw = TcpClient::open(tcp_of(sim, "gw"));
    UdpClient gw_udp;
    for (const auto codec : {Codec::Binary, Codec::Ascii}) {
        CHECK(show(ask(gw, read_d100(route(1, 2, 0x0004, 3), codec))) == show(word_answer(route(1, 2, 0x0004, 3), 3, codec)));
        CHECK(show(ask(gw, read_d100(route(1, 2, 0x0004, 7), codec))) == show(word_answer(route(1, 2, 0x0004, 7), 7, codec)));
        CHECK(show(ask(gw_udp, udp_of(sim, "gw"), read_d100(route(1, 2, 0x0004, 7), codec))) ==
              show(word_answer(route(1, 2, 0x0004, 7), 7, codec)));
        // The relaying station itself: multidrop 00, module I/O 03FF.
        CHECK(show(ask(gw, read_d100(route(1, 2, 0x03FF, 0), codec))) == show(word_answer(route(1, 2, 0x03FF, 0), 1, codec)));
    }
    // A write lands in the multidrop station only.
    const std::vector<std::uint16_t> words{0x1234};
    CHECK(show(ask(gw, client::write_words(with(route(1, 2, 0x0004, 3)), addr("D101"), words))) ==
          show(hex("D0 00 01 02 04 00 03 02 00 00 00")));
    auto line = TcpClient::open(tcp_of(sim, "line"));
    CHECK(show(ask(line, client::read_words(with(Route{}), addr("D101"), 1))) == show(word_answer(Route{}, 0)));
    auto drop = TcpClient::open(tcp_of(sim, "drop-3"));
    CHECK(show(ask(drop, client::read_words(with(Route{}), addr("D101"), 1))) == show(word_answer(Route{}, 0x1234)));
    // No multidrop station 5 on that line: the relaying station answers 4A02; no serial module at 0005: 4A02 too.
    CHECK(show(ask(gw, read_d100(route(1, 2, 0x0004, 5)))) == show(error_answer(route(1, 2, 0x0004, 5), 0x4A02, 0x0401, 0)));
    CHECK(show(ask(gw, read_d100(route(1, 2, 0x0005, 3)))) == show(error_answer(route(1, 2, 0x0005, 3), 0x4A02, 0x0401, 0)));
    // A multidrop station is not among the file commands' destinations (§3.1.4): 4B02.
    CHECK(show(ask(gw, file_search(route(1, 2, 0x0004, 3)))) == show(error_answer(route(1, 2, 0x0004, 3), 0x4B02, 0x1811, 0x0040)));
    // A CPU's built-in port reaches no multidrop station (§2.3): 4A02 as before.
    CHECK(show(ask(line, read_d100(route(0, 0xFF, 0x0004, 3)))) == show(error_answer(route(0, 0xFF, 0x0004, 3), 0x4A02, 0x0401, 0)));
}

TEST_CASE("file commands: only the request destinations of §3.1.4's table, 4B02 otherwise", "[route][files]") {
    SimProcess sim(plant_options(R"({"bind": "127.0.0.1", "http": {"enabled": false}, "stations": [
        {"name": "cpu", "profile": "R08CPU", "tcp_port": 0}]})"));
    auto cpu = TcpClient::open(tcp_of(sim, "cpu"));
    for (const auto codec : {Codec::Binary, Codec::Ascii}) {
        CHECK(show(ask(cpu, file_search(Route{}, codec))) == show(error_answer(Route{}, 0x4022, 0x1811, 0x0040, codec)));
        CHECK(show(ask(cpu, file_search(route(0, 0xFF, 0x03E0), codec))) ==
              show(error_answer(route(0, 0xFF, 0x03E0), 0x4022, 0x1811, 0x0040, codec)));
        for (const std::uint16_t io : {0x03D0, 0x03D1, 0x03D2, 0x03D3}) {
            INFO("module I/O " << std::hex << io);
            CHECK(show(ask(cpu, file_search(route(0, 0xFF, io), codec))) ==
                  show(error_answer(route(0, 0xFF, io), 0x4B02, 0x1811, 0x0040, codec)));
        }
    }
}

// --- Tracking, the pair's SM/SD, and the switches a stop error or a RESET causes ---------------

namespace {

// press-a (A) and press-b (B), switching at once (switchover 0), tracking the
// default ranges (all of M, L, B, D, W, the timers' and counters' values).
std::string tracking_plant(const std::string& extra_a = "") {
    return R"({"bind": "127.0.0.1", "stations": [
        {"name": "gw", "profile": "RJ71EN71", "tcp_port": 0, "udp_port": 0, "networks": [{"number": 1, "station": 1}]},
        {"name": "press-a", "profile": "R08PCPU", "tcp_port": 0, "networks": [{"number": 1, "station": 2}],
         "redundant": {"pair": "press-b", "system": "A", "switchover_ms": 0})" + extra_a + R"(},
        {"name": "press-b", "profile": "R08PCPU", "tcp_port": 0, "networks": [{"number": 1, "station": 3}],
         "redundant": {"pair": "press-a", "system": "B"}}]})";
}

const Route kToA = route(1, 2, 0x03FF);   // through gw to press-a, whatever its role
const Route kToB = route(1, 3, 0x03FF);

Bytes words_answer(const Route& r, const std::vector<std::uint16_t>& values, Codec codec = Codec::Binary) {
    std::string data;
    for (auto v : values) data += codec == Codec::Ascii ? ascii_hex(v, 4) : hex2(v) + " " + hex2(v >> 8) + " ";
    const auto n = values.size();
    if (codec == Codec::Ascii) return text("D000" + route_ascii(r) + ascii_hex(4 + 4 * n, 4) + "0000" + data);
    return hex("D0 00 " + route_hex(r) + " " + hex2(2 + 2 * n) + " 00 00 00 " + data);
}
// Bits read in bit units: "1010" is 4 points, ON OFF ON OFF.
Bytes bits_answer(const Route& r, const std::string& bits, Codec codec = Codec::Binary) {
    if (codec == Codec::Ascii) return text("D000" + route_ascii(r) + ascii_hex(4 + bits.size(), 4) + "0000" + bits);
    std::string data;
    for (std::size_t i = 0; i < bits.size(); i += 2) data += std::string(1, bits[i]) + (i + 1 < bits.size() ? bits[i + 1] : '0') + " ";
    return hex("D0 00 " + route_hex(r) + " " + hex2(2 + (bits.size() + 1) / 2) + " 00 00 00 " + data);
}
Bytes read(const Route& r, const char* device, std::uint16_t points, Codec codec = Codec::Binary) {
    return client::read_words(with(r, codec), addr(device), points);
}
Bytes write_word(const char* device, std::uint16_t value) {
    const std::vector<std::uint16_t> words{value};
    return client::write_words(with(Route{}), addr(device), words);
}

void step(const SimProcess& sim, const std::string& station, int scans = 1) {
    auto stepped = http(sim.http_port(), "POST", "/api/stations/" + station + "/clock/step",
                        R"({"scans": )" + std::to_string(scans) + "}");
    REQUIRE(stepped.status == 200);
}

// The pair's flags of one CPU, read through gw by binary and ASCII, TCP and UDP:
// SM1632-SM1635 (system A, system B, control, standby) and SD1643/SD1644 (own
// switch cause, switch failure), SD1649 (the last switch's cause).
void check_flags(const SimProcess& sim, TcpClient& gw, UdpClient& gw_udp, const Route& r, const std::string& sm,
                 std::uint16_t own, std::uint16_t failure, std::uint16_t last) {
    for (const auto codec : {Codec::Binary, Codec::Ascii}) {
        INFO("station " << int(r.station) << (codec == Codec::Ascii ? " ASCII" : " binary"));
        const auto bits = client::read_bits(with(r, codec), addr("SM1632"), 4);
        CHECK(show(ask(gw, bits)) == show(bits_answer(r, sm, codec)));
        CHECK(show(ask(gw_udp, udp_of(sim, "gw"), bits)) == show(bits_answer(r, sm, codec)));
        CHECK(show(ask(gw, read(r, "SD1643", 2, codec))) == show(words_answer(r, {own, failure}, codec)));
        CHECK(show(ask(gw_udp, udp_of(sim, "gw"), read(r, "SD1649", 1, codec))) == show(words_answer(r, {last}, codec)));
    }
}

}  // namespace

TEST_CASE("redundant pair: tracking at the control system's END, a write to the standby, the flags across a switch",
          "[route][plant][redundant][tracking]") {
    SimProcess sim(plant_options(tracking_plant(), {"--clock", "frozen"}));
    auto a = TcpClient::open(tcp_of(sim, "press-a"));
    auto b = TcpClient::open(tcp_of(sim, "press-b"));
    auto gw = TcpClient::open(tcp_of(sim, "gw"));
    UdpClient gw_udp;

    // Before any switch: A is the control system, B the standby; no cause yet.
    check_flags(sim, gw, gw_udp, kToA, "1010", 0, 0, 0);
    check_flags(sim, gw, gw_udp, kToB, "0101", 0, 0, 0);

    // Written to the control system: the standby has it after the control system's END, not before.
    REQUIRE(show(ask(a, write_word("D100", 0x1234))) == show(kWritten));
    REQUIRE(show(ask(a, write_word("W10", 0x00AB))) == show(kWritten));
    REQUIRE(show(ask(a, write_word("M16", 0x8001))) == show(kWritten));   // M16 and M31, a word of bits
    CHECK(show(ask(gw, read(kToB, "D100", 1))) == show(words_answer(kToB, {0})));
    step(sim, "press-a");
    for (const auto codec : {Codec::Binary, Codec::Ascii}) {
        const auto standby = route(1, 2, 0x03D1);
        CHECK(show(ask(gw, read(standby, "D100", 1, codec))) == show(words_answer(standby, {0x1234}, codec)));
        CHECK(show(ask(gw_udp, udp_of(sim, "gw"), read(kToB, "W10", 1, codec))) == show(words_answer(kToB, {0x00AB}, codec)));
        CHECK(show(ask(gw, read(kToB, "M16", 1, codec))) == show(words_answer(kToB, {0x8001}, codec)));
    }

    // A write to the standby is served, and the standby's next END gives it back the control system's value.
    CHECK(show(ask(b, write_word("D100", 0x5555))) == show(kWritten));
    CHECK(show(ask(b, read(Route{}, "D100", 1))) == show(words_answer(Route{}, {0x5555})));
    step(sim, "press-b");
    CHECK(show(ask(b, read(Route{}, "D100", 1))) == show(words_answer(Route{}, {0x1234})));

    // The control system's last END before the switch is what the new control system holds.
    REQUIRE(show(ask(a, write_word("D100", 0x2222))) == show(kWritten));
    step(sim, "press-a");
    auto posted = http(sim.http_port(), "POST", "/api/stations/press-a/redundant/switch");
    REQUIRE(posted.status == 200);
    CHECK(posted.json()["control"] == "press-b");
    for (const auto codec : {Codec::Binary, Codec::Ascii}) {
        const auto control = route(1, 2, 0x03D0);
        CHECK(show(ask(gw, read(control, "D100", 1, codec))) == show(words_answer(control, {0x2222}, codec)));
        CHECK(show(ask(gw_udp, udp_of(sim, "gw"), read(control, "W10", 1, codec))) == show(words_answer(control, {0x00AB}, codec)));
    }
    // The flags after: A standby, B control; the switch's cause 17 (the engineering tool's request: the API),
    // which occurred in A.
    check_flags(sim, gw, gw_udp, kToA, "1001", 17, 0, 17);
    check_flags(sim, gw, gw_udp, kToB, "0110", 0, 0, 17);

    // Tracking goes the other way now: B's END reaches A; A's own END tracks nothing.
    REQUIRE(show(ask(b, write_word("D100", 0x3333))) == show(kWritten));
    REQUIRE(show(ask(a, write_word("D101", 0x4444))) == show(kWritten));
    step(sim, "press-a");   // the standby's END: no image of B's yet, so D101 stays
    CHECK(show(ask(a, read(Route{}, "D101", 1))) == show(words_answer(Route{}, {0x4444})));
    CHECK(show(ask(gw, read(kToB, "D100", 1))) == show(words_answer(kToB, {0x3333})));
    step(sim, "press-b");
    CHECK(show(ask(gw, read(kToA, "D100", 2))) == show(words_answer(kToA, {0x3333, 0})));
}

TEST_CASE("redundant pair: a stop error of the control system switches the systems, a STOP does not",
          "[route][plant][redundant][tracking]") {
    SimProcess sim(plant_options(tracking_plant(), {"--clock", "frozen"}));
    auto a = TcpClient::open(tcp_of(sim, "press-a"));
    auto gw = TcpClient::open(tcp_of(sim, "gw"));
    UdpClient gw_udp;
    REQUIRE(show(ask(a, write_word("D200", 0x0777))) == show(kWritten));
    step(sim, "press-a");

    // STOP: the roles stay (a real pair does not switch on STOP).
    REQUIRE(http_put(sim.http_port(), "/api/stations/press-a/state", R"({"switch": "STOP"})").status == 200);
    step(sim, "press-a");
    CHECK(pair_state(sim, "press-a")["control"] == "press-a");
    CHECK(pair_state(sim, "press-a")["switches"] == 0);
    REQUIRE(http_put(sim.http_port(), "/api/stations/press-a/state", R"({"switch": "RUN"})").status == 200);

    // A stop error by the API: the control system switches at its END.
    auto raised = http_put(sim.http_port(), "/api/stations/press-a/state", R"({"error": {"code": "3100", "stop": true}})");
    REQUIRE(raised.status == 200);
    CHECK(raised.json()["state"] == "STOP");
    step(sim, "press-a");
    auto state = pair_state(sim, "press-a");
    CHECK(state["control"] == "press-b");
    CHECK(state["switches"] == 1);
    for (const auto codec : {Codec::Binary, Codec::Ascii}) {
        const auto control = route(1, 3, 0x03D0);
        CHECK(show(ask(gw, read(control, "D200", 1, codec))) == show(words_answer(control, {0x0777}, codec)));
    }
    check_flags(sim, gw, gw_udp, kToA, "1001", 2, 0, 2);
    check_flags(sim, gw, gw_udp, kToB, "0110", 0, 0, 2);

    // A stop error on the new control system by a scenario: the standby is in a stop error too, no switch
    // (SD1644 = 3 on the control system).
    auto started = http(sim.http_port(), "POST", "/api/stations/press-b/scenarios",
                        R"({"name": "fail", "triggers": [{"when": {"at_ms": 0}, "do": [{"error": {"code": "3200", "stop": true}}]}]})");
    REQUIRE(started.status / 100 == 2);
    step(sim, "press-b", 2);
    CHECK(pair_state(sim, "press-b")["control"] == "press-b");
    check_flags(sim, gw, gw_udp, kToB, "0110", 0, 3, 2);

    // press-a's RESET (the API's RESET switch) clears its stop error; press-b's next END switches to it.
    REQUIRE(http_put(sim.http_port(), "/api/stations/press-a/state", R"({"reset": true})").status == 200);
    step(sim, "press-b");
    state = pair_state(sim, "press-a");
    CHECK(state["control"] == "press-a");
    CHECK(state["switches"] == 2);
    check_flags(sim, gw, gw_udp, kToA, "1010", 0, 0, 2);   // its registers started afresh at the RESET
    check_flags(sim, gw, gw_udp, kToB, "0101", 2, 0, 2);
}

TEST_CASE("redundant pair: a RESET of the control system switches the systems (Remote RESET and the API)",
          "[route][plant][redundant][tracking]") {
    SimProcess sim(plant_options(tracking_plant(R"(, "cpu": {"remote_reset": true})"), {"--clock", "frozen"}));
    auto a = TcpClient::open(tcp_of(sim, "press-a"));
    auto gw = TcpClient::open(tcp_of(sim, "gw"));
    UdpClient gw_udp;
    REQUIRE(show(ask(a, write_word("D300", 0x0300))) == show(kWritten));
    step(sim, "press-a");

    // Remote STOP: no switch. Remote RESET: no answer, the connection closes, the systems switch.
    REQUIRE(show(ask(a, client::remote_stop(with(Route{})))) == show(kWritten));
    CHECK(pair_state(sim, "press-a")["control"] == "press-a");
    REQUIRE(a.send(client::remote_reset(with(Route{}))));
    Bytes unexpected;
    CHECK(a.wait_closed(std::chrono::seconds(10), &unexpected));
    CHECK(unexpected.empty());
    auto state = pair_state(sim, "press-a");
    CHECK(state["control"] == "press-b");
    CHECK(state["switches"] == 1);
    for (const auto codec : {Codec::Binary, Codec::Ascii}) {
        const auto control = route(1, 2, 0x03D0);
        CHECK(show(ask(gw, read(control, "D300", 1, codec))) == show(words_answer(control, {0x0300}, codec)));
    }
    // Cause 1 (power off or RESET); the reset CPU stores none (its registers start afresh).
    check_flags(sim, gw, gw_udp, kToA, "1001", 0, 0, 0);
    check_flags(sim, gw, gw_udp, kToB, "0110", 0, 0, 1);

    // The API's RESET switch on the new control system switches back.
    REQUIRE(http_put(sim.http_port(), "/api/stations/press-b/state", R"({"reset": true})").status == 200);
    CHECK(pair_state(sim, "press-a")["control"] == "press-a");
    check_flags(sim, gw, gw_udp, kToA, "1010", 0, 0, 1);
    check_flags(sim, gw, gw_udp, kToB, "0101", 0, 0, 0);
}

TEST_CASE("redundant pair: the program sees its CPU's role in SM1634/SM1635", "[route][plant][redundant][program]") {
    TempDir dir;
    // Y is each system's own I/O (not tracked): Y0 ON on the control system, Y1 on the standby.
    const auto program = dir.write("role.il", "LD SM1634\nOUT Y0\nLD SM1635\nOUT Y1\nEND\n");
    const auto cpu = R"(, "cpu": {"program": {"file": ")" + program.string() + R"("}})";
    SimProcess sim(plant_options(R"({"bind": "127.0.0.1", "stations": [
        {"name": "gw", "profile": "RJ71EN71", "tcp_port": 0, "networks": [{"number": 1, "station": 1}]},
        {"name": "press-a", "profile": "R08PCPU", "tcp_port": 0, "networks": [{"number": 1, "station": 2}],
         "redundant": {"pair": "press-b", "switchover_ms": 0})" + cpu + R"(},
        {"name": "press-b", "profile": "R08PCPU", "tcp_port": 0, "networks": [{"number": 1, "station": 3}],
         "redundant": {"pair": "press-a", "system": "B"})" + cpu + R"(}]})", {"--clock", "frozen"}));
    auto gw = TcpClient::open(tcp_of(sim, "gw"));
    const auto outputs = [&](const Route& r) { return show(ask(gw, client::read_bits(with(r), addr("Y0"), 2))); };
    step(sim, "press-a");
    step(sim, "press-b");
    CHECK(outputs(kToA) == show(bits_answer(kToA, "10")));
    CHECK(outputs(kToB) == show(bits_answer(kToB, "01")));
    REQUIRE(http(sim.http_port(), "POST", "/api/stations/press-b/redundant/switch").status == 200);
    step(sim, "press-a");
    step(sim, "press-b");
    CHECK(outputs(kToA) == show(bits_answer(kToA, "01")));
    CHECK(outputs(kToB) == show(bits_answer(kToB, "10")));
}
