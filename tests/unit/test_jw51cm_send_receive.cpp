// The JW-51CM's SEND/RECEIVE, data-memory start method (docs/jw51cm.md), fed
// through the face: the control block in data memory, the END that reads it,
// the exact computer-link commands the unit sends its partner (34 for SEND,
// 24 for RECEIVE), the answers it takes, FLAGS, the status flag bit of its
// TCP connection, the timer — all against a station stand-in whose clock and
// connections the test drives.
#include <catch2/catch.hpp>

#include <functional>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "config/config.hpp"
#include "frontends/jw51cm/computer_link.hpp"
#include "frontends/jw51cm/face.hpp"
#include "frontends/jw51cm/send_receive.hpp"
#include "support/jw51cm_frames.hpp"

namespace {

using namespace slmp;
using Bytes = std::vector<std::uint8_t>;
using test::jw51cm::request;
using test::jw51cm::response;

// What the unit asked of its connection out, for the test to answer.
struct Line {
    protocol::Transport transport = protocol::Transport::Tcp;
    std::string address;
    std::uint16_t port = 0;
    bool destroyed = false;
    bool is_connected = false;
    std::function<void(bool)> opened;
    std::vector<Bytes> sent;
    std::function<std::optional<std::size_t>(std::span<const std::uint8_t>)> whole;
    std::function<void(std::optional<Bytes>)> answer;
};

class FakeOutgoing final : public frontends::Outgoing {
public:
    explicit FakeOutgoing(std::shared_ptr<Line> line) : line_(std::move(line)) {}
    ~FakeOutgoing() override { line_->destroyed = true; }
    void open(std::function<void(bool)> done) override {
        // The fixture's `lines` keep each Line; a shared_ptr here would be a cycle (a leak).
        line_->opened = [line = line_.get(), done = std::move(done)](bool ok) {
            line->is_connected = ok;
            done(ok);
        };
    }
    bool connected() const override { return line_->is_connected; }
    void exchange(Bytes request, std::function<std::optional<std::size_t>(std::span<const std::uint8_t>)> whole,
                  std::function<void(std::optional<Bytes>)> answer) override {
        line_->sent.push_back(std::move(request));
        line_->whole = std::move(whole);
        line_->answer = std::move(answer);
    }

private:
    std::shared_ptr<Line> line_;
};

// The station: timers the test fires, connections it watches.
struct FakeStation final : frontends::StationServices {
    std::vector<std::pair<std::chrono::milliseconds, std::function<void()>>> timers;
    std::vector<std::shared_ptr<Line>> lines;
    std::vector<std::function<bool()>> wanted;
    void after(std::chrono::milliseconds timer, std::function<bool()> still, std::function<void()> then) override {
        timers.emplace_back(timer, std::move(then));
        wanted.push_back(std::move(still));
    }
    std::unique_ptr<frontends::Outgoing> connect(protocol::Transport transport, const std::string& address, std::uint16_t port) override {
        auto line = std::make_shared<Line>();
        line->transport = transport;
        line->address = address;
        line->port = port;
        lines.push_back(line);
        return std::make_unique<FakeOutgoing>(line);
    }
};

constexpr std::uint32_t kBlock = 0x0B00, kFlags = 0x09FE;

struct Fixture {
    devicemodel::Cpu cpu{config::load_profile("R08CPU").cpu};
    frontends::Settings settings = jw51cm::face().defaults();
    std::unique_ptr<frontends::Unit> unit;
    FakeStation station;
    jw51cm::MemoryMap map;

    // `open_method`: 80 TCP_Active or 01 UDP, on connection 1; station 13 (octal) is 127.0.0.1:5000.
    explicit Fixture(std::uint8_t open_method = 0x80) {
        auto& options = *std::static_pointer_cast<jw51cm::Options>(settings.options);
        auto set = [&](std::uint32_t at, Bytes bytes) { std::copy(bytes.begin(), bytes.end(), options.parameters.begin() + at); };
        set(0104, {open_method, 0x00, 0x08, 0x60});
        set(0400, {0x02});
        set(0410, {0x01, 013, 0x88, 0x13, 127, 0, 0, 1});
        set(0420, {0x01, 014, 0x89, 0x13, 127, 0, 0, 2});
        set(03764, {0xFE, 0x09, 0x00, 0x80});
        set(03770, {0x00, 0x0B, 0x00, 0x80});
        REQUIRE(jw51cm::check_send_receive_parameters(options.parameters, map, true).empty());
        unit = jw51cm::face().make_unit(cpu, settings);
        unit->attach(station);
        unit->power_on();
    }
    jw51cm::ByteAccess memory() { return jw51cm::ByteAccess(cpu.memory(), map); }
    std::uint8_t byte(std::uint32_t at) { return memory().byte(0, at); }
    void put(std::uint32_t at, const Bytes& bytes) {
        auto m = memory();
        for (std::size_t i = 0; i < bytes.size(); ++i) m.set_byte(0, at + static_cast<std::uint32_t>(i), bytes[i]);
    }
    // The block: TIMER, G/TYPE with the start bit, ST1 13, n, ADR_A, ADR_B (files 0).
    void start(std::uint8_t timer, std::uint8_t type, std::uint16_t n, std::uint16_t own, std::uint16_t theirs, std::uint8_t st = 013) {
        put(kBlock, {0x00, timer, static_cast<std::uint8_t>(0x80 | type), st, 0, 0, static_cast<std::uint8_t>(n & 0xFF),
                     static_cast<std::uint8_t>(n >> 8), static_cast<std::uint8_t>(own & 0xFF), static_cast<std::uint8_t>(own >> 8), 0, 0,
                     static_cast<std::uint8_t>(theirs & 0xFF), static_cast<std::uint8_t>(theirs >> 8), 0, 0});
        unit->end_of_scan();
    }
    std::uint8_t flags() { return byte(kBlock); }
};

}  // namespace

TEST_CASE("JW-51CM SEND/RECEIVE over TCP: open, the commands sent, the answers taken, close", "[jw51cm][jw51cm-send-receive]") {
    Fixture f;
    CHECK(f.byte(kFlags) == 0x80);   // the UDP port; connection 1 (TCP_Active) not open
    f.unit->end_of_scan();           // no start bit: nothing
    CHECK(f.station.lines.empty());
    f.start(0, 0x00, 0, 0, 0xFFFF);
    CHECK(f.flags() == 0x90);
    CHECK(f.byte(kBlock + 2) == 0x00);   // the start bit taken
    REQUIRE(f.station.lines.size() == 1);
    auto line = f.station.lines[0];
    CHECK(line->transport == protocol::Transport::Tcp);
    CHECK(line->address == "127.0.0.1");
    CHECK(line->port == 5000);
    REQUIRE(f.station.timers.size() == 1);
    CHECK(f.station.timers[0].first == std::chrono::milliseconds(120000));
    line->opened(true);
    CHECK(f.flags() == 0x40);
    CHECK(f.byte(kFlags) == 0x82);

    // The connection goes to station 13: another station's open or SEND is E0 while it is open.
    f.start(0, 0x00, 0, 0, 0xFFFF, 014);
    CHECK(f.flags() == 0xE0);
    f.start(0, 0x00, 4, 0x0800, 0x0840, 014);
    CHECK(f.flags() == 0xE0);
    CHECK(f.station.lines.size() == 1);
    CHECK(line->sent.empty());
    // SEND 4 bytes from 0x0800 to the partner's 0x0840: 34 00 40 08 04 00 and the data.
    f.put(0x0800, {0x11, 0x22, 0x33, 0x44});
    f.start(0, 0x00, 4, 0x0800, 0x0840);
    REQUIRE(line->sent.size() == 1);
    CHECK(line->sent[0] == request({0x34, 0x00, 0x40, 0x08, 0x04, 0x00, 0x11, 0x22, 0x33, 0x44}));
    auto answer = response({0x34, 0x00, 0x00, 0x40, 0x08, 0x04, 0x00});
    CHECK(line->whole(std::span(answer).first(43)) == std::nullopt);   // no RSLT yet
    CHECK(line->whole(std::span(answer).first(44)) == answer.size());   // RSLT 00: the echo follows
    line->answer(answer);
    CHECK(f.flags() == 0x40);
    // A start bit set while the unit is busy waits for the transfer's end.
    f.start(0, 0x02, 4, 0x0810, 0x0850);
    REQUIRE(line->sent.size() == 2);
    CHECK(line->sent[1] == request({0x24, 0x00, 0x50, 0x08, 0x04, 0x00}));
    f.put(kBlock + 2, {0x82});
    f.unit->end_of_scan();
    CHECK(line->sent.size() == 2);
    CHECK(f.flags() == 0x90);
    auto data = response({0x24, 0x00, 0x00, 0x50, 0x08, 0x04, 0x00, 0xA1, 0xA2, 0xA3, 0xA4});
    CHECK(line->whole(std::span(data).first(49)) == data.size());
    line->answer(data);
    CHECK(f.flags() == 0x40);
    CHECK(f.byte(0x0810) == 0xA1);
    CHECK(f.byte(0x0813) == 0xA4);
    f.unit->end_of_scan();   // the waiting start bit: the same RECEIVE again
    CHECK(line->sent.size() == 3);
    // The partner's error answer (RSLT 10): E0, nothing written.
    f.put(0x0810, {0x00});
    auto refusal = response({0x24, 0x10});
    CHECK(line->whole(refusal) == refusal.size());
    line->answer(refusal);
    CHECK(f.flags() == 0xE0);
    CHECK(f.byte(0x0810) == 0x00);
    // A late answer to an ended transfer does nothing.
    line->answer(data);
    CHECK(f.byte(0x0810) == 0x00);

    // The partner closes the idle connection: at the next END the bit goes, and a SEND is E0.
    line->is_connected = false;
    f.unit->end_of_scan();
    CHECK(line->destroyed);
    CHECK(f.byte(kFlags) == 0x80);
    f.start(0, 0x00, 4, 0x0800, 0x0840);
    CHECK(f.flags() == 0xE0);
    f.start(0, 0x00, 0, 0, 0xFFFF);   // opened again
    line = f.station.lines.at(1);
    line->opened(true);
    CHECK(f.flags() == 0x40);
    CHECK(f.byte(kFlags) == 0x82);

    // Close: the connection goes, the bit too; a SEND then is E0 without a connection.
    f.start(0, 0x00, 0, 0, 0xFFFE);
    CHECK(f.flags() == 0x40);
    CHECK(line->destroyed);
    CHECK(f.byte(kFlags) == 0x80);
    f.start(0, 0x00, 4, 0x0800, 0x0840);
    CHECK(f.flags() == 0xE0);
    CHECK(f.station.lines.size() == 2);
}

TEST_CASE("JW-51CM SEND/RECEIVE: the timer on the station's clock, errors before sending", "[jw51cm][jw51cm-send-receive]") {
    Fixture f;
    // The open never connects (refused): FLAGS 90 until the timer (TIMER 20 = 2 s) runs out, then 60.
    f.start(20, 0x00, 0, 0, 0xFFFF);
    auto line = f.station.lines.at(0);
    line->opened(false);
    CHECK(f.flags() == 0x90);
    REQUIRE(f.station.timers.size() == 1);
    CHECK(f.station.timers[0].first == std::chrono::milliseconds(2000));
    f.station.timers[0].second();
    CHECK(f.flags() == 0x60);
    CHECK(f.byte(kFlags) == 0x80);
    // A timer of an ended transfer does nothing.
    f.start(0, 0x00, 0, 0, 0xFFFF);
    f.station.lines.at(1)->opened(true);
    CHECK(f.flags() == 0x40);
    CHECK_FALSE(f.station.wanted[1]());   // the station may stop waiting for it
    f.station.timers[1].second();
    CHECK(f.flags() == 0x40);
    CHECK(f.byte(kFlags) == 0x82);
    // A transfer that times out closes the connection: a late answer cannot pass for the next one's.
    f.start(0, 0x00, 4, 0x0800, 0x0840);
    CHECK(f.station.wanted[2]());
    f.station.timers[2].second();
    CHECK(f.flags() == 0x60);
    CHECK(f.station.lines[1]->destroyed);
    CHECK(f.byte(kFlags) == 0x80);

    // Errors before anything is sent: E0.
    f.start(0, 0x01, 4, 0x0800, 0x0840);   // TYPE 01
    CHECK(f.flags() == 0xE0);
    f.start(0, 0x00, 4, 0x0800, 0x0840, 015);   // no table entry for station 15
    CHECK(f.flags() == 0xE0);
    f.start(0, 0x00, 0x401, 0x0800, 0x0840);   // n above 0x400
    CHECK(f.flags() == 0xE0);
    f.start(0, 0x00, 4, 0x1FFE, 0x0840);   // own range past file 0
    CHECK(f.flags() == 0xE0);
    CHECK(f.station.lines.size() == 2);

    // A Remote RESET: the unit forgets the running transfer and its connection.
    f.start(0, 0x00, 0, 0, 0xFFFF);
    CHECK(f.flags() == 0x90);
    f.unit->power_on();
    CHECK(f.flags() == 0x00);
    CHECK(f.station.lines[2]->destroyed);
    f.station.lines[2]->opened(true);   // too late: nothing
    CHECK(f.flags() == 0x00);
}

TEST_CASE("JW-51CM SEND/RECEIVE over UDP: no open, the 1 s timer, long transfers in two commands", "[jw51cm][jw51cm-send-receive]") {
    Fixture f(0x01);
    CHECK(f.byte(kFlags) == 0x82);   // the UDP channel (1) is on from power-on, with the UDP port (7)
    f.start(0, 0x00, 0, 0, 0xFFFF);
    CHECK(f.flags() == 0x40);
    CHECK(f.station.lines.empty());
    Bytes data(1000);
    for (std::size_t i = 0; i < data.size(); ++i) data[i] = static_cast<std::uint8_t>(i);
    f.put(0x1000, data);
    f.start(0, 0x00, 1000, 0x1000, 0x0100);
    auto line = f.station.lines.at(0);
    CHECK(line->transport == protocol::Transport::Udp);
    CHECK(f.station.timers.back().first == std::chrono::milliseconds(1000));
    REQUIRE(line->sent.size() == 1);
    CHECK(line->sent[0].size() == 1024);   // 976 bytes of data: a UDP command is at most 1024 bytes
    CHECK(Bytes(line->sent[0].begin() + 42, line->sent[0].begin() + 48) == Bytes({0x34, 0x00, 0x00, 0x01, 0xD0, 0x03}));
    line->answer(response({0x34, 0x00, 0x00, 0x00, 0x01, 0xD0, 0x03}));
    REQUIRE(line->sent.size() == 2);
    CHECK(Bytes(line->sent[1].begin() + 42, line->sent[1].begin() + 48) == Bytes({0x34, 0x00, 0xD0, 0x04, 0x18, 0x00}));
    CHECK(line->sent[1].back() == static_cast<std::uint8_t>(999));
    CHECK(f.flags() == 0x90);
    line->answer(std::nullopt);   // a receive error: the timer decides
    CHECK(f.flags() == 0x90);
    f.station.timers.back().second();
    CHECK(f.flags() == 0x60);
    CHECK(!line->destroyed);   // UDP keeps its socket
}
