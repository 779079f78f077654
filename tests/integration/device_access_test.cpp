// Issue 3 against the real binary: a configuration with a module (Q62DA at
// start I/O 0030), a network (No.1) and a second CPU; over TCP and UDP, binary
// and ASCII, 3E and 4E: Read/Write Random, Read/Write Block and Entry/Execute
// Monitor round trips; 0601 and U3\G reach the same module memory; 0613 and
// U3E0\G the same CPU buffer memory; module I/O 03E1 reaches CPU No.2.
// Requests are built with the client library; expected responses are spelled
// out by hand (frames.hpp).
#include <catch2/catch.hpp>
#include <vector>

#include "frames.hpp"
#include "link.hpp"
#include "sim_process.hpp"
#include "sockets.hpp"

using namespace slmp::test;
namespace client = slmp::protocol::client;
using slmp::protocol::DeviceExtension;
using slmp::protocol::DeviceForm;
using slmp::protocol::FieldWriter;

namespace {

const char* kPlant = R"({
  "profile": "R08CPU",
  "modules": [{"start_io": "0030", "model": "Q62DA", "buffer_words": 4096, "head_address": "1008"}],
  "networks": [{"number": 1, "device_sizes": {"W": 8192}}],
  "cpus": [{"number": 2, "profile": "R08CPU", "devices": {"D0": [2, 22]}}],
  "devices": {"D0": [1, 11]}
})";

const std::vector<Wire> kWires = {
    {FrameKind::E3, Codec::Binary, 0},
    {FrameKind::E3, Codec::Ascii, 0},
    {FrameKind::E4, Codec::Binary, 0x1234},
    {FrameKind::E4, Codec::Ascii, 0xBEEF},
};

// A double word: 4 bytes LE, or 8 hex digits (high word first).
Bytes dword_data(const Wire& w, std::uint32_t v) {
    if (w.codec == Codec::Binary)
        return {std::uint8_t(v), std::uint8_t(v >> 8), std::uint8_t(v >> 16), std::uint8_t(v >> 24)};
    return text(hex_digits(v, 8));
}

DeviceExtension module_u3() {
    DeviceExtension e;
    e.kind = DeviceExtension::Kind::ModuleAccess;
    e.target = 3;
    return e;
}
DeviceExtension cpu_buffer() {
    DeviceExtension e;
    e.kind = DeviceExtension::Kind::CpuBuffer;
    e.target = 0x3E0;
    return e;
}
DeviceExtension network_1() {
    DeviceExtension e;
    e.kind = DeviceExtension::Kind::LinkDirect;
    e.target = 1;
    return e;
}

// Random, block and monitor round trips, and both buffer memories, through one
// link in one wire format. `slot` keeps the formats apart in memory.
void exercise(Link& link, const Wire& w, unsigned slot) {
    INFO(link.name() << ", " << w.name());
    const auto o = w.options();
    const Bytes ok = expected_response(w, {});
    const std::uint32_t base = 1000 + 100 * slot;
    auto d = [&](std::uint32_t offset) { return addr("D" + std::to_string(base + offset)); };
    auto m = addr("M" + std::to_string(base));

    // 1402 words + dwords (iQ-R form), 1402 bits (Q form), then 0403.
    CHECK(show(link.exchange(client::build_request(o, 0x1402, 0x0002, [&](FieldWriter& f) {
              f.u8(1);
              f.u8(1);
              f.device(DeviceForm::IQR, d(0));
              f.u16(0x1995);
              f.device(DeviceForm::IQR, d(2));
              f.u32(0x4C544F4E);
          }))) == show(ok));
    CHECK(show(link.exchange(client::build_request(o, 0x1402, 0x0001, [&](FieldWriter& f) {
              f.u8(2);
              f.device(DeviceForm::Q, m);
              f.u8(1);
              f.device(DeviceForm::Q, addr("M" + std::to_string(base + 15)));
              f.u8(1);
          }))) == show(ok));
    const auto rr = client::build_request(o, 0x0403, 0x0000, [&](FieldWriter& f) {
        f.u8(2);
        f.u8(1);
        f.device(DeviceForm::Q, d(0));
        f.device(DeviceForm::Q, m);
        f.device(DeviceForm::Q, d(2));
    });
    Bytes rr_answer = concat({word_data(w, {0x1995, 0x8001}), dword_data(w, 0x4C544F4E)});
    CHECK(show(link.exchange(rr)) == show(expected_response(w, rr_answer)));

    // 0801 registers the same list; 0802 reads it (per connection; one session per UDP port).
    CHECK(show(link.exchange(client::build_request(o, 0x0801, 0x0000, [&](FieldWriter& f) {
              f.u8(2);
              f.u8(1);
              f.device(DeviceForm::Q, d(0));
              f.device(DeviceForm::Q, m);
              f.device(DeviceForm::Q, d(2));
          }))) == show(ok));
    CHECK(show(link.exchange(client::build_request(o, 0x0802, 0x0000))) == show(expected_response(w, rr_answer)));

    // 1406 word block and bit block (R08CPU: separate requests), then 0406 of both.
    CHECK(show(link.exchange(client::build_request(o, 0x1406, 0x0000, [&](FieldWriter& f) {
              f.u8(1);
              f.u8(0);
              f.device(DeviceForm::Q, d(10));
              f.u16(3);
              f.words(std::vector<std::uint16_t>{0x0A0A, 0x0B0B, 0x0C0C});
          }))) == show(ok));
    CHECK(show(link.exchange(client::build_request(o, 0x1406, 0x0002, [&](FieldWriter& f) {
              f.u8(0);
              f.u8(1);
              f.device(DeviceForm::IQR, addr("B" + hex_digits(0x100 + 0x20 * slot, 3)));
              f.u16(1);
              f.words(std::vector<std::uint16_t>{0x8421});
          }))) == show(ok));
    CHECK(show(link.exchange(client::build_request(o, 0x0406, 0x0000, [&](FieldWriter& f) {
              f.u8(1);
              f.u8(1);
              f.device(DeviceForm::Q, d(10));
              f.u16(3);
              f.device(DeviceForm::Q, addr("B" + hex_digits(0x100 + 0x20 * slot, 3)));
              f.u16(1);
          }))) == show(expected_response(w, word_data(w, {0x0A0A, 0x0B0B, 0x0C0C, 0x8421}))));
    // The same mixed write is refused with C05B by an R08CPU (real-CPU measurements).
    CHECK(show(link.exchange(client::build_request(o, 0x1406, 0x0000, [&](FieldWriter& f) {
              f.u8(1);
              f.u8(1);
              f.device(DeviceForm::Q, d(10));
              f.u16(1);
              f.words(std::vector<std::uint16_t>{1});
              f.device(DeviceForm::Q, m);
              f.u16(1);
              f.words(std::vector<std::uint16_t>{1});
          }))) == show(expected_response(w, error_info(w, 0x1406, 0x0000), 0xC05B)));

    // Module U3: 1601 writes buffer word 20+slot, U3\G reads it; 1401 U3\G writes, 0601 reads.
    const std::uint32_t g = 20 + 2 * slot;
    CHECK(show(link.exchange(client::build_request(o, 0x1601, 0x0000, [&](FieldWriter& f) {
              f.u32(0x1008 + 2 * g);
              f.u16(2);
              f.u16(3);
              f.u8(0xE8);
              f.u8(0x03);
          }))) == show(ok));
    auto g_addr = [](std::uint32_t n) { return addr("G" + std::to_string(n)); };
    CHECK(show(link.exchange(client::build_request(o, 0x0401, 0x0080, [&](FieldWriter& f) {
              f.extended_device(DeviceForm::Q, g_addr(g), module_u3());
              f.u16(1);
          }))) == show(expected_response(w, word_data(w, {0x03E8}))));
    CHECK(show(link.exchange(client::build_request(o, 0x1401, 0x0082, [&](FieldWriter& f) {
              f.extended_device(DeviceForm::IQR, g_addr(g + 1), module_u3());
              f.u16(1);
              f.u16(0xC109);
          }))) == show(ok));
    Bytes bytes_answer = w.codec == Codec::Binary ? Bytes{0xE8, 0x03, 0x09, 0xC1} : text("E80309C1");
    CHECK(show(link.exchange(client::build_request(o, 0x0601, 0x0000, [&](FieldWriter& f) {
              f.u32(0x1008 + 2 * g);
              f.u16(4);
              f.u16(3);
          }))) == show(expected_response(w, bytes_answer)));

    // CPU buffer memory: 1613 writes, U3E0\G reads; U3E0\G writes, 0613 reads.
    const std::uint32_t cg = 0x2680 + 4 * slot;
    CHECK(show(link.exchange(client::build_request(o, 0x1613, 0x0000, [&](FieldWriter& f) {
              f.u32(cg);
              f.u16(2);
              f.words(std::vector<std::uint16_t>{0x2000, 0x2001});
          }))) == show(ok));
    CHECK(show(link.exchange(client::build_request(o, 0x0403, 0x0082, [&](FieldWriter& f) {
              f.u8(0);
              f.u8(1);
              f.extended_device(DeviceForm::IQR, g_addr(cg), cpu_buffer());
          }))) == show(expected_response(w, dword_data(w, 0x20012000))));
    CHECK(show(link.exchange(client::build_request(o, 0x1402, 0x0082, [&](FieldWriter& f) {
              f.u8(1);
              f.u8(0);
              f.extended_device(DeviceForm::IQR, g_addr(cg + 2), cpu_buffer());
              f.u16(0x2002);
          }))) == show(ok));
    CHECK(show(link.exchange(client::build_request(o, 0x0613, 0x0000, [&](FieldWriter& f) {
              f.u32(cg);
              f.u16(3);
          }))) == show(expected_response(w, word_data(w, {0x2000, 0x2001, 0x2002}))));

    // Network 1: J1\W written by 1406/0080, read by 0406/0080; the CPU's own W is untouched.
    auto w_addr = addr("W" + hex_digits(0x100 + slot, 3));
    CHECK(show(link.exchange(client::build_request(o, 0x1406, 0x0080, [&](FieldWriter& f) {
              f.u8(1);
              f.u8(0);
              f.extended_device(DeviceForm::Q, w_addr, network_1());
              f.u16(1);
              f.u16(0x0101);
          }))) == show(ok));
    CHECK(show(link.exchange(client::build_request(o, 0x0406, 0x0080, [&](FieldWriter& f) {
              f.u8(1);
              f.u8(0);
              f.extended_device(DeviceForm::Q, w_addr, network_1());
              f.u16(1);
          }))) == show(expected_response(w, word_data(w, {0x0101}))));
    CHECK(show(link.exchange(client::read_words(o, w_addr, 1))) == show(expected_response(w, word_data(w, {0x0000}))));
}

// CPU No.2 through module I/O 03E1: its own D0 (configured 2, 22); 0801 refused.
void second_cpu(Link& link, const Wire& w) {
    INFO(link.name() << ", " << w.name());
    auto o = w.options();
    o.route.module_io = 0x03E1;
    auto reply = link.exchange(client::read_words(o, addr("D0"), 2));
    auto parsed = client::parse_response(reply);
    REQUIRE(parsed);
    CHECK(parsed->header.route.module_io == 0x03E1);
    CHECK(parsed->end_code == 0x0000);
    CHECK(show(parsed->data) == show(word_data(w, {2, 22})));
    CHECK(show(link.exchange(client::read_words(w.options(), addr("D0"), 2))) ==
          show(expected_response(w, word_data(w, {1, 11}))));
    auto monitor = client::parse_response(link.exchange(client::build_request(o, 0x0801, 0x0000, [&](FieldWriter& f) {
        f.u8(1);
        f.u8(0);
        f.device(DeviceForm::Q, addr("D0"));
    })));
    REQUIRE(monitor);
    CHECK(monitor->end_code == 0xC059);
    // CPU No.3 is not configured.
    o.route.module_io = 0x03E2;
    auto none = client::parse_response(link.exchange(client::read_words(o, addr("D0"), 1)));
    REQUIRE(none);
    CHECK(none->end_code == 0x4B02);
}

SimOptions plant() {
    SimOptions options;
    options.config_json = kPlant;
    return options;
}

void exercise_all(Link& link) {
    for (unsigned i = 0; i < kWires.size(); ++i) exercise(link, kWires[i], i);
    for (const auto& w : kWires) second_cpu(link, w);
}

}  // namespace

TEST_CASE("Random, block, monitor and buffer memory round trips over TCP", "[device_access][tcp]") {
    SimProcess sim(plant());
    TcpLink link(sim.tcp_port());
    exercise_all(link);
}

TEST_CASE("Random, block, monitor and buffer memory round trips over UDP", "[device_access][udp]") {
    SimProcess sim(plant());
    UdpLink link(sim.udp_port());
    exercise_all(link);
}

TEST_CASE("The manual's 0601 and U1 vectors answer byte for byte from the configured module",
          "[device_access][vectors]") {
    SimProcess sim(plant());
    TcpLink link(sim.tcp_port());
    const Wire b3{FrameKind::E3, Codec::Binary, 0};
    const Wire a3{FrameKind::E3, Codec::Ascii, 0};
    // Q62DA buffer memory 1H = 0001H, 2H = 0012H written with 1601 (binary), read with the manual's 0601.
    CHECK(show(link.exchange(request_frame(b3, hex("10 00 01 16 00 00 0A 10 00 00 04 00 03 00 01 00 12 00")))) ==
          show(hex("D0 00 00 FF FF 03 00 02 00 00 00")));
    CHECK(show(link.exchange(request_frame(a3, text("0010"
                                                    "0601"
                                                    "0000"
                                                    "0000100A"
                                                    "0004"
                                                    "0003")))) == show(text("D00000FF03FF00000C000001001200")));
    CHECK(show(link.exchange(request_frame(b3, hex("10 00 01 06 00 00 0A 10 00 00 04 00 03 00")))) ==
          show(hex("D0 00 00 FF FF 03 00 06 00 00 00 01 00 12 00")));
    // §7.3 U1 through 0401/0080: U3\G1 = 0001H.
    CHECK(show(link.exchange(request_frame(a3, text("0010"
                                                    "0401"
                                                    "0080"
                                                    "00"
                                                    "U003"
                                                    "000"
                                                    "G*"
                                                    "000001"
                                                    "000"
                                                    "0001")))) == show(text("D00000FF03FF00000800000001")));
}
