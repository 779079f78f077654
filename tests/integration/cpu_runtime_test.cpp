// The running CPU against the real binary (issue 4): SD203 follows remote
// RUN/STOP/PAUSE, Remote RESET drops every connection without an answer and
// keeps only latched memory, the remote password locks each connection on its
// own, and device memory survives a restart and a kill -9 through --state-dir.
#include <catch2/catch.hpp>

#include <signal.h>

#include <chrono>
#include <random>
#include <thread>

#include "frames.hpp"
#include "link.hpp"
#include "sim_process.hpp"

using namespace slmp::test;
namespace client = slmp::protocol::client;

namespace {

const Wire kBin{FrameKind::E3, Codec::Binary, 0};
const Wire kAsc{FrameKind::E3, Codec::Ascii, 0};

Bytes remote(const Wire& w, std::uint16_t command, std::uint16_t mode, bool run_fields = false) {
    return client::build_request(w.options(), command, 0x0000, [&](slmp::protocol::FieldWriter& f) {
        f.u16(mode);
        if (run_fields) {
            f.u8(0x00);   // clear mode: none
            f.u8(0x00);
        }
    });
}
Bytes read_words(const Wire& w, const std::string& address, std::uint16_t points) {
    return client::read_words(w.options(), addr(address), points);
}
Bytes write_words(const Wire& w, const std::string& address, const std::vector<std::uint16_t>& values) {
    return client::write_words(w.options(), addr(address), values);
}
Bytes password(const Wire& w, std::uint16_t command, const std::string& text) {
    return client::build_request(w.options(), command, 0x0000, [&](slmp::protocol::FieldWriter& f) {
        f.u16(static_cast<std::uint16_t>(text.size()));
        f.raw(slmp::test::text(text));
    });
}

Bytes ok_words(const Wire& w, std::initializer_list<std::uint16_t> values) {
    return expected_response(w, word_data(w, values));
}
Bytes ok(const Wire& w) { return expected_response(w, {}); }
Bytes refused(const Wire& w, std::uint16_t code, std::uint16_t command, std::uint16_t subcommand = 0) {
    return expected_response(w, error_info(w, command, subcommand), code);
}

std::string ask(TcpLink& link, const Bytes& request) { return show(link.exchange(request)); }

}  // namespace

TEST_CASE("SD203 follows remote STOP, PAUSE and RUN over the wire", "[cpu][runtime][no-proxy]") {
    SimProcess sim;
    for (const auto& w : {kBin, kAsc}) {
        INFO(w.name());
        TcpLink tcp(sim.tcp_port());
        UdpLink udp(sim.udp_port());
        CHECK(ask(tcp, read_words(w, "SD203", 1)) == show(ok_words(w, {0x0000})));
        CHECK(ask(tcp, remote(w, 0x1002, 0x0001)) == show(ok(w)));
        CHECK(show(udp.exchange(read_words(w, "SD203", 1))) == show(ok_words(w, {0x0022})));
        CHECK(ask(tcp, remote(w, 0x1003, 0x0001)) == show(ok(w)));
        CHECK(ask(tcp, read_words(w, "SD203", 1)) == show(ok_words(w, {0x0023})));
        // Another client (UDP) may not RUN without forcing while TCP holds the PAUSE.
        CHECK(show(udp.exchange(remote(w, 0x1001, 0x0001, true))) == show(refused(w, 0x4015, 0x1001)));
        CHECK(show(udp.exchange(remote(w, 0x1001, 0x0003, true))) == show(ok(w)));
        CHECK(ask(tcp, read_words(w, "SD203", 1)) == show(ok_words(w, {0x0000})));
    }
}

TEST_CASE("SD203 with the switch at STOP (--switch STOP)", "[cpu][runtime]") {
    SimProcess sim(with_args({"--switch", "STOP"}));
    TcpLink tcp(sim.tcp_port());
    CHECK(ask(tcp, read_words(kBin, "SD203", 1)) == show(ok_words(kBin, {0x0002})));
    CHECK(ask(tcp, remote(kBin, 0x1001, 0x0001, true)) == show(ok(kBin)));   // completes, stays STOP
    CHECK(ask(tcp, read_words(kBin, "SD203", 1)) == show(ok_words(kBin, {0x0002})));
}

// Clear Error 1617 is refused by an iQ-R CPU's built-in port, as the Chinese
// manual's access table says; SM50 (error reset) clears the continuation error
// at the next END, and the CPU turns SM50 off (docs/cpu-runtime.md).
TEST_CASE("a continuation error: 1617 refused by the built-in port, SM50 clears it at END", "[cpu][runtime][error_clear]") {
    SimOptions options;
    options.config_json = R"({"cpu": {"error": {"code": "1900", "stop": false}}})";
    SimProcess sim(options);
    TcpLink tcp(sim.tcp_port());
    UdpLink udp(sim.udp_port());
    const auto clear_error = [](const Wire& w) { return client::build_request(w.options(), 0x1617, 0x0000, [](auto&) {}); };
    for (const auto& w : {kBin, kAsc}) {
        INFO(w.name());
        CHECK(ask(tcp, clear_error(w)) == show(refused(w, 0xC059, 0x1617)));
        CHECK(show(udp.exchange(clear_error(w))) == show(refused(w, 0xC059, 0x1617)));
        CHECK(ask(tcp, read_words(w, "SD0", 1)) == show(ok_words(w, {0x1900})));
    }
    REQUIRE(ask(tcp, client::write_bits(kBin.options(), addr("SM50"), std::vector<std::uint8_t>{1})) == show(ok(kBin)));
    // The next END resets the error: wait for it (the CPU scans on its own clock).
    const auto deadline = std::chrono::steady_clock::now() + std::chrono::seconds(10);
    while (ask(tcp, read_words(kBin, "SD0", 1)) != show(ok_words(kBin, {0x0000})) && std::chrono::steady_clock::now() < deadline)
        std::this_thread::sleep_for(std::chrono::milliseconds(10));
    CHECK(ask(tcp, read_words(kAsc, "SD0", 1)) == show(ok_words(kAsc, {0x0000})));
    CHECK(ask(tcp, client::read_bits(kBin.options(), addr("SM0"), 2)) == show(expected_response(kBin, Bytes{0x00})));
    CHECK(ask(tcp, client::read_bits(kBin.options(), addr("SM50"), 1)) == show(expected_response(kBin, Bytes{0x00})));
}

TEST_CASE("Remote RESET: no answer, every connection closed, latched memory kept", "[cpu][runtime][reset][no-proxy]") {
    SimOptions options;
    options.config_json = R"({"cpu": {"remote_reset": true, "latch": {"D": [100, 199]}}})";
    SimProcess sim(options);
    TcpLink a(sim.tcp_port());
    TcpLink b(sim.tcp_port());
    REQUIRE(ask(a, write_words(kBin, "D0", {0x1111})) == show(ok(kBin)));
    REQUIRE(ask(a, write_words(kBin, "D100", {0x2222})) == show(ok(kBin)));
    REQUIRE(ask(a, client::write_bits(kBin.options(), addr("L0"), std::vector<std::uint8_t>{1})) == show(ok(kBin)));
    REQUIRE(ask(b, client::write_bits(kBin.options(), addr("M0"), std::vector<std::uint8_t>{1})) == show(ok(kBin)));

    CHECK(ask(a, remote(kBin, 0x1006, 0x0001)) == show(refused(kBin, 0x4013, 0x1006)));   // RUN: refused
    REQUIRE(ask(a, remote(kBin, 0x1002, 0x0001)) == show(ok(kBin)));
    REQUIRE(a.client().send(remote(kBin, 0x1006, 0x0001)));
    Bytes unexpected;
    CHECK(a.client().wait_closed(std::chrono::seconds(10), &unexpected));
    CHECK(show(unexpected) == show(Bytes{}));
    CHECK(b.client().wait_closed(std::chrono::seconds(10), &unexpected));
    CHECK(unexpected.empty());

    auto again = connect_with_retry(sim.tcp_port(), std::chrono::seconds(10));
    REQUIRE(again);
    auto exchange = [&](const Bytes& request) {
        again->send(request);
        Bytes frame;
        again->response(&frame);
        return show(frame);
    };
    CHECK(exchange(read_words(kBin, "SD203", 1)) == show(ok_words(kBin, {0x0000})));   // from the switch: RUN
    CHECK(exchange(read_words(kBin, "D0", 1)) == show(ok_words(kBin, {0x0000})));
    CHECK(exchange(read_words(kBin, "D100", 1)) == show(ok_words(kBin, {0x2222})));
    CHECK(exchange(client::read_bits(kBin.options(), addr("L0"), 1)) == show(expected_response(kBin, hex("10"))));
    CHECK(exchange(client::read_bits(kBin.options(), addr("M0"), 1)) == show(expected_response(kBin, hex("00"))));
}

TEST_CASE("remote password: lock and unlock across two connections", "[cpu][password][no-proxy]") {
    SimOptions options;
    options.config_json = R"({"cpu": {"password": "secret7"}})";
    SimProcess sim(options);
    for (const auto& w : {kBin, kAsc}) {
        INFO(w.name());
        TcpLink a(sim.tcp_port());
        TcpLink b(sim.tcp_port());
        CHECK(ask(a, read_words(w, "D0", 1)) == show(refused(w, 0xC201, 0x0401)));
        CHECK(ask(a, password(w, 0x1630, "secret8")) == show(refused(w, 0xC810, 0x1630)));
        CHECK(ask(a, password(w, 0x1630, "secret7")) == show(ok(w)));
        CHECK(ask(a, read_words(w, "D0", 1)) == show(ok_words(w, {0x0000})));
        CHECK(ask(b, read_words(w, "D0", 1)) == show(refused(w, 0xC201, 0x0401)));
        CHECK(ask(b, password(w, 0x1630, "secret7")) == show(ok(w)));
        CHECK(ask(a, password(w, 0x1631, "secret7")) == show(ok(w)));
        CHECK(ask(a, read_words(w, "D0", 1)) == show(refused(w, 0xC201, 0x0401)));
        CHECK(ask(b, read_words(w, "D0", 1)) == show(ok_words(w, {0x0000})));
    }
    // A new connection starts locked.
    TcpLink c(sim.tcp_port());
    CHECK(ask(c, read_words(kBin, "D0", 1)) == show(refused(kBin, 0xC201, 0x0401)));
}

TEST_CASE("persistence: write, stop, start, read back", "[cpu][persistence]") {
    TempDir state;
    auto args = [&](std::string restore) {
        SimOptions o;
        o.args = {"--state-dir", state.path().string()};
        o.config_json = R"({"restore": ")" + restore + R"(", "cpu": {"latch": {"D": [0, 9]}}})";
        return o;
    };
    {
        SimProcess sim(args("latched"));
        TcpLink link(sim.tcp_port());
        REQUIRE(ask(link, write_words(kBin, "D0", {0xBEEF, 0x0102})) == show(ok(kBin)));
        REQUIRE(ask(link, write_words(kBin, "D500", {0x5555})) == show(ok(kBin)));
        REQUIRE(ask(link, write_words(kBin, "ZR100", {0x7777})) == show(ok(kBin)));
    }   // SIGTERM: a clean shutdown saves
    REQUIRE(std::filesystem::exists(state.path() / "snapshot.bin"));
    {
        SimProcess sim(args("latched"));   // like a power cycle: latched devices only
        TcpLink link(sim.tcp_port());
        CHECK(ask(link, read_words(kBin, "D0", 2)) == show(ok_words(kBin, {0xBEEF, 0x0102})));
        CHECK(ask(link, read_words(kBin, "D500", 1)) == show(ok_words(kBin, {0x0000})));
        CHECK(ask(link, read_words(kBin, "ZR100", 1)) == show(ok_words(kBin, {0x7777})));
        REQUIRE(ask(link, write_words(kBin, "D500", {0x6666})) == show(ok(kBin)));
    }
    {
        SimProcess sim(args("all"));   // everything as it was saved
        TcpLink link(sim.tcp_port());
        CHECK(ask(link, read_words(kBin, "D500", 1)) == show(ok_words(kBin, {0x6666})));
    }
    SECTION("a snapshot of another profile refuses to start, naming the fix") {
        auto result = run_sim({"--profile", "Q26UDEHCPU", "--state-dir", state.path().string(), "--tcp-port", "0",
                               "--udp-port", "0", "--no-http"});
        CHECK(result.exit_code == 2);
        CHECK_THAT(result.err, Catch::Contains("saved by profile R08CPU"));
    }
}

TEST_CASE("persistence: kill -9 during writes leaves a whole snapshot", "[cpu][persistence][crash]") {
    // 20 kills at varied moments during at least 10^4 acknowledged writes, snapshots every 5 ms.
    // Each write sets D0-D99 to one new value in one request, so a whole snapshot holds 100
    // equal words; a torn one would not. The value restored is one that existed: never above
    // the last write sent, and at least the first write of the previous round that a later
    // snapshot saw. The last write of a round is sent but not waited for, so the kill can
    // land while a request is in the server.
    TempDir state;
    SimOptions options;
    options.args = {"--state-dir", state.path().string()};
    options.config_json = R"({"restore": "all", "snapshot_interval_s": 0.005})";
    std::mt19937 random(16);   // fixed seed: the same kill moments every run
    std::uint16_t last_sent = 0;
    std::uint16_t first_of_previous_round = 1;
    int acknowledged = 0;
    for (int round = 0; round < 20; ++round) {
        INFO("round " << round);
        SimProcess sim(options);
        TcpLink link(sim.tcp_port());
        auto frame = link.exchange(read_words(kBin, "D0", 100));
        auto response = client::parse_response(frame);
        REQUIRE(response);
        auto reader = response->reader();
        auto restored = reader.words(100, "D0-D99");
        for (auto v : restored) REQUIRE(v == restored[0]);
        CHECK(restored[0] <= last_sent);
        if (round > 0) CHECK(restored[0] >= first_of_previous_round);
        // Values only grow across rounds. Count only writes made after a snapshot that was
        // taken after this round's first write, so the next round always has something of
        // this round to find (a loaded machine may not snapshot again for a while).
        const auto snapshot = state.path() / "snapshot.bin";
        auto snapshot_time = [&] {
            std::error_code ec;
            return std::filesystem::last_write_time(snapshot, ec);
        };
        auto write_next = [&] {
            ++last_sent;
            REQUIRE(ask(link, write_words(kBin, "D0", std::vector<std::uint16_t>(100, last_sent))) == show(ok(kBin)));
            ++acknowledged;
        };
        write_next();
        first_of_previous_round = last_sent;
        const auto after_first_write = snapshot_time();
        // 500-700 acknowledged writes a round (so 20 rounds make at least 10^4), and more
        // until one comes after a snapshot that saw this round.
        const int writes = std::uniform_int_distribution<int>(500, 700)(random);
        auto deadline = std::chrono::steady_clock::now() + std::chrono::seconds(20);
        int this_round = 1;
        int after_first_snapshot = 0;
        while ((this_round < writes || after_first_snapshot == 0) && std::chrono::steady_clock::now() < deadline) {
            write_next();
            ++this_round;
            if (snapshot_time() != after_first_write) ++after_first_snapshot;
        }
        REQUIRE(after_first_snapshot > 0);
        ++last_sent;
        link.client().send(write_words(kBin, "D0", std::vector<std::uint16_t>(100, last_sent)));   // in flight at the kill
        sim.stop(SIGKILL);
    }
    CHECK(acknowledged >= 10000);
}
