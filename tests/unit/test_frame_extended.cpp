// The station-number-extended frame (68 00 / E8 00, binary only; SLMP Reference
// Manual §2.1, ch. 4) on the RJ71GN11-T2 profile, byte-exact; ports
// without it (an R08CPU's built-in port) do not know the frame and skip it.
#include "support/fixtures.hpp"

using namespace slmp;
using namespace slmp::test;

namespace {

void seed(devicemodel::Cpu& cpu) {
    auto d = devicemodel::parse_address("D100")->spec;
    cpu.memory().set_value(*d, 100, 0x1995);
    cpu.memory().set_value(*d, 101, 0x1202);
    cpu.memory().set_value(*d, 102, 0x1130);
}

}  // namespace

TEST_CASE("station-number-extended frame: read D100-D102 (the §3.4 A vector in the extended shape)", "[frames][extended]") {
    auto cpu = make_cpu("RJ71GN11-T2");
    seed(cpu);
    SECTION("station FF, extended station 0000: own station") {
        auto out = run(cpu, bytes("68 00 34 12 00 00 | 00 FF FF 03 00 | 00 00 00 | 12 00 | 10 00 | 01 04 00 00 | 00 | "
                                  "00 00 00 00 00 | 64 00 00 A8 03 00"));
        CHECK(hex(out.response) == hex(bytes("E8 00 34 12 00 00 | 00 FF FF 03 00 | 00 00 00 | 12 00 | 00 00 | "
                                             "01 04 00 00 00 00 00 00 00 00 | 95 19 02 12 30 11")));
    }
    SECTION("station 7C, extended station FFFF: own station, echoed") {
        auto out = run(cpu, bytes("68 00 01 00 00 00 | 00 7C FF 03 00 | 00 FF FF | 12 00 | 10 00 | 01 04 00 00 | 00 | "
                                  "00 00 00 00 00 | 64 00 00 A8 01 00"));
        CHECK(hex(out.response) == hex(bytes("E8 00 01 00 00 00 | 00 7C FF 03 00 | 00 FF FF | 0E 00 | 00 00 | "
                                             "01 04 00 00 00 00 00 00 00 00 | 95 19")));
    }
    SECTION("station 7C, extended station 0080 (128): another station -> 4A02 with the extended error information") {
        auto out = run(cpu, bytes("68 00 02 00 00 00 | 00 7C FF 03 00 | 00 80 00 | 12 00 | 10 00 | 01 04 00 00 | 00 | "
                                  "00 00 00 00 00 | 64 00 00 A8 01 00"));
        CHECK(hex(out.response) == hex(bytes("E8 00 02 00 00 00 | 00 7C FF 03 00 | 00 80 00 | 14 00 | 02 4A | "
                                             "01 04 00 00 00 00 00 00 00 00 | 00 7C FF 03 00 00 80 00")));
    }
    SECTION("a write through the extended frame, then a 3E read of it") {
        auto out = run(cpu, bytes("68 00 03 00 00 00 | 00 FF FF 03 00 | 00 00 00 | 16 00 | 10 00 | 01 14 00 00 | 00 | "
                                  "00 00 00 00 00 | 00 00 00 A8 02 00 | 34 12 78 56"));
        CHECK(hex(out.response) == hex(bytes("E8 00 03 00 00 00 | 00 FF FF 03 00 | 00 00 00 | 0C 00 | 00 00 | "
                                             "01 14 00 00 00 00 00 00 00 00")));
        auto d = devicemodel::parse_address("D0")->spec;
        CHECK(cpu.memory().value(*d, 0) == 0x1234);
        CHECK(cpu.memory().value(*d, 1) == 0x5678);
    }
    SECTION("every proper prefix waits for more") {
        auto frame = bytes("68 00 34 12 00 00 00 FF FF 03 00 00 00 00 12 00 10 00 01 04 00 00 00 00 00 00 00 00 64 00 00 A8 03 00");
        for (std::size_t n = 0; n < frame.size(); ++n)
            CHECK(run(cpu, std::span(frame).first(n)).action == Outcome::Action::NeedMore);
    }
}

TEST_CASE("station-number-extended frame on ports without it: skipped, not answered", "[frames][extended]") {
    for (const char* profile : {"R08CPU", "Q06UDVCPU-QJ71E71", "FX5U-32MR"}) {
        auto cpu = make_cpu(profile);
        auto out = run(cpu, bytes("68 00 34 12 00 00 00 FF FF 03 00 00 00 00 12 00 10 00 01 04 00 00 00 00 00 00 00 00 "
                                  "64 00 00 A8 03 00"));
        CHECK(out.action == Outcome::Action::Silent);
        CHECK(out.response.empty());
    }
}
