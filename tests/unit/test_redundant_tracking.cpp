// A redundant pair's tracking (station/redundant_tracking.hpp) and its special
// relays and registers (devicemodel/redundant_registers.hpp; docs/plants.md,
// "Tracking"; docs/cpu-runtime.md, "Redundant pairs").
#include <catch2/catch.hpp>

#include <algorithm>
#include <string>
#include <vector>

#include "config/config.hpp"
#include "devicemodel/cpu.hpp"
#include "devicemodel/device_table.hpp"
#include "devicemodel/redundant_registers.hpp"
#include "devicemodel/special_registers.hpp"
#include "station/redundant_tracking.hpp"

using slmp::devicemodel::Cpu;
using slmp::devicemodel::DeviceMemory;
using slmp::devicemodel::DeviceSpec;
using slmp::station::Tracking;

namespace {

const DeviceSpec& spec(const char* symbol) { return *slmp::devicemodel::find_by_symbol(symbol); }

Cpu cpu(const char* profile) { return Cpu(slmp::config::load_profile(profile).cpu); }

// Counts the points the standby's writes touched.
struct Writes : slmp::devicemodel::WriteObserver {
    std::vector<std::string> seen;
    void written(const DeviceSpec& s, std::uint32_t first, std::uint32_t count) override {
        seen.push_back(std::string(s.symbol) + std::to_string(first) + "+" + std::to_string(count));
    }
};

}  // namespace

TEST_CASE("tracking: the default ranges are all of M, L, B, D, W and the timers' and counters' values", "[redundant][tracking]") {
    auto a = cpu("R08PCPU");
    auto b = cpu("R08PCPU");
    Tracking tracking(std::nullopt, a.memory(), b.memory());
    std::vector<std::string> symbols;
    for (const auto& r : tracking.ranges()) {
        symbols.emplace_back(r.spec->symbol);
        CHECK(r.first == 0);
        CHECK(r.count == a.memory().size(r.spec->area) - a.memory().size(r.spec->area) % (r.spec->unit == slmp::devicemodel::Unit::Bit ? 16 : 1));
    }
    CHECK(symbols == std::vector<std::string>{"M", "L", "B", "D", "W", "TN", "STN", "CN", "LTN", "LSTN", "LCN"});

    // An empty list tracks nothing.
    CHECK(Tracking(std::vector<Tracking::Range>{}, a.memory(), b.memory()).ranges().empty());
}

TEST_CASE("tracking: an image of the control system's devices written over the standby's, only where they differ",
          "[redundant][tracking]") {
    auto a = cpu("R08PCPU");
    auto b = cpu("R08PCPU");
    auto& control = a.memory();
    auto& standby = b.memory();
    control.set_value(spec("D"), 5, 0x1234);
    control.set_bit(spec("M"), 17, true);
    control.set_value(spec("TN"), 3, 9);
    control.set_value(spec("LTN"), 2, 0x00012345);
    control.set_value(spec("W"), 0x10, 0xABCD);
    standby.set_value(spec("D"), 6, 0x7777);   // a client's write to the standby
    standby.set_value(spec("X"), 0, 1);        // X is not tracked

    Tracking tracking(std::nullopt, control, standby);
    auto image = tracking.capture(control);
    Writes writes;
    standby.set_write_observer(&writes);
    tracking.apply(*image, standby);
    standby.set_write_observer(nullptr);
    CHECK(standby.value(spec("D"), 5) == 0x1234);
    CHECK(standby.value(spec("D"), 6) == 0);
    CHECK(standby.bit(spec("M"), 17));
    CHECK(standby.value(spec("TN"), 3) == 9);
    CHECK(standby.value(spec("LTN"), 2) == 0x00012345);
    CHECK(standby.value(spec("W"), 0x10) == 0xABCD);
    CHECK(standby.value(spec("X"), 0) == 1);
    // Only the differing runs were written, each heard once: M17, D5-D6, W10, TN3, LTN2.
    std::sort(writes.seen.begin(), writes.seen.end());
    CHECK(writes.seen == std::vector<std::string>{"D5+2", "LTN2+1", "M17+1", "TN3+1", "W16+1"});

    // Applied again: nothing differs, nothing is written.
    writes.seen.clear();
    standby.set_write_observer(&writes);
    tracking.apply(*image, standby);
    standby.set_write_observer(nullptr);
    CHECK(writes.seen.empty());
}

TEST_CASE("tracking: given ranges, cut to what both CPUs have", "[redundant][tracking]") {
    auto a = cpu("R08PCPU");
    auto b = cpu("Q26UDEHCPU");
    const auto d_size = std::min(a.memory().size(spec("D").area), b.memory().size(spec("D").area));
    std::vector<Tracking::Range> given{{&spec("D"), 0, 10}, {&spec("D"), d_size - 4, 100}, {&spec("LTN"), 0, 16}};
    Tracking tracking(given, a.memory(), b.memory());
    REQUIRE(tracking.ranges().size() == 2);   // Q26UDEH has no long timers
    CHECK(tracking.ranges()[1].count == 4);
    a.memory().set_value(spec("D"), 9, 1);
    a.memory().set_value(spec("D"), 10, 2);
    tracking.apply(*tracking.capture(a.memory()), b.memory());
    CHECK(b.memory().value(spec("D"), 9) == 1);
    CHECK(b.memory().value(spec("D"), 10) == 0);
}

TEST_CASE("the pair's SM/SD: the QnPRH numbers, the iQ-R numbers, none on iQ-F", "[redundant][special]") {
    using namespace slmp::devicemodel;
    RedundantStatus status{true, true, SwitchCause::StopError, SwitchCause::StopError, SwitchFailure::StandbyStopError};
    auto q = cpu("Q26UDEHCPU");
    publish_redundant(q.memory(), Family::QnU, status);
    CHECK_FALSE(q.memory().bit(spec("SM"), 1511));
    CHECK(q.memory().bit(spec("SM"), 1512));
    CHECK(q.memory().bit(spec("SM"), 1515));
    CHECK_FALSE(q.memory().bit(spec("SM"), 1516));
    CHECK(special::sd(q.memory(), 1588) == 2);
    CHECK(special::sd(q.memory(), 1601) == 2);

    auto r = cpu("R08PCPU");
    status = {false, false, SwitchCause::None, SwitchCause::Request, SwitchFailure::StandbyUnavailable};
    publish_redundant(r.memory(), Family::IQR, status);
    CHECK(r.memory().bit(spec("SM"), 1632));
    CHECK_FALSE(r.memory().bit(spec("SM"), 1633));
    CHECK_FALSE(r.memory().bit(spec("SM"), 1634));
    CHECK(r.memory().bit(spec("SM"), 1635));
    CHECK(special::sd(r.memory(), 1643) == 0);
    CHECK(special::sd(r.memory(), 1644) == 1);
    CHECK(special::sd(r.memory(), 1649) == 17);

    auto f = cpu("FX5U-32MR");
    publish_redundant(f.memory(), Family::IQF, status);
    CHECK_FALSE(f.memory().bit(spec("SM"), 1632));
}
