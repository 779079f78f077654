// The Ladder Motion host link against the real binary over TCP
// (docs/hostlink.md): a "kind": "ladder-motion" station, round trips in every
// area (checked through the HTTP API on the mapped devices too), error codes,
// silence, split and coalesced segments, garbage before a record, STX/ETX;
// a MELSEC station that serves SLMP and Host Link on one memory; --serial.
#include <catch2/catch.hpp>

#include <fcntl.h>
#include <poll.h>
#include <termios.h>
#include <unistd.h>

#include <string>

#include "frames.hpp"
#include "http_client.hpp"
#include "sim_process.hpp"
#include "sockets.hpp"

using namespace slmp::test;

namespace {

// XOR of the bytes, two uppercase hex digits (Ladder Motion host-link manual, docs/hostlink.md).
std::string fcs(const std::string& body) {
    unsigned x = 0;
    for (unsigned char c : body) x ^= c;
    static constexpr char digits[] = "0123456789ABCDEF";
    return {digits[x >> 4], digits[x & 0xF]};
}
std::string record(const std::string& body) { return body + fcs(body) + "*\r"; }

SimOptions ladder_motion(const std::string& extra = "") {
    SimOptions options;
    options.tcp_ports = 0;
    options.udp_ports = 0;
    options.config_json = R"({"kind": "ladder-motion", "hostlink": {"tcp_port": 0)" + extra + "}}";
    return options;
}

std::uint16_t hostlink_port(const SimProcess& sim) { return sim.ready().at("hostlink").at(0).get<std::uint16_t>(); }

// Reads one response record (through its CR, and the ETX after it when `wrapped`).
std::string read_record(TcpClient& client, bool wrapped = false) {
    std::string got;
    for (;;) {
        auto cr = got.find('\r');
        if (cr != std::string::npos && (!wrapped || got.size() > cr + 1)) break;
        auto more = client.read_exactly(1);
        if (more.empty()) FAIL("no whole host-link record; got: " << got);
        got.push_back(static_cast<char>(more[0]));
    }
    return got;
}

std::string ask(TcpClient& client, const std::string& request) {
    REQUIRE(client.send(request));
    return read_record(client);
}

}  // namespace

TEST_CASE("host link: round trips in every area over TCP", "[hostlink]") {
    SimProcess sim(ladder_motion());
    REQUIRE(sim.tcp_ports().empty());   // a Ladder Motion station has no SLMP port
    auto client = TcpClient::open(hostlink_port(sim));

    CHECK(ask(client, "@00MM40*\r") == "@00MM001140*\r");
    CHECK(ask(client, "@00WD0100ABCD123452*\r") == "@00WD0053*\r");   // the spec's vector 6 prints FCS 52: a slip
    CHECK(ask(client, record("@00RD01000002")) == record("@00RD00ABCD1234"));
    for (auto [write, read] : {std::pair{"WR", "RR"}, std::pair{"WH", "RH"}, std::pair{"WL", "RL"},
                               std::pair{"WJ", "RJ"}, std::pair{"WC", "RC"}, std::pair{"Wc", "Rc"}}) {
        INFO(write);
        CHECK(ask(client, record(std::string("@00") + write + "00071234FEDC")) == record(std::string("@00") + write + "00"));
        CHECK(ask(client, record(std::string("@00") + read + "00070002")) == record(std::string("@00") + read + "001234FEDC"));
    }
    CHECK(ask(client, "@00WV00001234567849*\r") == "@00WV0041*\r");
    CHECK(ask(client, "@00RV0000000145*\r") == "@00RV00123456784C*\r");
    CHECK(ask(client, record("@00WG0010101")) == record("@00WG00"));
    CHECK(ask(client, record("@00RG00100003")) == record("@00RG00101"));
    for (auto [write, read] : {std::pair{"Wr", "Rr"}, std::pair{"Wh", "Rh"}, std::pair{"Wl", "Rl"}, std::pair{"Wj", "Rj"}}) {
        INFO(write);
        CHECK(ask(client, record(std::string("@00") + write + "0201501")) == record(std::string("@00") + write + "00"));
        CHECK(ask(client, record(std::string("@00") + read + "020140004")) == record(std::string("@00") + read + "000010"));
    }
    CHECK(ask(client, "@00TSHELLO05*\r") == "@00TSHELLO05*\r");
    CHECK(ask(client, "@00R&0003000136*\r") == "@00R&000135*\r");

    // The areas are the station's device memory: DM0100 is D100, VR0 is R0/R1, CIO 7 is M112..M127.
    auto http = sim.http_port();
    CHECK(http_get(http, "/api/devices/D100?count=2").json()["values"] == nlohmann::json({0xABCD, 0x1234}));
    CHECK(http_get(http, "/api/devices/R0?count=2").json()["values"] == nlohmann::json({0x5678, 0x1234}));
    CHECK(http_get(http, "/api/devices/M112?as=words").json()["values"] == nlohmann::json({0x1234}));
    CHECK(http_get(http, "/api/devices/TS10?count=3").json()["values"] == nlohmann::json({1, 0, 1}));
    // And an HTTP write is read by the host link.
    REQUIRE(http_put(http, "/api/devices/D6655", R"({"values": [4660]})").status == 200);
    CHECK(ask(client, record("@00RD66550001")) == record("@00RD001234"));
}

TEST_CASE("host link: error codes, unknown commands and silence over TCP", "[hostlink]") {
    SimProcess sim(ladder_motion());
    auto client = TcpClient::open(hostlink_port(sim));
    CHECK(ask(client, "@00RD0000000255*\r") == record("@00RD01"));          // bad FCS
    CHECK(ask(client, "@00ZZ40*\r") == "@00IC4A*\r");                       // unknown command
    CHECK(ask(client, record("@00RD66560001")) == record("@00RD01"));       // past DM6655
    CHECK(ask(client, record("@00WD66551234ABCD")) == record("@00WD01"));   // runs past: nothing written
    CHECK(ask(client, record("@00RD66550001")) == record("@00RD000000"));
    CHECK(ask(client, record("@00RD00000031")) == record("@00RD01"));       // > 132 bytes of answer
    CHECK(ask(client, record("@00TS" + std::string(124, 'X'))) == record("@00TS01"));   // a 133-byte record
    CHECK(ask(client, "@00SC0252*\r") == "@00SC0151*\r");                   // refused OMRON command
    // XZ, `**` and another station's record get no answer: the next answer is MM's.
    REQUIRE(client.send("@00XZ42*\r"));
    REQUIRE(client.send(record("@00**")));
    REQUIRE(client.send(record("@01MM")));
    CHECK(ask(client, "@00MM40*\r") == "@00MM001140*\r");
}

TEST_CASE("host link: split, coalesced, garbage-prefixed and STX/ETX records", "[hostlink]") {
    SimProcess sim(ladder_motion());
    auto client = TcpClient::open(hostlink_port(sim));
    // One record in three segments.
    REQUIRE(client.send("@00WD01"));
    REQUIRE(client.send("00ABCD12"));
    CHECK(ask(client, "3452*\r") == "@00WD0053*\r");
    // Three records in one segment: three answers, in order.
    REQUIRE(client.send("@00MM40*\r" + record("@00RD01000001") + "@00ZZ40*\r"));
    CHECK(read_record(client) == "@00MM001140*\r");
    CHECK(read_record(client) == record("@00RD00ABCD"));
    CHECK(read_record(client) == "@00IC4A*\r");
    // Garbage, then a valid record.
    CHECK(ask(client, "\x7F\xFFjunk\r\n@00MM40*\r") == "@00MM001140*\r");
    // STX … ETX: the answer comes back wrapped.
    REQUIRE(client.send("\x02@00MM40*\r\x03"));
    CHECK(read_record(client, true) == "\x02@00MM001140*\r\x03");
}

TEST_CASE("host link: QQMR/QQIR lists belong to their connection", "[hostlink]") {
    SimProcess sim(ladder_motion());
    auto first = TcpClient::open(hostlink_port(sim));
    auto second = TcpClient::open(hostlink_port(sim));
    CHECK(ask(first, record("@00WD01001234")) == record("@00WD00"));
    CHECK(ask(first, record("@00Wr001051")) == record("@00Wr00"));
    CHECK(ask(first, "@00QQMRDM  0100CH,CIO 00010511*\r") == "@00QQMR005F*\r");
    CHECK(ask(first, "@00QQIR5B*\r") == "@00QQIR001234,142*\r");
    CHECK(ask(second, "@00QQIR5B*\r") == record("@00QQIR01"));
}

TEST_CASE("host link and SLMP on one MELSEC station: a write through one is read through the other", "[hostlink]") {
    SimOptions options;
    options.udp_ports = 0;
    options.args = {"--hostlink-port", "0"};
    SimProcess sim(options);
    auto slmp = TcpClient::open(sim.tcp_port());
    auto link = TcpClient::open(hostlink_port(sim));
    // SLMP 1401 (3E binary): D100 = 0x1234.
    REQUIRE(slmp.send(hex("500000FFFF03000E00100001140000640000A801003412")));
    CHECK(slmp.read_exactly(11) == hex("D00000FFFF030002000000"));
    CHECK(ask(link, record("@00RD01000001")) == record("@00RD001234"));
    // Host link WD0200 = 0xBEEF; SLMP 0401 reads D200 low byte first.
    CHECK(ask(link, record("@00WD0200BEEF")) == record("@00WD00"));
    REQUIRE(slmp.send(hex("500000FFFF03000C00100001040000C80000A80100")));
    CHECK(slmp.read_exactly(13) == hex("D00000FFFF030004000000EFBE"));
}

TEST_CASE("host link configuration errors name the key and the fix", "[hostlink]") {
    TempDir dir;
    auto check = [&](const std::string& json) {
        auto file = dir.write("config.json", json);
        return run_sim({"--check-config", file.string()});
    };
    auto kind = check(R"({"kind": "omron"})");
    CHECK(kind.exit_code == 2);
    CHECK_THAT(kind.err, Catch::Contains("/kind") && Catch::Contains("ladder-motion"));
    auto ports = check(R"({"kind": "ladder-motion", "ports": [{"transport": "tcp", "port": 5000}]})");
    CHECK(ports.exit_code == 2);
    CHECK_THAT(ports.err, Catch::Contains("/ports") && Catch::Contains("hostlink"));
    auto area = check(R"({"kind": "ladder-motion", "hostlink": {"areas": {"DX": {"size": 5}}}})");
    CHECK_THAT(area.err, Catch::Contains("/hostlink/areas/DX") && Catch::Contains("CIO, HR"));
    auto size = check(R"({"kind": "ladder-motion", "hostlink": {"areas": {"DM": {"device": "D5000", "size": 6000}}}})");
    CHECK(size.exit_code == 2);
    CHECK_THAT(size.err, Catch::Contains("areas/DM") && Catch::Contains("device_sizes"));
    auto good = check(R"({"kind": "ladder-motion", "hostlink": {"tcp_port": 9600, "refused_code": "15"}})");
    CHECK(good.exit_code == 0);
}

TEST_CASE("host link on a pseudo-terminal (--serial)", "[hostlink]") {
    TempDir dir;
    auto path = dir.path() / "ttyLM0";
    auto options = ladder_motion();
    options.args = {"--serial", path.string()};
    SimProcess sim(options);
    CHECK(sim.ready().at("serial").get<std::string>().rfind("/dev/pts/", 0) == 0);
    int fd = ::open(path.c_str(), O_RDWR | O_NOCTTY);
    REQUIRE(fd >= 0);
    termios raw{};
    ::tcgetattr(fd, &raw);
    ::cfmakeraw(&raw);
    ::tcsetattr(fd, TCSANOW, &raw);
    std::string request = "@00MM40*\r@00WD0100ABCD123452*\r";
    REQUIRE(::write(fd, request.data(), request.size()) == static_cast<ssize_t>(request.size()));
    std::string got;
    auto deadline = std::chrono::steady_clock::now() + kReplyTimeout;
    while (got.size() < 22 && std::chrono::steady_clock::now() < deadline) {
        pollfd p{fd, POLLIN, 0};
        if (::poll(&p, 1, remaining_ms(deadline)) <= 0) break;
        char buffer[256];
        auto n = ::read(fd, buffer, sizeof buffer);
        if (n <= 0) break;
        got.append(buffer, static_cast<std::size_t>(n));
    }
    ::close(fd);
    CHECK(got == "@00MM001140*\r@00WD0053*\r");
    CHECK(http_get(sim.http_port(), "/api/devices/D100").json()["values"] == nlohmann::json({0xABCD}));
}

TEST_CASE("host link: a record left unfinished closes the connection after the partial-frame timeout", "[hostlink]") {
    SimProcess sim(ladder_motion(R"(, "partial_frame_timeout_ms": 300)"));
    auto client = TcpClient::open(hostlink_port(sim));
    CHECK(ask(client, "@00MM40*\r") == "@00MM001140*\r");   // whole records keep it open
    REQUIRE(client.send("@00MM"));
    CHECK(client.wait_closed(std::chrono::seconds(10)));
    // The port still serves new clients.
    auto again = TcpClient::open(hostlink_port(sim));
    CHECK(ask(again, "@00MM40*\r") == "@00MM001140*\r");
}
