// The HTTP control API against the real slmp-sim binary (docs/api.md): device
// reads and writes in every view, cross-checked byte for byte over SLMP in
// binary and ASCII; info; connections; and every kind of bad input with its
// exact status and message.
#include <catch2/catch.hpp>

#include <string>
#include <vector>

#include "frames.hpp"
#include "http_client.hpp"
#include "link.hpp"
#include "sim_process.hpp"
#include "sockets.hpp"

using namespace slmp::test;
namespace client = slmp::protocol::client;
using nlohmann::json;

namespace {

const Wire kBinary{FrameKind::E3, Codec::Binary, 0};
const Wire kAscii{FrameKind::E3, Codec::Ascii, 0};

void expect_error(const HttpResponse& r, int status, const std::string& message) {
    INFO(r.body);
    CHECK(r.status == status);
    CHECK(r.header("content-type") == "application/json");
    CHECK(r.error() == message);
}

}  // namespace

TEST_CASE("HTTP API: words written over SLMP are read by the API, binary and ASCII", "[http]") {
    SimProcess sim;
    TcpLink link(sim.tcp_port());
    for (const auto& w : {kBinary, kAscii}) {
        INFO(w.name());
        auto start = w.codec == Codec::Binary ? "D100" : "D110";
        REQUIRE(show(link.exchange(client::write_words(w.options(), addr(start), std::vector<std::uint16_t>{1, 0x8000, 0xFFFF}))) ==
                show(expected_response(w, {})));
        auto r = http_get(sim.http_port(), std::string("/api/devices/") + start + "?count=3");
        CHECK(r.status == 200);
        CHECK(r.json() == json{{"device", start}, {"as", "words"}, {"count", 3}, {"values", {1, 32768, 65535}}});
    }
}

TEST_CASE("HTTP API: values written by the API are read over SLMP byte for byte", "[http]") {
    SimProcess sim;
    TcpLink link(sim.tcp_port());

    SECTION("words, negative values in two's complement") {
        auto r = http_put(sim.http_port(), "/api/devices/D300", R"({"values": [4660, -1, 0]})");
        CHECK(r.status == 200);
        CHECK(r.json() == json{{"device", "D300"}, {"as", "words"}, {"count", 3}, {"values", {4660, 65535, 0}}});
        for (const auto& w : {kBinary, kAscii})
            CHECK(show(link.exchange(client::read_words(w.options(), addr("D300"), 3))) ==
                  show(expected_response(w, word_data(w, {0x1234, 0xFFFF, 0x0000}))));
    }
    SECTION("bits, as 0/1 and true/false") {
        auto r = http_put(sim.http_port(), "/api/devices/M10", R"({"values": [1, 0, true, true, false]})");
        CHECK(r.status == 200);
        CHECK(r.json()["values"] == json{1, 0, 1, 1, 0});
        for (const auto& w : {kBinary, kAscii})
            CHECK(show(link.exchange(client::read_bits(w.options(), addr("M10"), 5))) ==
                  show(expected_response(w, bit_data(w, {1, 0, 1, 1, 0}))));
        // The same bits as a word: bit k is M(10 + k).
        CHECK(http_get(sim.http_port(), "/api/devices/M10?as=words").json()["values"] == json{0x0D});
    }
    SECTION("hexadecimal devices: X1F") {
        CHECK(http_put(sim.http_port(), "/api/devices/X1F", R"({"values": [1]})").status == 200);
        CHECK(show(link.exchange(client::read_bits(kBinary.options(), addr("X1E"), 2))) ==
              show(expected_response(kBinary, bit_data(kBinary, {0, 1}))));
        CHECK(http_get(sim.http_port(), "/api/devices/x1e?count=2").json()["device"] == "X1E");
    }
    SECTION("double words: low word first") {
        auto r = http_put(sim.http_port(), "/api/devices/D400?as=dwords", R"({"values": [305419896, -2]})");
        CHECK(r.status == 200);
        CHECK(show(link.exchange(client::read_words(kBinary.options(), addr("D400"), 4))) ==
              show(expected_response(kBinary, word_data(kBinary, {0x5678, 0x1234, 0xFFFE, 0xFFFF}))));
        CHECK(http_get(sim.http_port(), "/api/devices/D400?as=dwords&count=2").json()["values"] == json{305419896, 4294967294u});
    }
    SECTION("long devices hold 32-bit values: LTN") {
        CHECK(http_put(sim.http_port(), "/api/devices/LTN2", R"({"values": [70000]})").status == 200);
        CHECK(http_get(sim.http_port(), "/api/devices/LTN2").json() ==
              json{{"device", "LTN2"}, {"as", "dwords"}, {"count", 1}, {"values", {70000}}});
    }
    SECTION("strings: two bytes a word, low byte first, NUL-terminated") {
        auto r = http_put(sim.http_port(), "/api/devices/D500", R"({"string": "HELLO"})");
        CHECK(r.status == 200);
        CHECK(r.json() == json{{"device", "D500"}, {"as", "string"}, {"count", 3}, {"string", "HELLO"}});
        CHECK(show(link.exchange(client::read_words(kAscii.options(), addr("D500"), 3))) ==
              show(expected_response(kAscii, word_data(kAscii, {0x4548, 0x4C4C, 0x004F}))));
        // An even length gets a whole NUL word, as the CPU's string instructions store it.
        CHECK(http_put(sim.http_port(), "/api/devices/D600", R"({"string": "AB"})").json()["count"] == 2);
        CHECK(http_get(sim.http_port(), "/api/devices/D600?count=2").json()["values"] == json{0x4241, 0});
        CHECK(http_get(sim.http_port(), "/api/devices/D600?as=string&count=10").json()["string"] == "AB");
        // One byte a character: Latin-1 survives the round trip.
        CHECK(http_put(sim.http_port(), "/api/devices/D700", "{\"string\": \"\xC3\xA9t\xC3\xA9\"}").status == 200);
        CHECK(http_get(sim.http_port(), "/api/devices/D700?count=2").json()["values"] == json{0x74E9, 0x00E9});
        CHECK(http_get(sim.http_port(), "/api/devices/D700?as=string&count=2").json()["string"] == "\xC3\xA9t\xC3\xA9");
    }
}

TEST_CASE("HTTP API: bad input gets 400 with a message that names the fix", "[http]") {
    SimProcess sim;
    auto port = sim.http_port();
    SECTION("unknown device") {
        expect_error(http_get(port, "/api/devices/Q100"), 400,
                     "unknown device in address 'Q100' (expected e.g. D100, M0, X1F, ZR1000)");
    }
    SECTION("bad device number") {
        expect_error(http_get(port, "/api/devices/D1F"), 400,
                     "bad device number '1F' in address 'D1F' (D is numbered in decimal)");
    }
    SECTION("past the configured size") {
        expect_error(http_get(port, "/api/devices/D10239?count=2"), 400,
                     "D10239 with 2 words runs past D10239, the last D device of R08CPU (10240 devices); lower the "
                     "start or count, or raise device_sizes.D in the configuration");
        expect_error(http_put(port, "/api/devices/M12287", R"({"values": [1, 1]})"), 400,
                     "M12287 with 2 bits runs past M12287, the last M device of R08CPU (12288 devices); lower the "
                     "start or count, or raise device_sizes.M in the configuration");
    }
    SECTION("count") {
        expect_error(http_get(port, "/api/devices/D0?count=0"), 400,
                     "count 0 is out of range; use 1 to 65536 (read larger spans in parts)");
        expect_error(http_get(port, "/api/devices/D0?count=ten"), 400, "count=ten is not a number; use 1 to 65536");
    }
    SECTION("views") {
        expect_error(http_get(port, "/api/devices/D0?as=bytes"), 400,
                     "as=bytes is not a view; use bits, words, dwords or string");
        expect_error(http_get(port, "/api/devices/D0?as=bits"), 400,
                     "D is a word device; use as=words, as=dwords or as=string");
        expect_error(http_get(port, "/api/devices/LTN0?as=words"), 400, "LTN holds 32-bit values; use as=dwords");
        expect_error(http_get(port, "/api/devices/M0?as=string"), 400,
                     "as=string needs a word device such as D, W or R; M is not one");
    }
    SECTION("unknown query parameter") {
        expect_error(http_get(port, "/api/devices/D0?cnt=2"), 400,
                     "unknown query parameter 'cnt' for /api/devices/D0; use count, as");
    }
    SECTION("malformed JSON and bad bodies") {
        expect_error(http_put(port, "/api/devices/D0", R"({"values": [1,)"), 400,
                     "the body is not valid JSON; send {\"values\": [1, 2, 3]} or {\"string\": \"text\"}");
        expect_error(http_put(port, "/api/devices/D0", "[1, 2]"), 400,
                     "the body must be a JSON object: {\"values\": [...]} or {\"string\": \"...\"}");
        expect_error(http_put(port, "/api/devices/D0", R"({"value": [1]})"), 400,
                     "unknown key \"value\" in the body; use \"values\" or \"string\"");
        expect_error(http_put(port, "/api/devices/D0", R"({"values": [1], "string": "A"})"), 400,
                     "give either \"values\" or \"string\", not both");
        expect_error(http_put(port, "/api/devices/D0", R"({"values": 5})"), 400,
                     "\"values\" must be a list of numbers, e.g. {\"values\": [1, 2, 3]}");
        expect_error(http_put(port, "/api/devices/D0", R"({"values": []})"), 400,
                     "\"values\" is empty; give at least one value");
    }
    SECTION("values that do not fit") {
        expect_error(http_put(port, "/api/devices/D0", R"({"values": [1, 65536]})"), 400,
                     "values[1]: 65536 does not fit a 16-bit word; use -32768..65535");
        expect_error(http_put(port, "/api/devices/D0", R"({"values": [1.5]})"), 400,
                     "values[0]: 1.5 is not an integer; give whole numbers");
        expect_error(http_put(port, "/api/devices/M0", R"({"values": [2]})"), 400,
                     "values[0]: 2 is not a bit value; use 0, 1, true or false");
        expect_error(http_put(port, "/api/devices/D0?as=dwords", R"({"values": [4294967296]})"), 400,
                     "values[0]: 4294967296 does not fit a 32-bit double word; use -2147483648..4294967295");
        expect_error(http_put(port, "/api/devices/D0", "{\"string\": \"\xE3\x81\x82\"}"), 400,
                     "\"string\": character \xE3\x81\x82 at byte 0 is not a single byte; strings are stored one byte "
                     "a character (U+0000-U+00FF)");
    }
    SECTION("a rejected write changes nothing") {
        REQUIRE(http_put(port, "/api/devices/D20", R"({"values": [7, 7, 7]})").status == 200);
        CHECK(http_put(port, "/api/devices/D20", R"({"values": [1, 2, 70000]})").status == 400);
        CHECK(http_put(port, "/api/devices/D10238", R"({"values": [1, 2, 3]})").status == 400);
        CHECK(http_get(port, "/api/devices/D20?count=3").json()["values"] == json{7, 7, 7});
        CHECK(http_get(port, "/api/devices/D10238?count=2").json()["values"] == json{0, 0});
    }
    SECTION("buffer memory is not a plain device") {
        expect_error(http_get(port, "/api/devices/G0"), 400,
                     "G (buffer memory) is reached through a module, not as a plain device; read a CPU device such "
                     "as D100 instead");
    }
}

TEST_CASE("HTTP API: unknown routes 404, wrong methods 405, big bodies 413", "[http]") {
    SimProcess sim;
    auto port = sim.http_port();
    expect_error(http_get(port, "/api/nothing"), 404,
                 "no endpoint /api/nothing; the endpoints are listed in docs/api.md (e.g. /api/info)");
    auto r = http(port, "POST", "/api/devices/D0", "{}");
    expect_error(r, 405, "POST is not served on /api/devices/D0; use GET, PUT");
    CHECK(r.header("allow") == "GET, PUT");
    std::string big = "{\"values\": [" + std::string(1 << 20, '1') + "]}";
    expect_error(http_put(port, "/api/devices/D0", big), 413,
                 "the request body is over 1048576 bytes; write fewer values per request");
}

TEST_CASE("HTTP API: info names the profile, sizes, devices and ports", "[http]") {
    SimProcess sim(with_args({"--profile", "Q26UDEHCPU"}));
    auto info = http_get(sim.http_port(), "/api/info").json();
    CHECK(info["profile"] == json{{"name", "Q26UDEHCPU"}, {"type_name", "Q26UDEHCPU"}, {"model_code", "026C"}, {"family", "QnU"}});
    CHECK(info["ports"]["tcp"] == json{sim.tcp_port()});
    CHECK(info["ports"]["udp"] == json{sim.udp_port()});
    CHECK(info["ports"]["http"] == sim.http_port());
    CHECK(info["ports"]["bind"] == "127.0.0.1");
    CHECK(info["device_sizes"]["D"].get<unsigned>() > 0);
    bool has_x = false;
    for (const auto& d : info["devices"])
        if (d["symbol"] == "X") has_x = d == json{{"symbol", "X"}, {"unit", "bit"}, {"radix", 16}, {"name", "input"}};
    CHECK(has_x);
}

TEST_CASE("HTTP API: connections are listed and one can be closed", "[http]") {
    SimProcess sim;
    auto port = sim.http_port();
    TcpLink first(sim.tcp_port());
    TcpLink second(sim.tcp_port());
    REQUIRE(!first.exchange(client::read_words(kBinary.options(), addr("D0"), 1)).empty());
    REQUIRE(!first.exchange(client::read_words(kBinary.options(), addr("D0"), 1)).empty());
    REQUIRE(!second.exchange(client::read_words(kBinary.options(), addr("D0"), 1)).empty());

    auto list = http_get(port, "/api/connections").json()["connections"];
    REQUIRE(list.size() == 2);
    CHECK(list[0]["transport"] == "tcp");
    CHECK(list[0]["port"] == sim.tcp_port());
    CHECK(list[0]["requests"] == 2);
    CHECK(list[1]["requests"] == 1);
    CHECK(list[0]["peer"].get<std::string>().rfind("tcp:127.0.0.1:", 0) == 0);
    CHECK(list[0]["opened"].get<std::string>().size() == std::string("2024-01-01T00:00:00.000Z").size());

    auto id = list[0]["id"].get<std::uint64_t>();
    auto closed = http(port, "DELETE", "/api/connections/" + std::to_string(id));
    CHECK(closed.status == 200);
    CHECK(closed.json() == json{{"closed", id}});
    CHECK(first.client().wait_closed(kReplyTimeout));

    // The session leaves the list once its coroutine has finished; bounded wait.
    auto deadline = std::chrono::steady_clock::now() + kReplyTimeout;
    while (http_get(port, "/api/connections").json()["connections"].size() != 1 && std::chrono::steady_clock::now() < deadline)
        std::this_thread::sleep_for(std::chrono::milliseconds(10));
    CHECK(http_get(port, "/api/connections").json()["connections"].size() == 1);

    expect_error(http(port, "DELETE", "/api/connections/" + std::to_string(id)), 404,
                 "no open connection " + std::to_string(id) + "; GET /api/connections lists the open ones");
    expect_error(http(port, "DELETE", "/api/connections/first"), 400,
                 "connection id 'first' is not a number; take the id from GET /api/connections");
}

TEST_CASE("HTTP API: options and configuration", "[http]") {
    SECTION("--no-http serves no HTTP port and leaves it out of the ready file") {
        SimProcess sim(with_args({"--no-http"}));
        CHECK_FALSE(sim.ready().contains("http"));
    }
    SECTION("the configuration file's http object") {
        SimOptions off;
        off.config_json = R"({"http": {"enabled": false}})";
        CHECK_FALSE(SimProcess(off).ready().contains("http"));
        SimOptions on;
        on.config_json = R"({"http": {"port": 0, "bind": "127.0.0.1"}})";
        SimProcess sim(on);
        REQUIRE(sim.http_port() != 0);
        CHECK(http_get(sim.http_port(), "/api/info").status == 200);
    }
    SECTION("unknown http keys are errors") {
        TempDir dir;
        auto file = dir.write("c.json", R"({"http": {"prot": 8080}})");
        auto r = run_sim({"--config", file.string()});
        CHECK(r.exit_code == 2);
        CHECK(r.err.find("/http/prot") != std::string::npos);
    }
    SECTION("--no-http with --http-port is a contradiction") {
        auto r = run_sim({"--no-http", "--http-port", "0", "--tcp-port", "0"});
        CHECK(r.exit_code == 2);
        CHECK(r.err == "slmp-sim: error: --no-http contradicts --http-port/--http-bind; give one or the other\n");
    }
    SECTION("a taken HTTP port names the fix") {
        SimProcess first;
        auto r = run_sim({"--tcp-port", "0", "--udp-port", "0", "--bind", "127.0.0.1", "--http-port",
                          std::to_string(first.http_port())});
        CHECK(r.exit_code == 2);
        CHECK(r.err == "slmp-sim: error: cannot listen on HTTP 127.0.0.1:" + std::to_string(first.http_port()) +
                           ": Address already in use; choose another port (--http-port, 0 = any free port) or turn "
                           "the HTTP API off (--no-http)\n");
    }
}

TEST_CASE("HTTP API: the operating state and the RUN/STOP switch", "[http][state]") {
    SimProcess sim;
    auto port = sim.http_port();
    auto state = http_get(port, "/api/state");
    CHECK(state.status == 200);
    CHECK(state.json() == json{{"state", "RUN"}, {"switch", "RUN"}, {"cause", nullptr}, {"remote_hold", nullptr}, {"error", nullptr}});

    auto stopped = http_put(port, "/api/state", R"({"switch": "STOP"})");
    CHECK(stopped.status == 200);
    CHECK(stopped.json() == json{{"state", "STOP"}, {"switch", "STOP"}, {"cause", "switch"}, {"remote_hold", nullptr}, {"error", nullptr}});
    // SD203 (bits 0-3) shows STOP over SLMP too.
    TcpLink link(sim.tcp_port());
    const Wire w{};
    auto sd203 = link.exchange(client::read_words(w.options(), addr("SD203"), 1));
    REQUIRE(sd203.size() == 13);
    CHECK((sd203[11] & 0x0F) == 2);

    CHECK(http_put(port, "/api/state", R"({"switch": "RUN"})").json()["state"] == "RUN");
    expect_error(http_put(port, "/api/state", R"({"switch": "PAUSE"})"), 400, "\"switch\" must be \"RUN\" or \"STOP\"");
    expect_error(http_put(port, "/api/state", R"({"state": "STOP"})"), 400,
                 "unknown key \"state\" in the body; use \"switch\", \"error\" or \"reset\" (remote RUN/STOP/PAUSE/RESET are "
                 "SLMP commands 1001/1002/1003/1006)");
    const std::string example = "{\"switch\": \"STOP\"}, {\"error\": {\"code\": \"3100\", \"stop\": true}} or {\"reset\": true}";
    expect_error(http_put(port, "/api/state", "STOP"), 400, "the body must be a JSON object such as " + example);
    expect_error(http_put(port, "/api/state", "{}"), 400, "the body must be a JSON object such as " + example);

    // A CPU error, as a scenario's "error" action raises it; then the RESET switch clears it.
    const std::string bad_error = "\"error\" must be like {\"code\": \"3100\", \"stop\": true} (4 hex digits; stop true: a "
                                  "stop error, false: a continuation error)";
    for (const char* body : {R"({"error": {"code": "31"}})", R"({"error": {"code": 3100}})", R"({"error": {"code": "31G0"}})",
                             R"({"error": {"code": "3100", "stop": 1}})", R"({"error": {"code": "3100", "x": true}})"})
        expect_error(http_put(port, "/api/state", body), 400, bad_error);
    expect_error(http_put(port, "/api/state", R"({"reset": false})"), 400, "\"reset\": true is the only value");
    auto raised = http_put(port, "/api/state", R"({"error": {"code": "3100", "stop": true}})");
    CHECK(raised.status == 200);
    CHECK(raised.json() == json{{"state", "STOP"}, {"switch", "RUN"}, {"cause", "error"}, {"remote_hold", nullptr},
                                {"error", {{"code", "3100"}, {"stop", true}}}});
    auto sd0 = link.exchange(client::read_words(w.options(), addr("SD0"), 1));
    REQUIRE(sd0.size() == 13);
    CHECK(sd0[11] == 0x00);
    CHECK(sd0[12] == 0x31);
    // RESET: the CPU restarts (the error is gone, RUN from the switch) and the SLMP connection closes.
    auto reset = http_put(port, "/api/state", R"({"reset": true})");
    CHECK(reset.status == 200);
    CHECK(reset.json() == json{{"state", "RUN"}, {"switch", "RUN"}, {"cause", nullptr}, {"remote_hold", nullptr}, {"error", nullptr}});
    CHECK(link.client().wait_closed(std::chrono::seconds(10)));
}
