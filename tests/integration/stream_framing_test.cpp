// How the TCP session splits a byte stream into frames: requests split into
// single bytes, several requests in one write, a pipelined 4E burst, garbage
// before a frame. After each scenario a "sentinel" loopback request proves
// that nothing else (a duplicate, an answer to garbage) was sent before it —
// without waiting on a clock.
#include <catch2/catch.hpp>

#include <chrono>
#include <thread>

#include "frames.hpp"
#include "link.hpp"
#include "sim_process.hpp"
#include "sockets.hpp"

using namespace slmp::test;
namespace client = slmp::protocol::client;

namespace {

const Wire kBin3{FrameKind::E3, Codec::Binary, 0};
const Wire kAsc3{FrameKind::E3, Codec::Ascii, 0};

Bytes sentinel_request(const Wire& w) {
    return request_frame(w, w.codec == Codec::Binary ? hex("10 00 19 06 00 00 04 00 53 45 4E 54")
                                                     : text("001006190000" "0004" "SENT"));
}
Bytes sentinel_response(const Wire& w) {
    return expected_response(w, concat({w.codec == Codec::Binary ? hex("04 00") : text("0004"), text("SENT")}));
}

// Reads the next response frame; its bytes, or "" on timeout/EOF.
std::string next(TcpClient& c) {
    Bytes frame;
    std::string why;
    if (!c.response(&frame, kReplyTimeout, &why)) return "<no response: " + why + ">";
    return show(frame);
}

}  // namespace

TEST_CASE("A request sent one byte at a time is answered once, correctly", "[framing][tcp]") {
    SimProcess sim;
    for (const auto& w : {kBin3, kAsc3, Wire{FrameKind::E4, Codec::Binary, 0x7777}}) {
        INFO(w.name());
        auto c = TcpClient::open(sim.tcp_port());
        std::vector<std::uint16_t> values = {0x0A0B, 0x0C0D};
        auto request = client::write_words(w.options(), addr("D300"), values);
        for (auto b : request) {
            REQUIRE(c.send(Bytes{b}));
            std::this_thread::sleep_for(std::chrono::milliseconds(2));
        }
        CHECK(next(c) == show(expected_response(w, {})));
        auto read = client::read_words(w.options(), addr("D300"), 2);
        for (auto b : read) {
            REQUIRE(c.send(Bytes{b}));
            std::this_thread::sleep_for(std::chrono::milliseconds(2));
        }
        CHECK(next(c) == show(expected_response(w, word_data(w, values))));
        REQUIRE(c.send(sentinel_request(w)));
        CHECK(next(c) == show(sentinel_response(w)));
    }
}

TEST_CASE("Three requests in one write get three responses in order", "[framing][tcp]") {
    SimProcess sim;
    for (const auto& w : {kBin3, kAsc3}) {
        INFO(w.name());
        auto c = TcpClient::open(sim.tcp_port());
        std::vector<std::uint16_t> values = {0x1111, 0x2222, 0x3333};
        auto burst = concat({client::write_words(w.options(), addr("D400"), values),
                             client::read_words(w.options(), addr("D401"), 2),
                             client::build_request(w.options(), 0x0101, 0x0000)});
        REQUIRE(c.send(burst));
        CHECK(next(c) == show(expected_response(w, {})));
        CHECK(next(c) == show(expected_response(w, word_data(w, {0x2222, 0x3333}))));
        Bytes type_name;
        REQUIRE(c.response(&type_name));
        CHECK(std::string(type_name.begin(), type_name.end()).find("R08CPU          ") != std::string::npos);
        REQUIRE(c.send(sentinel_request(w)));
        CHECK(next(c) == show(sentinel_response(w)));
    }
}

TEST_CASE("A pipelined burst of 20 4E requests is answered in order with each serial echoed", "[framing][tcp][4e]") {
    SimOptions options;
    options.config_json =
        R"({"devices": {"D0": [100, 101, 102, 103, 104, 105, 106, 107, 108, 109,
                               110, 111, 112, 113, 114, 115, 116, 117, 118, 119]}})";
    SimProcess sim(options);
    // One connection for both bursts: with a second one still closing, the
    // R08CPU's commands-per-connection limit (1 + 32 / 2) would refuse the last 3.
    auto c = TcpClient::open(sim.tcp_port());
    for (auto codec : {Codec::Binary, Codec::Ascii}) {
        Bytes burst;
        std::vector<Wire> wires;
        for (std::uint16_t i = 0; i < 20; ++i) {
            Wire w{FrameKind::E4, codec, static_cast<std::uint16_t>(0xA000 + 0x0101 * i)};
            wires.push_back(w);
            auto r = client::read_words(w.options(), addr("D" + std::to_string(i)), 1);
            burst.insert(burst.end(), r.begin(), r.end());
        }
        REQUIRE(c.send(burst));
        for (std::uint16_t i = 0; i < 20; ++i) {
            INFO((codec == Codec::Binary ? "binary" : "ASCII") << " request " << i);
            CHECK(next(c) == show(expected_response(wires[i], word_data(wires[i], {std::uint16_t(100 + i)}))));
        }
        Wire w4{FrameKind::E4, codec, 0x5A5A};
        REQUIRE(c.send(sentinel_request(w4)));
        CHECK(next(c) == show(sentinel_response(w4)));
    }
}

TEST_CASE("Garbage before a valid frame is skipped and only the frame is answered", "[framing][tcp][garbage][no-proxy]") {
    SimProcess sim;
    auto c = TcpClient::open(sim.tcp_port());
    // Bytes that cannot start a 3E/4E subheader in either code (no 0x50/0x54/'5').
    Bytes garbage = concat({hex("00 01 02 03 FF FE 99 D0 00"), text("hello, plc!\r\n")});
    auto read = client::read_words(kBin3.options(), addr("D0"), 1);
    REQUIRE(c.send(concat({garbage, read})));
    CHECK(next(c) == show(expected_response(kBin3, word_data(kBin3, {0}))));
    REQUIRE(c.send(concat({garbage, sentinel_request(kAsc3)})));
    CHECK(next(c) == show(sentinel_response(kAsc3)));
    // Garbage alone, then later a frame: still one answer, to the frame.
    REQUIRE(c.send(garbage));
    REQUIRE(c.send(sentinel_request(kBin3)));
    CHECK(next(c) == show(sentinel_response(kBin3)));
}

TEST_CASE("A port fixed to one data code skips frames in the other code", "[framing][tcp][data-code]") {
    SECTION("binary port") {
        SimProcess sim(with_args({"--data-code", "binary"}));
        auto c = TcpClient::open(sim.tcp_port());
        REQUIRE(c.send(concat({client::read_words(kAsc3.options(), addr("D0"), 1), sentinel_request(kBin3)})));
        CHECK(next(c) == show(sentinel_response(kBin3)));
    }
    SECTION("ASCII port") {
        SimProcess sim(with_args({"--data-code", "ascii"}));
        auto c = TcpClient::open(sim.tcp_port());
        REQUIRE(c.send(concat({client::read_words(kBin3.options(), addr("D0"), 1), sentinel_request(kAsc3)})));
        CHECK(next(c) == show(sentinel_response(kAsc3)));
        UdpClient u;
        REQUIRE(u.send_to(sim.udp_port(), client::read_words(kBin3.options(), addr("D0"), 1)));
        REQUIRE(u.send_to(sim.udp_port(), sentinel_request(kAsc3)));
        auto reply = u.receive();
        REQUIRE(reply.has_value());
        CHECK(show(*reply) == show(sentinel_response(kAsc3)));
    }
}

// An answer is written at once when the socket takes it (Outbox::send_now); one
// that does not fit waits for the client. A client that sends 3000 960-word
// reads and reads nothing until all are sent receives 5.8 MB of answers — more
// than the server's send buffer (4 MB at most) and its own capped receive buffer
// hold — so some answers meet a full buffer: they must still arrive whole, once
// and in order (each reads from its own start device, so each answer differs).
TEST_CASE("Answers that meet a full send buffer arrive whole and in order once the client reads", "[framing][tcp]") {
    std::vector<std::uint16_t> values(1024);
    std::string devices;
    for (std::size_t i = 0; i < values.size(); ++i) {
        values[i] = static_cast<std::uint16_t>(0x1000 + 7 * i);
        devices += (i ? "," : "") + std::to_string(values[i]);
    }
    SimOptions options = with_args({"--profile", "Q26UDEHCPU"});   // no commands-per-connection limit
    options.config_json = R"({"devices": {"D0": [)" + devices + "]}}";
    SimProcess sim(options);
    auto c = TcpClient::open(sim.tcp_port(), nullptr, 4096);   // a small receive buffer: it fills soon

    constexpr int kRequests = 3000;
    auto start_of = [](int i) { return static_cast<std::size_t>(i % 64); };
    Bytes burst;
    for (int i = 0; i < kRequests; ++i) {
        auto r = client::read_words(kBin3.options(), addr("D" + std::to_string(start_of(i))), 960);
        burst.insert(burst.end(), r.begin(), r.end());
    }
    REQUIRE(c.send(burst));
    for (int i = 0; i < kRequests; ++i) {
        const auto first = values.begin() + static_cast<std::ptrdiff_t>(start_of(i));
        const auto expected =
            show(expected_response(kBin3, word_data(kBin3, std::vector<std::uint16_t>(first, first + 960))));
        const auto got = next(c);
        if (got != expected)
            FAIL("answer " << i << " is not D" << start_of(i) << "-D" << start_of(i) + 959 << ": " << got.substr(0, 80));
    }
    // Nothing else was sent: the next answer is that of the next request.
    REQUIRE(c.send(client::read_words(kBin3.options(), addr("D0"), 1)));
    CHECK(next(c) == show(expected_response(kBin3, word_data(kBin3, {values[0]}))));
}
