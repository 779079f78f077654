// What the JW-51CM writes into data memory on its own (docs/jw51cm.md): the
// command execution completion record after each command (§11, parameters
// 3660–3667) and the connection status flag byte (§12, 3764–3767) — exact
// bytes in the mapped device memory, and the parameters' checks.
#include <catch2/catch.hpp>

#include <memory>
#include <vector>

#include "config/config.hpp"
#include "frontends/jw51cm/computer_link.hpp"
#include "frontends/jw51cm/face.hpp"
#include "frontends/jw51cm/unit_reports.hpp"
#include "support/jw51cm_frames.hpp"

namespace {

using namespace slmp;
using Bytes = std::vector<std::uint8_t>;
using test::jw51cm::request;
using test::jw51cm::response;

void set_parameters(jw51cm::Options& options, std::uint32_t octal_address, const Bytes& bytes) {
    std::copy(bytes.begin(), bytes.end(), options.parameters.begin() + octal_address);
}

// The record: 32 bytes at file 0 0o5000 (register 19000, D256); the flags at
// コ0740 (the manual's example: relays 07400-07407, M3840-M3847).
struct Fixture {
    devicemodel::Cpu cpu{config::load_profile("R08CPU").cpu};
    jw51cm::Options options;
    std::unique_ptr<jw51cm::ComputerLink> link;

    Fixture() {
        set_parameters(options, 03660, {0x00, 0x0A, 0x00, 0x00, 0x20, 0x00, 0x00, 0x80});
        set_parameters(options, 03764, {0xE0, 0x01, 0x00, 0x80});
        link = std::make_unique<jw51cm::ComputerLink>(cpu, options);
        REQUIRE(jw51cm::check_report_parameters(options.parameters, link->map()).empty());
    }
    Bytes bytes(std::uint32_t address, std::size_t count) {
        jw51cm::ByteAccess memory(cpu.memory(), link->map());
        Bytes out;
        for (std::size_t i = 0; i < count; ++i) out.push_back(memory.byte(0, address + static_cast<std::uint32_t>(i)));
        return out;
    }
};

}  // namespace

TEST_CASE("JW-51CM completion record: peer, connection, RSLT and the command after every answer", "[jw51cm][jw51cm-reports]") {
    Fixture f;
    const jw51cm::Caller caller{{127, 0, 0, 9}, 0x1234, 2};
    auto read = request({0x24, 0x00, 0x00, 0x08, 0x02, 0x00});
    REQUIRE(f.link->handle_stream(read, {}, caller).response == response({0x24, 0x00, 0x00, 0x00, 0x08, 0x02, 0x00, 0x00, 0x00}));
    Bytes expected{0x7F, 0x00, 0x00, 0x09, 0x34, 0x12, 0x02, 0x00, 0x00, 0x00, 0x00, 0x00,
                   0x47, 0x00, 0x24, 0x00, 0x00, 0x08, 0x02, 0x00};
    expected.resize(32, 0x00);
    CHECK(f.bytes(05000, 32) == expected);

    // A refusal is recorded with its RSLT (35 in write mode 0: 10), a long
    // command cut to the area, over UDP on connection 7.
    Bytes fill{0x35, 0x00, 0x00, 0x08, 0x01, 0x00, 0xFF};
    REQUIRE(f.link->handle_datagram(request(fill), {}, {{10, 1, 2, 3}, 50000, 7}).response == response({0x35, 0x10}));
    CHECK(f.bytes(05000, 21) == Bytes{0x0A, 0x01, 0x02, 0x03, 0x50, 0xC3, 0x07, 0x00, 0x10, 0x00, 0x00, 0x00,
                                      0x47, 0x00, 0x35, 0x00, 0x00, 0x08, 0x01, 0x00, 0xFF});
    CHECK(f.bytes(05000 + 21, 11) == Bytes(11, 0x00));   // the shorter command: zeros after it
    REQUIRE(f.link->handle_stream(request({0xF9, 0x01}), {}, caller).response == response({0xF9, 0x00, 0x01}));
    Bytes write{0x34, 0x00, 0x00, 0x09, 0x20, 0x00};
    for (int i = 0; i < 0x20; ++i) write.push_back(static_cast<std::uint8_t>(i));
    REQUIRE(f.link->handle_stream(request(write), {}, caller).response == response({0x34, 0x00, 0x00, 0x00, 0x09, 0x20, 0x00}));
    auto record = f.bytes(05000, 33);
    CHECK(record[8] == 0x00);
    CHECK(Bytes(record.begin() + 12, record.begin() + 32) ==
          Bytes({0x47, 0x00, 0x34, 0x00, 0x00, 0x09, 0x20, 0x00, 0x00, 0x01, 0x02, 0x03, 0x04, 0x05, 0x06, 0x07, 0x08, 0x09, 0x0A, 0x0B}));
    CHECK(record[32] == 0x00);   // the area ends at 32 bytes
    // A request not yet whole writes nothing; nor does an unknown COM over a stream until answered.
    f.link->handle_stream(request({0x24, 0x00}), {}, caller);
    CHECK(f.bytes(05000 + 14, 1) == Bytes{0x34});
    REQUIRE(f.link->handle_stream(request({0x99}), {}, caller).response == response({0x99, 0x01}));
    CHECK(f.bytes(05000 + 8, 7) == Bytes({0x01, 0x00, 0x00, 0x00, 0x47, 0x00, 0x99}));
}

TEST_CASE("JW-51CM completion record: off without 3667 = 80", "[jw51cm][jw51cm-reports]") {
    devicemodel::Cpu cpu{config::load_profile("R08CPU").cpu};
    jw51cm::Options options;
    set_parameters(options, 03660, {0x00, 0x0A, 0x00, 0x00, 0x20, 0x00, 0x00, 0x00});
    jw51cm::ComputerLink link(cpu, options);
    link.handle_stream(request({0xE9}), {}, {{127, 0, 0, 1}, 1, 0});
    jw51cm::ByteAccess memory(cpu.memory(), link.map());
    for (std::uint32_t i = 0; i < 16; ++i) CHECK(memory.byte(0, 05000 + i) == 0);
}

TEST_CASE("JW-51CM connection status flags: UDP from power-on, TCP while established", "[jw51cm][jw51cm-reports]") {
    Fixture f;
    f.link->assign_connections(true);
    CHECK(f.bytes(0740, 1) == Bytes{0x00});   // nothing before power-on
    f.link->power_on();
    CHECK(f.bytes(0740, 1) == Bytes{0x80});   // UDP is connection 7
    CHECK(f.link->udp_connection() == 7);
    CHECK(f.link->open_connection() == 0);
    CHECK(f.link->open_connection() == 1);
    CHECK(f.bytes(0740, 1) == Bytes{0x83});
    f.link->close_connection(0);
    CHECK(f.bytes(0740, 1) == Bytes{0x82});
    CHECK(f.link->open_connection() == 0);   // the lowest free number again
    for (std::uint8_t n = 2; n < 7; ++n) CHECK(f.link->open_connection() == n);
    CHECK(f.bytes(0740, 1) == Bytes{0xFF});
    CHECK(f.link->open_connection() == jw51cm::kNoConnection);   // served, but the unit has no number left
    f.link->close_connection(jw51cm::kNoConnection);
    CHECK(f.bytes(0740, 1) == Bytes{0xFF});
    for (std::uint8_t n = 0; n < 7; ++n) f.link->close_connection(n);
    CHECK(f.bytes(0740, 1) == Bytes{0x80});
    // The byte is the unit's: the ladder may clear it, power-on writes it again.
    jw51cm::ByteAccess memory(f.cpu.memory(), f.link->map());
    memory.set_byte(0, 0740, 0x00);
    f.link->power_on();
    CHECK(f.bytes(0740, 1) == Bytes{0x80});

    // Without a UDP port, TCP clients have all 8 numbers.
    f.link->assign_connections(false);
    f.link->power_on();
    CHECK(f.bytes(0740, 1) == Bytes{0x00});
    CHECK(f.link->udp_connection() == jw51cm::kNoConnection);
    for (std::uint8_t n = 0; n < 8; ++n) CHECK(f.link->open_connection() == n);
    CHECK(f.bytes(0740, 1) == Bytes{0xFF});
}

TEST_CASE("JW-51CM unit: a TCP session takes a connection number and gives it back", "[jw51cm][jw51cm-reports]") {
    devicemodel::Cpu cpu{config::load_profile("R08CPU").cpu};
    auto settings = jw51cm::face().defaults();
    auto& options = *std::static_pointer_cast<jw51cm::Options>(settings.options);
    set_parameters(options, 03660, {0x00, 0x0A, 0x00, 0x00, 0x10, 0x00, 0x00, 0x80});
    set_parameters(options, 03764, {0xE0, 0x01, 0x00, 0x80});
    auto unit = jw51cm::face().make_unit(cpu, settings);
    unit->power_on();
    jw51cm::MemoryMap map(options.file_bytes, options.timers);
    jw51cm::ByteAccess memory(cpu.memory(), map);
    CHECK(memory.byte(0, 0740) == 0x80);
    protocol::Peer peer;
    peer.address = "127.0.0.5";
    peer.ipv4 = {127, 0, 0, 5};
    peer.port = 0x0FA0;   // the manual's host program binds 4000
    auto session = unit->new_session(peer);
    CHECK(memory.byte(0, 0740) == 0x81);
    auto answer = unit->stream(request({0xE9}), session.get(), {});
    CHECK(answer.code == "00");
    Bytes record;
    for (std::uint32_t i = 0; i < 16; ++i) record.push_back(memory.byte(0, 05000 + i));
    CHECK(record == Bytes{0x7F, 0x00, 0x00, 0x05, 0xA0, 0x0F, 0x00, 0x00, 0x00, 0x00, 0x00, 0x00, 0x47, 0x00, 0xE9, 0x00});
    peer.port = 5;
    unit->datagram(request({0xE9}), {}, peer);
    CHECK(memory.byte(0, 05000 + 4) == 0x05);
    CHECK(memory.byte(0, 05000 + 6) == 0x07);
    session.reset();
    CHECK(memory.byte(0, 0740) == 0x80);
    // A session that outlives its unit (shutdown) touches nothing.
    auto late = unit->new_session(peer);
    unit.reset();
    late.reset();
}

TEST_CASE("JW-51CM report parameters are checked as the unit checks them", "[jw51cm][jw51cm-reports]") {
    jw51cm::MemoryMap map;
    std::vector<std::uint8_t> image(jw51cm::kParameterBytes, 0);
    CHECK(jw51cm::check_report_parameters(image, map).empty());
    auto with = [&](std::uint32_t at, Bytes bytes) {
        auto copy = image;
        std::copy(bytes.begin(), bytes.end(), copy.begin() + at);
        return jw51cm::check_report_parameters(copy, map);
    };
    CHECK(with(03660, {0x00, 0x0A, 0x00, 0x00, 0x40, 0x00, 0x00, 0x80}).empty());
    CHECK_THAT(with(03667, {0x81}), Catch::Contains("parameter 3667"));
    CHECK_THAT(with(03660, {0x00, 0x0A, 0x00, 0x00, 0x0F, 0x00, 0x00, 0x80}), Catch::Contains("parameter 3664") && Catch::Contains("16-64"));
    CHECK_THAT(with(03660, {0x00, 0x0A, 0x00, 0x00, 0x41, 0x00, 0x00, 0x80}), Catch::Contains("16-64"));
    CHECK_THAT(with(03660, {0xF0, 0x1F, 0x00, 0x00, 0x20, 0x00, 0x00, 0x80}), Catch::Contains("not inside a file"));   // past 8 KB
    CHECK_THAT(with(03660, {0x00, 0x00, 0x08, 0x00, 0x20, 0x00, 0x00, 0x80}), Catch::Contains("file 8"));
    CHECK_THAT(with(03663, {0x01}), Catch::Contains("parameter 3663") && Catch::Contains("must be 00"));
    CHECK_THAT(with(03767, {0x01}), Catch::Contains("parameter 3767"));
    CHECK_THAT(with(03764, {0x00, 0x20, 0x00, 0x80}), Catch::Contains("parameter 3764"));
}
