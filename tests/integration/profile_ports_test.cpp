// What each kind of port accepts, as seen from a socket
// (real-CPU measurements): 4E silence on QnU/FX5U,
// iQ-R subcommands refused with C059/C061 or a closed connection, the model
// name per profile, range errors.
#include <catch2/catch.hpp>

#include <chrono>

#include "frames.hpp"
#include "link.hpp"
#include "sim_process.hpp"
#include "sockets.hpp"

using namespace slmp::test;
namespace client = slmp::protocol::client;
using slmp::protocol::DeviceForm;
using namespace std::chrono_literals;

namespace {

const Wire kBin3{FrameKind::E3, Codec::Binary, 0};
const Wire kAsc3{FrameKind::E3, Codec::Ascii, 0};

std::string next(TcpClient& c) {
    Bytes frame;
    std::string why;
    if (!c.response(&frame, kReplyTimeout, &why)) return "<no response: " + why + ">";
    return show(frame);
}

Bytes read_d0(const Wire& w, DeviceForm form = DeviceForm::Q) {
    return client::read_words(w.options(), addr("D0"), 1, form);
}
Bytes d0_response(const Wire& w) { return expected_response(w, word_data(w, {0})); }

}  // namespace

TEST_CASE("QnU built-in port: 4E gets no answer, 0101 and iQ-R subcommands get C059", "[profile][qnu][no-proxy]") {
    SimProcess sim(with_args({"--profile", "Q26UDEHCPU"}));
    auto c = TcpClient::open(sim.tcp_port());
    for (const auto& w : {kBin3, kAsc3}) {
        INFO(w.name());
        // A 4E request is ignored; the 3E request behind it is the first thing answered.
        Wire w4{FrameKind::E4, w.codec, 0x0001};
        REQUIRE(c.send(concat({read_d0(w4), read_d0(w)})));
        CHECK(next(c) == show(d0_response(w)));
        REQUIRE(c.send(client::build_request(w.options(), 0x0101, 0x0000)));
        CHECK(next(c) == show(expected_response(w, error_info(w, 0x0101, 0x0000), 0xC059)));
        REQUIRE(c.send(read_d0(w, DeviceForm::IQR)));
        CHECK(next(c) == show(expected_response(w, error_info(w, 0x0401, 0x0002), 0xC059)));
        // Still serving.
        REQUIRE(c.send(read_d0(w)));
        CHECK(next(c) == show(d0_response(w)));
    }
}

TEST_CASE("QJ71E71 port: 4E is answered, iQ-R subcommands get C061", "[profile][qj71e71]") {
    SimProcess sim(with_args({"--profile", "Q06UDVCPU-QJ71E71"}));
    auto c = TcpClient::open(sim.tcp_port());
    Wire w4{FrameKind::E4, Codec::Binary, 0x2468};
    REQUIRE(c.send(read_d0(w4)));
    CHECK(next(c) == show(d0_response(w4)));
    REQUIRE(c.send(read_d0(kBin3, DeviceForm::IQR)));
    CHECK(next(c) == show(expected_response(kBin3, error_info(kBin3, 0x0401, 0x0002), 0xC061)));
    // 0101 names the CPU behind the module.
    REQUIRE(c.send(client::build_request(kBin3.options(), 0x0101, 0x0000)));
    CHECK(next(c) == show(expected_response(kBin3, concat({text("Q06UDVCPU       "), hex("68 03")}))));
}

TEST_CASE("FX5U built-in port: an iQ-R subcommand closes the TCP connection", "[profile][fx5u][no-proxy]") {
    SimProcess sim(with_args({"--profile", "FX5U-32MR"}));
    auto c = TcpClient::open(sim.tcp_port());
    REQUIRE(c.send(read_d0(kBin3)));
    CHECK(next(c) == show(d0_response(kBin3)));
    REQUIRE(c.send(client::build_request(kBin3.options(), 0x0101, 0x0000)));
    CHECK(next(c) == show(expected_response(kBin3, concat({text("FX5U-32MR/DS    "), hex("41 4A")}))));
    REQUIRE(c.send(read_d0(kBin3, DeviceForm::IQR)));
    Bytes unexpected;
    CHECK(c.wait_closed(5s, &unexpected));
    CHECK(show(unexpected) == show(Bytes{}));
    // The port itself keeps serving new connections.
    auto again = TcpClient::open(sim.tcp_port());
    REQUIRE(again.send(read_d0(kAsc3)));
    CHECK(next(again) == show(d0_response(kAsc3)));
}

TEST_CASE("R08CPU device range: start or span past the size answers 4031 and writes nothing", "[profile][iqr][range]") {
    SimOptions options;
    options.config_json = R"({"device_sizes": {"D": 12000}, "devices": {"D11999": [7]}})";
    SimProcess sim(options);
    auto c = TcpClient::open(sim.tcp_port());
    // The configured size overrides the profile's 10240: D11999 is the last one.
    REQUIRE(c.send(client::read_words(kBin3.options(), addr("D11999"), 1)));
    CHECK(next(c) == show(expected_response(kBin3, word_data(kBin3, {7}))));
    REQUIRE(c.send(client::read_words(kBin3.options(), addr("D11999"), 2)));
    CHECK(next(c) == show(expected_response(kBin3, error_info(kBin3, 0x0401, 0x0000), 0x4031)));
    REQUIRE(c.send(client::read_words(kAsc3.options(), addr("D12000"), 1)));
    CHECK(next(c) == show(expected_response(kAsc3, error_info(kAsc3, 0x0401, 0x0000), 0x4031)));
    std::vector<std::uint16_t> values = {1, 2};
    REQUIRE(c.send(client::write_words(kBin3.options(), addr("D11999"), values)));
    CHECK(next(c) == show(expected_response(kBin3, error_info(kBin3, 0x1401, 0x0000), 0x4031)));
    REQUIRE(c.send(client::read_words(kBin3.options(), addr("D11999"), 1)));
    CHECK(next(c) == show(expected_response(kBin3, word_data(kBin3, {7}))));
}
