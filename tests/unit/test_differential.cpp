// protocol/differential: the generated requests of slmp diff cover every row of
// the command table in every frame and data code, each is one whole frame, and
// the comparison tells answers, silence and closes apart (docs/twin.md).
#include <catch2/catch.hpp>

#include <set>
#include <string>

#include "config/config.hpp"
#include "devicemodel/hex.hpp"
#include "protocol/differential.hpp"

using namespace slmp;
using protocol::differential::Observed;

TEST_CASE("differential: every command-table row is generated, as whole frames, in 3E/4E binary/ASCII", "[differential]") {
    auto profile = GENERATE(as<std::string>{}, "R08CPU", "Q26UDEHCPU", "FX5U-32MR");
    auto kind = GENERATE(protocol::FrameKind::E3, protocol::FrameKind::E4);
    auto codec = GENERATE(protocol::Codec::Binary, protocol::Codec::Ascii);
    auto p = config::load_profile(profile);
    protocol::client::FrameOptions frame;
    frame.kind = kind;
    frame.codec = codec;
    frame.numbering = p.cpu.numbering;
    auto samples = protocol::differential::generate(p.port, p.cpu, frame);
    INFO(profile);
    CHECK(samples.size() >= 250);
    std::set<std::string> labelled;
    std::uint16_t serial = 0;
    for (const auto& s : samples) {
        INFO(s.label);
        auto scan = protocol::scan_frame(s.bytes, protocol::Direction::Request, protocol::DataCodePolicy::Auto, 1u << 20);
        REQUIRE(scan.status == protocol::FrameScan::Status::Complete);
        CHECK(scan.size == s.bytes.size());
        CHECK(scan.header.kind == kind);
        CHECK(scan.header.codec == codec);
        if (kind == protocol::FrameKind::E4) CHECK(scan.header.serial == serial++);   // each its own serial
        labelled.insert(s.label.substr(0, 10));
    }
    for (const auto& row : protocol::all_commands()) {
        if (row.command == 0x1006) continue;   // Remote RESET restarts the CPU: left out on purpose
        if (row.command == 0x0E35) continue;   // Parameter Set Start locks a node for 10 s: likewise
        auto key = devicemodel::hex4(row.command) + "/" + devicemodel::hex4(row.subcommand) + " ";
        INFO(row.name);
        CHECK(labelled.count(key) == 1);
    }
}

TEST_CASE("differential: the same answer is no difference; another end code, bytes, silence or close is", "[differential]") {
    Observed ok{Observed::Kind::Answer, {0xD0, 0x00, 0x00, 0x00}, 0};
    Observed other_bytes{Observed::Kind::Answer, {0xD0, 0x00, 0x00, 0x01}, 0};
    Observed refused{Observed::Kind::Answer, {0xD0, 0x00, 0x59, 0xC0}, 0xC059};
    Observed silence{Observed::Kind::Silence, {}, 0};
    Observed closed{Observed::Kind::Close, {}, 0};
    using protocol::differential::difference;
    CHECK_FALSE(difference(ok, ok));
    CHECK_FALSE(difference(silence, silence));
    CHECK_FALSE(difference(closed, closed));
    CHECK(*difference(ok, refused) == "end code 0000, 4 bytes vs end code C059, 4 bytes");
    CHECK(*difference(ok, other_bytes) == "same end code 0000, bytes differ from offset 3 (4 vs 4 bytes): D0000000 vs D0000001");
    CHECK(*difference(silence, closed) == "no answer vs connection closed");
    CHECK(*difference(ok, silence) == "end code 0000, 4 bytes vs no answer");
}
