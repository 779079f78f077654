// GET/PUT /api/buffer against the real binary (docs/api.md, "Buffer memory"):
// the API reaches the same stores as SLMP — a module's buffer memory (U3\G,
// Extend Unit 0601/1601), the CPU buffer (U3E0\G, Memory 0613/1613) and CPU
// No.2's (U3E1) — cross-checked over SLMP; and bad input with its exact
// status and message.
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
using slmp::protocol::FieldWriter;

namespace {

const char* kPlant = R"({
  "profile": "R08CPU",
  "modules": [{"start_io": "0030", "model": "Q62DA", "buffer_words": 4096, "head_address": "1008"}],
  "cpus": [{"number": 2, "profile": "R08CPU"}]
})";

const Wire kBinary{FrameKind::E3, Codec::Binary, 0};

SimOptions plant() {
    SimOptions options;
    options.config_json = kPlant;
    return options;
}

void expect_error(const HttpResponse& r, int status, const std::string& message) {
    INFO(r.body);
    CHECK(r.status == status);
    CHECK(r.error() == message);
}

}  // namespace

TEST_CASE("HTTP buffer: a module's buffer memory is the one 0601 and U3¥G reach", "[http][buffer]") {
    SimProcess sim(plant());
    TcpLink link(sim.tcp_port());
    auto r = http_put(sim.http_port(), "/api/buffer/U3/G100", R"({"values": [4660, 65535]})");
    CHECK(r.status == 200);
    CHECK(r.json() == json{{"module", "U3"}, {"device", "G100"}, {"as", "words"}, {"count", 2}, {"values", {4660, 65535}}});
    // 0601: byte address = head address 1008 + word × 2.
    auto o = kBinary.options();
    CHECK(show(link.exchange(client::build_request(o, 0x0601, 0x0000, [&](FieldWriter& f) {
              f.u32(0x1008 + 2 * 100);
              f.u16(4);
              f.u16(3);
          }))) == show(expected_response(kBinary, Bytes{0x34, 0x12, 0xFF, 0xFF})));
    // 1601 writes, the API reads.
    CHECK(show(link.exchange(client::build_request(o, 0x1601, 0x0000, [&](FieldWriter& f) {
              f.u32(0x1008 + 2 * 200);
              f.u16(2);
              f.u16(3);
              f.u8(0x78);
              f.u8(0x56);
          }))) == show(expected_response(kBinary, {})));
    CHECK(http_get(sim.http_port(), "/api/buffer/u03/g200").json()["values"] == json{0x5678});
    // Double words and strings as on /api/devices.
    CHECK(http_put(sim.http_port(), "/api/buffer/U3/G300?as=dwords", R"({"values": [305419896]})").status == 200);
    CHECK(http_get(sim.http_port(), "/api/buffer/U3/G300?count=2").json()["values"] == json{0x5678, 0x1234});
    CHECK(http_put(sim.http_port(), "/api/buffer/U3/G400", R"({"string": "AB"})").json()["string"] == "AB");
}

TEST_CASE("HTTP buffer: U3E0 and station are the CPU buffer of 0613/1613, U3E1 is CPU No.2's", "[http][buffer]") {
    SimProcess sim(plant());
    TcpLink link(sim.tcp_port());
    auto o = kBinary.options();
    CHECK(show(link.exchange(client::build_request(o, 0x1613, 0x0000, [&](FieldWriter& f) {
              f.u32(0x100);
              f.u16(2);
              f.words(std::vector<std::uint16_t>{0x2000, 0x2001});
          }))) == show(expected_response(kBinary, {})));
    CHECK(http_get(sim.http_port(), "/api/buffer/U3E0/G256?count=2").json()["values"] == json{0x2000, 0x2001});
    CHECK(http_get(sim.http_port(), "/api/buffer/station/G256?count=2").json()["values"] == json{0x2000, 0x2001});
    CHECK(http_put(sim.http_port(), "/api/buffer/U3E0/HG5", R"({"values": [7]})").status == 200);
    CHECK(http_get(sim.http_port(), "/api/buffer/U3E0/HG5").json()["values"] == json{7});

    CHECK(http_put(sim.http_port(), "/api/buffer/U3E1/G10", R"({"values": [99]})").status == 200);
    CHECK(http_get(sim.http_port(), "/api/buffer/U3E0/G10").json()["values"] == json{0});
    // 0601 module 03E1: CPU No.2's buffer memory, byte address = word × 2.
    CHECK(show(link.exchange(client::build_request(o, 0x0601, 0x0000, [&](FieldWriter& f) {
              f.u32(2 * 10);
              f.u16(2);
              f.u16(0x03E1);
          }))) == show(expected_response(kBinary, Bytes{99, 0})));

    auto list = http_get(sim.http_port(), "/api/buffer").json()["buffers"];
    REQUIRE(list.size() == 4);
    CHECK(list[0] == json{{"module", "U3"}, {"owner", "module U3 (Q62DA)"}, {"G", 4096}});
    CHECK(list[1]["module"] == "U3E0");
    CHECK(list[2]["module"] == "U3E1");
    CHECK(list[3]["module"] == "station");
}

TEST_CASE("HTTP buffer: bad input gets the exact status and message", "[http][buffer]") {
    SimProcess sim(plant());
    auto port = sim.http_port();
    expect_error(http_get(port, "/api/buffer/U5/G0"), 404,
                 "no buffer memory 'U5'; the configured ones are U3, U3E0, U3E1, station (add an intelligent module "
                 "under \"modules\" in the configuration)");
    expect_error(http_get(port, "/api/buffer/U3/G4095?count=2"), 400,
                 "G4095 with 2 words runs past G4095, the last G device of module U3 (Q62DA) (4096 devices); lower the "
                 "start or count, or raise buffer_words of that module in the configuration's \"modules\"");
    expect_error(http_put(port, "/api/buffer/U3/G4096", R"({"values": [1]})"), 400,
                 "G4096 with 1 words runs past G4095, the last G device of module U3 (Q62DA) (4096 devices); lower the "
                 "start or count, or raise buffer_words of that module in the configuration's \"modules\"");
    expect_error(http_get(port, "/api/buffer/U3/HG0"), 400,
                 "HG is the CPU buffer's fixed-cycle area; U3 has only G (use U3E0 for HG)");
    expect_error(http_get(port, "/api/buffer/U3/D100"), 400, "'D100' is not a buffer memory address; write G100");
    expect_error(http_get(port, "/api/buffer/U3E0/X0"), 400, "'X0' is not a buffer memory address; write G100 or HG100");
    expect_error(http_get(port, "/api/buffer/U3/G0?as=bits"), 400, "as=bits is not a buffer memory view; use words, dwords or string");
    expect_error(http_put(port, "/api/buffer/U3/G0", R"({"values": [1,)"), 400,
                 "the body is not valid JSON; send {\"values\": [1, 2, 3]} or {\"string\": \"text\"}");
    expect_error(http_put(port, "/api/buffer/U3/G0", R"({"values": [70000]})"), 400,
                 "values[0]: 70000 does not fit a 16-bit word; use -32768..65535");
    // A rejected write changes nothing.
    CHECK(http_get(port, "/api/buffer/U3/G0").json()["values"] == json{0});
}
