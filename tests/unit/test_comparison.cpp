// station/comparison: differential mode's report (docs/twin.md, "Compare")
// counts every compared request by kind, keeps the last Comparison::kKept
// differences (the oldest first, numbered from 1), logs one warning a
// difference and starts afresh on clear().
#include <catch2/catch.hpp>

#include <memory>
#include <sstream>

#include <spdlog/sinks/ostream_sink.h>
#include <spdlog/spdlog.h>

#include "station/comparison.hpp"

using namespace slmp;
using protocol::differential::DifferenceKind;
using protocol::differential::Observed;
using station::Comparison;
using station::ComparedRequest;

namespace {

ComparedRequest compared(std::uint8_t upstream_value, std::uint8_t twin_value) {
    ComparedRequest c;
    c.command = 0x0401;
    c.peer.address = "127.0.0.1";
    c.peer.port = 50312;
    c.request = {0x50, 0x00};
    c.upstream = Observed{Observed::Kind::Answer, {0xD0, 0x00, upstream_value}, 0};
    c.twin = Observed{Observed::Kind::Answer, {0xD0, 0x00, twin_value}, 0};
    return c;
}

}  // namespace

TEST_CASE("comparison: counts by kind, keeps the last 100 differences, one warning each, clear starts afresh",
          "[compare][station]") {
    std::ostringstream text;
    auto sink = std::make_shared<spdlog::sinks::ostream_sink_mt>(text);
    spdlog::logger log("test", sink);
    Comparison comparison(std::chrono::milliseconds(50), log);

    CHECK(comparison.add(compared(1, 1)).same());
    for (std::uint8_t i = 0; i < 105; ++i) CHECK(comparison.add(compared(i, static_cast<std::uint8_t>(i + 1))).kind == DifferenceKind::Bytes);
    auto silent = compared(0, 0);
    silent.upstream = Observed{Observed::Kind::Silence, {}, 0};
    CHECK(comparison.add(silent).kind == DifferenceKind::Silence);

    CHECK(comparison.compared() == 107);
    CHECK(comparison.same() == 1);
    CHECK(comparison.different() == 106);
    CHECK(comparison.count(DifferenceKind::Bytes) == 105);
    CHECK(comparison.count(DifferenceKind::Silence) == 1);
    CHECK(comparison.count(DifferenceKind::Close) == 0);
    REQUIRE(comparison.differences().size() == Comparison::kKept);
    CHECK(comparison.differences().front().number == 8);   // #2-#7 only counted now
    CHECK(comparison.differences().back().number == 107);
    CHECK(comparison.differences().back().difference.kind == DifferenceKind::Silence);

    const auto lines = text.str();
    std::size_t warnings = 0;
    for (auto at = lines.find("compare: #"); at != std::string::npos; at = lines.find("compare: #", at + 1)) ++warnings;
    CHECK(warnings == 106);
    CHECK(lines.find("compare: #2 0401/0000 from tcp:127.0.0.1:50312: bytes: upstream vs twin: same end code 0000, "
                     "bytes differ from offset 2 (3 vs 3 bytes): D00000 vs D00001; request 5000") != std::string::npos);

    comparison.clear();
    CHECK(comparison.compared() == 0);
    CHECK(comparison.different() == 0);
    CHECK(comparison.differences().empty());
    comparison.add(compared(1, 2));
    CHECK(comparison.differences().front().number == 1);
}
