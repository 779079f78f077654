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

TEST_CASE("differential: the same answer is no difference — another end code, bytes, silence or close is", "[differential]") {
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

TEST_CASE("differential: classify names the kind — close before silence, end code before bytes, time last", "[differential][compare]") {
    using protocol::differential::classify;
    using protocol::differential::DifferenceKind;
    using protocol::differential::kind_name;
    using namespace std::chrono_literals;
    Observed ok{Observed::Kind::Answer, {0xD0, 0x00, 0x00, 0x00}, 0};
    Observed other_bytes{Observed::Kind::Answer, {0xD0, 0x00, 0x00, 0x01}, 0};
    Observed longer{Observed::Kind::Answer, {0xD0, 0x00, 0x00, 0x00, 0x07}, 0};
    Observed refused{Observed::Kind::Answer, {0xD0, 0x00, 0x59, 0xC0}, 0xC059};
    Observed silence{Observed::Kind::Silence, {}, 0};
    Observed closed{Observed::Kind::Close, {}, 0};

    CHECK(classify(ok, ok).same());
    CHECK(classify(silence, silence).same());
    CHECK(classify(closed, closed).same());
    CHECK(kind_name(classify(ok, ok).kind) == "same");

    // One side closed: close, whatever the other did.
    CHECK(classify(ok, closed).kind == DifferenceKind::Close);
    CHECK(classify(closed, silence).kind == DifferenceKind::Close);
    CHECK(classify(silence, closed).kind == DifferenceKind::Close);
    // One side silent, the other answered: silence.
    auto d = classify(silence, refused);
    CHECK(d.kind == DifferenceKind::Silence);
    CHECK(d.text == "no answer vs end code C059, 4 bytes");
    CHECK_FALSE(d.first_byte);

    // Both answered: another end code, then the first differing byte.
    d = classify(ok, refused);
    CHECK(d.kind == DifferenceKind::EndCode);
    CHECK(kind_name(d.kind) == "end_code");
    CHECK(d.first_byte == 2u);
    d = classify(ok, other_bytes);
    CHECK(d.kind == DifferenceKind::Bytes);
    CHECK(d.first_byte == 3u);
    d = classify(ok, longer);   // the shorter is the start of the longer: its length
    CHECK(d.kind == DifferenceKind::Bytes);
    CHECK(d.first_byte == 4u);
    CHECK(d.text == "same end code 0000, bytes differ from offset 4 (4 vs 5 bytes): D0000000 vs D000000007");

    // Times: only with a slack, only when both were measured, only for the same answer.
    auto timed = [](Observed o, std::chrono::microseconds t) {
        o.time = t;
        return o;
    };
    CHECK(classify(timed(ok, 4ms), timed(ok, 120ms)).same());   // no slack given: not compared
    CHECK(classify(timed(ok, 4ms), ok, 10ms).same());           // one side not measured
    d = classify(timed(ok, 4ms), timed(ok, 120ms), 10ms);
    CHECK(d.kind == DifferenceKind::Time);
    CHECK(d.text == "the same answer, in 4.000 ms vs 120.000 ms (far apart: more than twice the shorter plus 10.000 ms)");
    CHECK(classify(timed(ok, 4ms), timed(other_bytes, 120ms), 10ms).kind == DifferenceKind::Bytes);

    // The rule: the longer more than twice the shorter plus the slack.
    using protocol::differential::times_far_apart;
    CHECK_FALSE(times_far_apart(0ms, 50ms, 50ms));
    CHECK(times_far_apart(0ms, 51ms, 50ms));
    CHECK_FALSE(times_far_apart(100ms, 250ms, 50ms));
    CHECK(times_far_apart(251ms, 100ms, 50ms));
    CHECK_FALSE(times_far_apart(3ms, 3ms, 0ms));
}
