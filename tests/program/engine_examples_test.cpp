// Spec §8 worked examples (the acceptance vectors), scan by scan at engine level.
#include <catch2/catch.hpp>

#include "engine_support.hpp"

using namespace engine_test;

TEST_CASE("8.1 self-holding circuit", "[program][engine][examples]") {
    Rig rig(dotted("LD X0 · OR Y0 · ANI X1 · OUT Y0 · END"));
    struct Row { int x0, x1, y0; };
    for (auto [x0, x1, y0] : {Row{0, 0, 0}, Row{1, 0, 1}, Row{0, 0, 1}, Row{0, 1, 0}, Row{0, 0, 0}, Row{1, 1, 0}}) {
        rig.set("X0", x0);
        rig.set("X1", x1);
        rig.scan();
        INFO("scan " << rig.scans);
        CHECK(rig.get("Y0") == static_cast<std::uint32_t>(y0));
    }
}
