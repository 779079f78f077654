// TCP connection policies of the real server: idle timeout, connection limit,
// oversized length field. Waits are generous upper bounds only.
#include <catch2/catch.hpp>

#include <cerrno>
#include <chrono>
#include <cstring>
#include <thread>

#include "frames.hpp"
#include "link.hpp"
#include "sim_process.hpp"
#include "sockets.hpp"

using namespace slmp::test;
namespace client = slmp::protocol::client;
using namespace std::chrono_literals;

namespace {

const Wire kBin3{FrameKind::E3, Codec::Binary, 0};

Bytes loopback_request(const std::string& data) {
    Bytes body = hex("10 00 19 06 00 00");
    body.push_back(static_cast<std::uint8_t>(data.size()));
    body.push_back(0);
    body = concat({body, text(data)});
    return request_frame(kBin3, body);
}
Bytes loopback_response(const std::string& data) {
    Bytes count = {static_cast<std::uint8_t>(data.size()), 0};
    return expected_response(kBin3, concat({count, text(data)}));
}

// One loopback round trip on `c`; true when the exact answer came back.
bool serves(TcpClient& c, const std::string& data = "PING") {
    if (!c.send(loopback_request(data))) return false;
    Bytes frame;
    if (!c.response(&frame)) return false;
    return frame == loopback_response(data);
}

// A new connection that is served, retried until `limit` passes (a refused
// connect, or one reset from the backlog or closed by the server, tries again).
std::optional<TcpClient> served_within(std::uint16_t port, std::chrono::milliseconds limit) {
    auto deadline = std::chrono::steady_clock::now() + limit;
    while (std::chrono::steady_clock::now() < deadline) {
        auto c = TcpClient::connect(port);
        if (c && serves(*c)) return c;
        std::this_thread::sleep_for(20ms);
    }
    return std::nullopt;
}

}  // namespace

TEST_CASE("Idle timeout: a silent connection is closed by the server", "[policy][tcp][idle]") {
    SimProcess sim(with_args({"--idle-timeout", "0.3"}));
    auto silent = TcpClient::open(sim.tcp_port());
    auto started = std::chrono::steady_clock::now();
    Bytes unexpected;
    CHECK(silent.wait_closed(5s, &unexpected));
    CHECK(show(unexpected) == show(Bytes{}));
    // Not before the timeout (generous lower margin for timer granularity).
    CHECK(std::chrono::steady_clock::now() - started >= 200ms);

    // A connection that keeps talking is served across several timeout periods' worth of requests
    // as long as each gap is shorter than the timeout, and then closed once it goes silent.
    auto busy = TcpClient::open(sim.tcp_port());
    for (int i = 0; i < 5; ++i) {
        CHECK(serves(busy));
        std::this_thread::sleep_for(50ms);
    }
    CHECK(busy.wait_closed(5s));
}

TEST_CASE("Idle timeout 0 never closes a connection", "[policy][tcp][idle]") {
    SimProcess sim(with_args({"--idle-timeout", "0"}));
    auto c = TcpClient::open(sim.tcp_port());
    // Nothing arrives and the connection is not closed for a while...
    auto got = c.recv_some(700ms);
    CHECK(got.status == RecvStatus::Timeout);
    // ...and it still serves.
    CHECK(serves(c));
}

TEST_CASE("Connection limit: a second client is refused until the first leaves", "[policy][tcp][limit]") {
    SimProcess sim(with_args({"--max-connections", "1"}));
    auto first = TcpClient::open(sim.tcp_port());
    REQUIRE(serves(first));   // the server has accepted it

    int error = 0;
    auto second = TcpClient::connect(sim.tcp_port(), &error);
    CHECK_FALSE(second.has_value());
    CHECK(error == ECONNREFUSED);
    INFO("connect error: " << std::strerror(error));

    // The first client still works while the second is refused.
    CHECK(serves(first, "STILL"));

    first.close();
    auto third = connect_with_retry(sim.tcp_port(), 5s);
    REQUIRE(third.has_value());
    CHECK(serves(*third, "AGAIN"));

    // With the new client in, the port is closed again.
    auto fourth = TcpClient::connect(sim.tcp_port(), &error);
    CHECK_FALSE(fourth.has_value());
    CHECK(error == ECONNREFUSED);
}

TEST_CASE("Connection limit counts per port", "[policy][tcp][limit]") {
    auto options = with_args({"--max-connections", "1"});
    options.tcp_ports = 2;
    SimProcess sim(options);
    REQUIRE(sim.tcp_ports().size() == 2);
    auto a = TcpClient::open(sim.tcp_port(0));
    REQUIRE(serves(a));
    auto b = TcpClient::open(sim.tcp_port(1));
    CHECK(serves(b));
}

TEST_CASE("Connection limit: the profile's connection count is the default (FX5U: 8)", "[policy][tcp][limit][profile]") {
    SimProcess sim(with_args({"--profile", "FX5U-32MR"}));
    std::vector<TcpClient> clients;
    for (int i = 0; i < 8; ++i) {
        clients.push_back(TcpClient::open(sim.tcp_port()));
        REQUIRE(serves(clients.back()));
    }
    int error = 0;
    CHECK_FALSE(TcpClient::connect(sim.tcp_port(), &error).has_value());
    CHECK(error == ECONNREFUSED);
    // A configured port's own max_connections wins over the profile's.
    SimProcess more(with_args({"--profile", "FX5U-32MR", "--max-connections", "9"}));
    std::vector<TcpClient> nine;
    for (int i = 0; i < 9; ++i) {
        nine.push_back(TcpClient::open(more.tcp_port()));
        REQUIRE(serves(nine.back()));
    }
}

TEST_CASE("A length field over the max-request-bytes limit closes the connection and others are still served",
          "[policy][tcp][limits]") {
    SimProcess sim(with_args({"--max-request-bytes", "64"}));
    // Binary 3E header announcing 1000 bytes.
    {
        auto c = TcpClient::open(sim.tcp_port());
        REQUIRE(c.send(hex("50 00 00 FF FF 03 00 E8 03 10 00 01 04 00 00")));
        Bytes unexpected;
        CHECK(c.wait_closed(5s, &unexpected));
        CHECK(show(unexpected) == show(Bytes{}));
    }
    // ASCII 3E header announcing 0xFFFF characters.
    {
        auto c = TcpClient::open(sim.tcp_port());
        REQUIRE(c.send(text("500000FF03FF00FFFF0010")));
        Bytes unexpected;
        CHECK(c.wait_closed(5s, &unexpected));
        CHECK(show(unexpected) == show(Bytes{}));
    }
    // A request within the limit on a new connection is served.
    auto fresh = TcpClient::open(sim.tcp_port());
    CHECK(serves(fresh));
}

TEST_CASE("An oversized length field with the default limit closes the connection", "[policy][tcp][limits]") {
    SimProcess sim;
    auto bystander = TcpClient::open(sim.tcp_port());
    REQUIRE(serves(bystander));
    {
        auto c = TcpClient::open(sim.tcp_port());
        REQUIRE(c.send(hex("54 00 01 00 00 00 00 FF FF 03 00 FF FF")));   // 4E, 65535 bytes
        CHECK(c.wait_closed(5s));
    }
    // Neither the server nor other connections are affected.
    CHECK(serves(bystander, "OTHER"));
    auto fresh = TcpClient::open(sim.tcp_port());
    CHECK(serves(fresh));
}

TEST_CASE("A client that disconnects mid-frame does not disturb the server", "[policy][tcp]") {
    SimProcess sim;
    {
        auto c = TcpClient::open(sim.tcp_port());
        auto request = loopback_request("HALF");
        REQUIRE(c.send(Bytes(request.begin(), request.begin() + 10)));
    }
    auto c = TcpClient::open(sim.tcp_port());
    CHECK(serves(c));
}

// --- Half-frames and many connections from one address (issue 16) -------------

TEST_CASE("Partial-frame timeout: a connection whose frame stays incomplete is closed", "[policy][tcp][partial]") {
    SimProcess sim(with_args({"--partial-frame-timeout", "0.3"}));
    auto bystander = TcpClient::open(sim.tcp_port());
    REQUIRE(serves(bystander));

    auto half = TcpClient::open(sim.tcp_port());
    REQUIRE(half.send(hex("50 00 00 FF")));   // 4 bytes of a 3E header, then nothing
    auto started = std::chrono::steady_clock::now();
    Bytes unexpected;
    CHECK(half.wait_closed(10s, &unexpected));
    CHECK(show(unexpected) == show(Bytes{}));
    CHECK(std::chrono::steady_clock::now() - started >= 200ms);   // not before the timeout (timer granularity)
    // The idle timeout (300 s by default) did not apply: only the started frame did.
    CHECK(serves(bystander, "AFTER"));
}

// While the server waits on its own write to a client that reads slowly it
// reads nothing, so the unfinished frame behind the served ones is not the
// client's doing: the partial-frame timeout must not close the connection.
TEST_CASE("Partial-frame timeout: a client slow to read its answers is not closed for the frame the server did not read",
          "[policy][tcp][partial]") {
    SimOptions options = with_args({"--partial-frame-timeout", "0.3", "--profile", "Q26UDEHCPU"});   // no pipelining limit
    SimProcess sim(options);
    auto c = TcpClient::open(sim.tcp_port(), nullptr, 4096);   // a small receive buffer: it fills soon
    // 3000 960-word reads (5.8 MB of answers): the server's first read ends in
    // the middle of a request (8192 bytes hold 390 whole 21-byte frames).
    constexpr int kRequests = 3000;
    Bytes burst;
    for (int i = 0; i < kRequests; ++i) {
        auto r = client::read_words(kBin3.options(), addr("D0"), 960);
        burst.insert(burst.end(), r.begin(), r.end());
    }
    REQUIRE(c.send(burst));
    std::this_thread::sleep_for(1s);   // reads nothing for more than the timeout: the server's write waits
    const auto answer = show(expected_response(kBin3, word_data(kBin3, std::vector<std::uint16_t>(960, 0))));
    for (int i = 0; i < kRequests; ++i) {
        Bytes frame;
        std::string why;
        if (!c.response(&frame, kReplyTimeout, &why)) FAIL("answer " << i << " missing: " << why);
        if (show(frame) != answer) FAIL("answer " << i << " is not 960 zero words");
    }
}

TEST_CASE("Partial-frame timeout counts from the frame's first byte, so trickling bytes do not extend it",
          "[policy][tcp][partial]") {
    SimProcess sim(with_args({"--partial-frame-timeout", "0.3"}));
    auto c = TcpClient::open(sim.tcp_port());
    // One byte every 200 ms: the whole frame would take over 4 s, while each gap is
    // shorter than the timeout. The server closes before the frame is whole.
    auto request = loopback_request("SLOWLORIS");
    bool closed = false;
    for (auto byte : request) {
        if (!c.send(Bytes{byte})) break;
        auto got = c.recv_some(200ms);
        if (got.status == RecvStatus::Eof || got.status == RecvStatus::Error) {
            closed = true;
            break;
        }
        REQUIRE(got.status == RecvStatus::Timeout);   // no answer to an incomplete frame
    }
    CHECK(closed);
}

TEST_CASE("Partial-frame timeout: whole frames in pieces within the timeout are served, and 0 turns it off",
          "[policy][tcp][partial]") {
    SECTION("pieces within the timeout") {
        SimProcess sim(with_args({"--partial-frame-timeout", "5"}));
        auto c = TcpClient::open(sim.tcp_port());
        auto request = loopback_request("PIECES");
        REQUIRE(c.send(Bytes(request.begin(), request.begin() + 5)));
        REQUIRE(c.send(Bytes(request.begin() + 5, request.end())));
        Bytes frame;
        REQUIRE(c.response(&frame));
        CHECK(show(frame) == show(loopback_response("PIECES")));
    }
    SECTION("0 = never") {
        SimProcess sim(with_args({"--partial-frame-timeout", "0"}));
        auto c = TcpClient::open(sim.tcp_port());
        auto request = loopback_request("LATER");
        REQUIRE(c.send(Bytes(request.begin(), request.begin() + 4)));
        CHECK(c.recv_some(700ms).status == RecvStatus::Timeout);   // still open, nothing answered
        REQUIRE(c.send(Bytes(request.begin() + 4, request.end())));
        Bytes frame;
        REQUIRE(c.response(&frame));
        CHECK(show(frame) == show(loopback_response("LATER")));
    }
}

TEST_CASE("Slowloris: 300 half-frame connections do not keep a well-behaved client out", "[policy][tcp][partial][slowloris]") {
    // The default connection limit (R08CPU: 16, the profile's) and idle timeout (300 s):
    // the half-frames fill every slot, the partial-frame timeout frees them, and the client gets in.
    SimProcess sim(with_args({"--partial-frame-timeout", "1"}));
    std::vector<TcpClient> attackers;
    for (int i = 0; i < 300; ++i) {
        auto c = TcpClient::connect(sim.tcp_port());   // beyond the limit: refused, or reset from the backlog
        if (c && c->send(hex("50 00 00 FF"))) attackers.push_back(std::move(*c));
    }
    INFO(attackers.size() << " half-frame connections were accepted");
    CHECK(attackers.size() >= 16);
    // Well within the idle timeout: only the partial-frame timeout can have freed a slot.
    auto client = served_within(sim.tcp_port(), 60s);
    REQUIRE(client);
    CHECK(serves(*client, "SERVED"));
}

TEST_CASE("Per-address cap: a client address at its limit has new connections closed, others are served",
          "[policy][tcp][per-address]") {
    SimProcess sim(with_args({"--max-connections-per-address", "2"}));
    auto a1 = TcpClient::open(sim.tcp_port());
    auto a2 = TcpClient::open(sim.tcp_port());
    REQUIRE(serves(a1));
    REQUIRE(serves(a2));

    auto a3 = TcpClient::open(sim.tcp_port());   // accepted by the kernel, closed by the server at once
    Bytes unexpected;
    CHECK(a3.wait_closed(5s, &unexpected));
    CHECK(show(unexpected) == show(Bytes{}));

    int error = 0;
    auto b = TcpClient::connect(sim.tcp_port(), &error, "127.0.0.2");   // another address is not limited
    REQUIRE(b);
    CHECK(serves(*b));

    // When one of the address's connections leaves, a new one is served (once the
    // server has seen the close: retried until then).
    a1.close();
    auto again = served_within(sim.tcp_port(), 10s);
    REQUIRE(again);
    CHECK(serves(a2, "STILL"));
}

TEST_CASE("The per-port config keys partial_frame_timeout_ms and max_connections_per_address", "[policy][tcp][config]") {
    SimOptions options;
    options.tcp_ports = 0;
    options.config_json = R"({"ports": [{"transport": "tcp", "port": 0, "partial_frame_timeout_ms": 300,
                                         "max_connections_per_address": 1}]})";
    SimProcess sim(options);
    auto first = TcpClient::open(sim.tcp_port());
    REQUIRE(serves(first));
    auto second = TcpClient::open(sim.tcp_port());
    CHECK(second.wait_closed(5s));   // the address is at its limit of 1

    REQUIRE(first.send(hex("50 00")));   // a frame begun and never finished
    CHECK(first.wait_closed(10s));
}
