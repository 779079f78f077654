// Batch write (1401) then batch read (0401) against the real server, over TCP
// and UDP, binary and ASCII, 3E and 4E. Expected responses are spelled out
// byte for byte (frames.hpp), and the manual's own vectors are replayed as raw
// bytes (SLMP Reference Manual ch. 4, §5.2).
#include <catch2/catch.hpp>

#include <vector>

#include "frames.hpp"
#include "link.hpp"
#include "sim_process.hpp"
#include "sockets.hpp"

using namespace slmp::test;
namespace client = slmp::protocol::client;
using slmp::protocol::DeviceForm;

namespace {

const std::vector<Wire> kWires = {
    {FrameKind::E3, Codec::Binary, 0},
    {FrameKind::E3, Codec::Ascii, 0},
    {FrameKind::E4, Codec::Binary, 0x1234},
    {FrameKind::E4, Codec::Ascii, 0xBEEF},
};

// Writes and reads D, M (bit and word units), X and Y through one link in one
// wire format. `slot` moves every address so the formats do not share devices.
void exercise_devices(Link& link, const Wire& w, unsigned slot) {
    INFO(link.name() << ", " << w.name());
    const auto opts = w.options();
    const Bytes ok = expected_response(w, {});

    // D: word units on a word device.
    auto d = addr("D" + std::to_string(100 + 10 * slot));
    std::vector<std::uint16_t> dv = {0x1995, 0x1202, 0x1130, 0xFFFF};
    CHECK(show(link.exchange(client::write_words(opts, d, dv))) == show(ok));
    CHECK(show(link.exchange(client::read_words(opts, d, 4))) == show(expected_response(w, word_data(w, dv))));

    // M: bit units, odd count (the binary form pads the last nibble).
    auto m = addr("M" + std::to_string(1000 + 32 * slot));
    std::vector<std::uint8_t> mb = {1, 1, 0, 0, 1, 1, 0, 0, 1};
    CHECK(show(link.exchange(client::write_bits(opts, m, mb))) == show(ok));
    CHECK(show(link.exchange(client::read_bits(opts, m, 9))) == show(expected_response(w, bit_data(w, mb))));
    // The same bits read as one word: bit k is M(start + k).
    CHECK(show(link.exchange(client::read_words(opts, m, 1))) == show(expected_response(w, word_data(w, {0x0133}))));

    // M: word units on a bit device, then bit units read back (bit 0 = lowest device).
    auto mw = addr("M" + std::to_string(2000 + 64 * slot));
    std::vector<std::uint16_t> mwv = {0x2347, 0xAB96};
    CHECK(show(link.exchange(client::write_words(opts, mw, mwv))) == show(ok));
    CHECK(show(link.exchange(client::read_words(opts, mw, 2))) == show(expected_response(w, word_data(w, mwv))));
    std::vector<std::uint8_t> low8 = {1, 1, 1, 0, 0, 0, 1, 0};   // 0x47, least significant bit first
    CHECK(show(link.exchange(client::read_bits(opts, mw, 8))) == show(expected_response(w, bit_data(w, low8))));

    // X: hexadecimal device numbers (X1A0 + 0x20 * slot); bit write, word read.
    auto x = addr("X" + hex_digits(0x1A0 + 0x20 * slot, 3));
    std::vector<std::uint8_t> xb = {1, 0, 1, 1, 0};
    CHECK(show(link.exchange(client::write_bits(opts, x, xb))) == show(ok));
    CHECK(show(link.exchange(client::read_bits(opts, x, 5))) == show(expected_response(w, bit_data(w, xb))));
    CHECK(show(link.exchange(client::read_words(opts, x, 1))) == show(expected_response(w, word_data(w, {0x000D}))));

    // Y: word write, bit read across a hex digit boundary.
    auto y = addr("Y" + hex_digits(0x2F0 + 0x20 * slot, 3));
    CHECK(show(link.exchange(client::write_words(opts, y, std::vector<std::uint16_t>{0xA5C3}))) == show(ok));
    std::vector<std::uint8_t> yb = {1, 1, 0, 0, 0, 0, 1, 1, 1, 0, 1, 0, 0, 1, 0, 1};   // 0xA5C3, LSB first
    CHECK(show(link.exchange(client::read_bits(opts, y, 16))) == show(expected_response(w, bit_data(w, yb))));

    // iQ-R device form (0002/0003) reads what the Q form wrote.
    CHECK(show(link.exchange(client::read_words(opts, d, 4, DeviceForm::IQR))) ==
          show(expected_response(w, word_data(w, dv))));
    CHECK(show(link.exchange(client::read_bits(opts, m, 9, DeviceForm::IQR))) ==
          show(expected_response(w, bit_data(w, mb))));
}

// The manual's vectors, as raw bytes (not built by our encoder).
void replay_manual_vectors(Link& link) {
    const Wire b3{FrameKind::E3, Codec::Binary, 0};
    const Wire a3{FrameKind::E3, Codec::Ascii, 0};
    INFO(link.name());

    // §6.2 W3 (binary) then §3.4 A: write D100..D102 = 1995 1202 1130, read them.
    CHECK(show(link.exchange(hex("50 00 00 FF FF 03 00 12 00 10 00 01 14 00 00 64 00 00 A8 03 00 95 19 02 12 30 11"))) ==
          show(hex("D0 00 00 FF FF 03 00 02 00 00 00")));
    CHECK(show(link.exchange(hex("50 00 00 FF FF 03 00 0C 00 10 00 01 04 00 00 64 00 00 A8 03 00"))) ==
          show(hex("D0 00 00 FF FF 03 00 08 00 00 00 95 19 02 12 30 11")));
    // §3.4 B: the same read in ASCII.
    CHECK(show(link.exchange(text("500000FF03FF000018001004010000D*0001000003"))) ==
          show(text("D00000FF03FF0000100000199512021130")));
    // §3.4 C: 4E binary and ASCII, serial 1234.
    CHECK(show(link.exchange(hex("54 00 34 12 00 00 00 FF FF 03 00 0C 00 10 00 01 04 00 00 64 00 00 A8 03 00"))) ==
          show(hex("D4 00 34 12 00 00 00 FF FF 03 00 08 00 00 00 95 19 02 12 30 11")));
    CHECK(show(link.exchange(text("54001234000000FF03FF000018001004010000D*0001000003"))) ==
          show(text("D4001234000000FF03FF0000100000199512021130")));

    // §6.2 W1 (ASCII) then read M100..M107 in bit units, both codecs.
    CHECK(show(link.exchange(request_frame(a3, text("0010" "1401" "0001" "M*" "000100" "0008" "11001100")))) ==
          show(text("D00000FF03FF0000040000")));
    CHECK(show(link.exchange(request_frame(b3, hex("10 00 01 04 01 00 64 00 00 90 08 00")))) ==
          show(hex("D0 00 00 FF FF 03 00 06 00 00 00 11 00 11 00")));
    CHECK(show(link.exchange(request_frame(a3, text("0010" "0401" "0001" "M*" "000100" "0008")))) ==
          show(text("D00000FF03FF00000C000011001100")));

    // §6.2 W2 (binary) then read M100..M131 in word units, both codecs.
    CHECK(show(link.exchange(request_frame(b3, hex("10 00 01 14 00 00 64 00 00 90 02 00 47 23 96 AB")))) ==
          show(hex("D0 00 00 FF FF 03 00 02 00 00 00")));
    CHECK(show(link.exchange(request_frame(b3, hex("10 00 01 04 00 00 64 00 00 90 02 00")))) ==
          show(hex("D0 00 00 FF FF 03 00 06 00 00 00 47 23 96 AB")));
    CHECK(show(link.exchange(request_frame(a3, text("0010" "0401" "0000" "M*" "000100" "0002")))) ==
          show(text("D00000FF03FF00000C00002347AB96")));

    // iQ-R form in ASCII: 4-character code, 8-digit number ("D***" and "D   " padding).
    CHECK(show(link.exchange(request_frame(a3, text("0010" "0401" "0002" "D***" "00000100" "0002")))) ==
          show(text("D00000FF03FF00000C000019951202")));
    CHECK(show(link.exchange(request_frame(a3, text("0010" "0401" "0002" "D   " "00000101" "0001")))) ==
          show(text("D00000FF03FF00000800001202")));
    // iQ-R form in binary: 4-byte number, 2-byte code.
    CHECK(show(link.exchange(request_frame(b3, hex("10 00 01 04 02 00 65 00 00 00 A8 00 02 00")))) ==
          show(hex("D0 00 00 FF FF 03 00 06 00 00 00 02 12 30 11")));
}

}  // namespace

TEST_CASE("1401 write then 0401 read of D, M, X, Y over TCP in every frame and code", "[device][tcp]") {
    SimProcess sim;
    TcpLink link(sim.tcp_port());
    for (unsigned i = 0; i < kWires.size(); ++i) exercise_devices(link, kWires[i], i);
}

TEST_CASE("1401 write then 0401 read of D, M, X, Y over UDP in every frame and code", "[device][udp]") {
    SimProcess sim;
    UdpLink link(sim.udp_port());
    for (unsigned i = 0; i < kWires.size(); ++i) exercise_devices(link, kWires[i], i);
}

TEST_CASE("The manual's device read/write vectors answer byte for byte over TCP", "[device][tcp][vectors]") {
    SimProcess sim;
    TcpLink link(sim.tcp_port());
    replay_manual_vectors(link);
}

TEST_CASE("The manual's device read/write vectors answer byte for byte over UDP", "[device][udp][vectors]") {
    SimProcess sim;
    UdpLink link(sim.udp_port());
    replay_manual_vectors(link);
}

TEST_CASE("Values written in one code and frame are read back in the other, across TCP and UDP",
          "[device][tcp][udp]") {
    SimProcess sim;
    TcpLink tcp(sim.tcp_port());
    UdpLink udp(sim.udp_port());
    const Wire bin3{FrameKind::E3, Codec::Binary, 0};
    const Wire asc4{FrameKind::E4, Codec::Ascii, 0x00A5};

    std::vector<std::uint16_t> values = {0x0001, 0x8000, 0xCAFE};
    REQUIRE(show(tcp.exchange(client::write_words(bin3.options(), addr("D500"), values))) ==
            show(expected_response(bin3, {})));
    CHECK(show(udp.exchange(client::read_words(asc4.options(), addr("D500"), 3))) ==
          show(expected_response(asc4, word_data(asc4, values))));

    std::vector<std::uint8_t> bits = {0, 1, 1, 0, 1, 0, 0, 1, 1, 1};
    REQUIRE(show(udp.exchange(client::write_bits(asc4.options(), addr("Y7FA"), bits))) ==
            show(expected_response(asc4, {})));
    CHECK(show(tcp.exchange(client::read_bits(bin3.options(), addr("Y7FA"), 10))) ==
          show(expected_response(bin3, bit_data(bin3, bits))));
}

TEST_CASE("Initial device values from the config file's devices key are served", "[device][config]") {
    SimOptions options;
    options.config_json = R"({"devices": {"D100": [1, 2, 3], "M0": [1, 0, 1], "X10": [1, 1, 0, 1]}})";
    SimProcess sim(options);
    TcpLink link(sim.tcp_port());
    const Wire b3{FrameKind::E3, Codec::Binary, 0};
    const Wire a3{FrameKind::E3, Codec::Ascii, 0};
    CHECK(show(link.exchange(client::read_words(b3.options(), addr("D99"), 5))) ==
          show(expected_response(b3, word_data(b3, {0, 1, 2, 3, 0}))));
    CHECK(show(link.exchange(client::read_bits(a3.options(), addr("M0"), 4))) ==
          show(expected_response(a3, bit_data(a3, {1, 0, 1, 0}))));
    CHECK(show(link.exchange(client::read_bits(b3.options(), addr("X10"), 5))) ==
          show(expected_response(b3, bit_data(b3, {1, 1, 0, 1, 0}))));
}

TEST_CASE("A rejected batch write answers the error frame and changes nothing", "[device][tcp][errors]") {
    SimProcess sim;
    TcpLink link(sim.tcp_port());
    const Wire b3{FrameKind::E3, Codec::Binary, 0};
    // 961 words is over the 960-word limit: C051 with the error information.
    std::vector<std::uint16_t> too_many(961, 0x5555);
    CHECK(show(link.exchange(client::write_words(b3.options(), addr("D0"), too_many))) ==
          show(expected_response(b3, error_info(b3, 0x1401, 0x0000), 0xC051)));
    CHECK(show(link.exchange(client::read_words(b3.options(), addr("D0"), 2))) ==
          show(expected_response(b3, word_data(b3, {0, 0}))));
    // An unknown subcommand answers C059 (§3.4 D), ASCII too.
    CHECK(show(link.exchange(hex("50 00 00 FF FF 03 00 0C 00 10 00 01 04 00 01 64 00 00 A8 03 00"))) ==
          show(expected_response(b3, error_info(b3, 0x0401, 0x0100), 0xC059)));
}
