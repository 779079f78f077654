// The block behind device memory (devicemodel/zero_page_arena.hpp): pages
// never written are known without reading them, copies and comparisons go by
// them, and DeviceMemory::possibly_nonzero turns them into device ranges.
#include <catch2/catch.hpp>

#include <cstring>

#include "devicemodel/device_clear.hpp"
#include "devicemodel/device_memory.hpp"
#include "devicemodel/zero_page_arena.hpp"

using slmp::devicemodel::ByteRange;
using slmp::devicemodel::ZeroPageArena;

namespace {

bool pagemap_readable() {
    // Where /proc/self/pagemap cannot be read every page counts as touched
    // (correct, only slower): the page-exact checks below need it.
    ZeroPageArena probe(1 << 20);
    return probe.touched().empty();
}

}  // namespace

TEST_CASE("zero page arena: untouched pages are zero and not reported", "[device_memory][zero_pages]") {
    ZeroPageArena arena(1 << 20);
    REQUIRE(arena.size() == (1u << 20));
    for (std::size_t i = 0; i < arena.size(); i += 4096) CHECK(arena.data()[i] == std::byte{0});
    if (!pagemap_readable()) {
        WARN("/proc/self/pagemap not readable: every page counts as touched");
        return;
    }
    // Read pages map the shared zero page: they may be reported, they stay zero.
    ZeroPageArena fresh(1 << 20);
    CHECK(fresh.touched().empty());
    fresh.data()[5000] = std::byte{7};
    fresh.data()[300000] = std::byte{9};
    auto touched = fresh.touched();
    REQUIRE(touched.size() == 2);
    CHECK(touched[0].begin <= 5000);
    CHECK(touched[0].end > 5000);
    CHECK(touched[1].begin <= 300000);
    CHECK(touched[1].end > 300000);
    CHECK(touched[1].end - touched[1].begin <= 64 * 1024);   // a page, not a huge page

    SECTION("a copy holds the written bytes and touches nothing else") {
        ZeroPageArena copy(fresh);
        CHECK(copy == fresh);
        CHECK(copy.data()[5000] == std::byte{7});
        CHECK(copy.data()[300000] == std::byte{9});
        CHECK(copy.touched().size() == 2);
        copy.data()[300000] = std::byte{0};
        CHECK_FALSE(copy == fresh);
    }
    SECTION("a range asked for is clipped to it") {
        auto part = fresh.touched(4500, 6000);
        REQUIRE(part.size() == 1);
        CHECK(part[0].begin == 4500);
        CHECK(part[0].end == 6000);
        CHECK(fresh.touched(100000, 200000).empty());
    }
}

TEST_CASE("zero page arena: small blocks live on the heap and count as touched", "[device_memory][zero_pages]") {
    ZeroPageArena small(100);
    auto touched = small.touched();
    REQUIRE(touched.size() == 1);
    CHECK(touched[0].begin == 0);
    CHECK(touched[0].end == 100);
    small.data()[3] = std::byte{1};
    ZeroPageArena copy(small);
    CHECK(copy == small);
    CHECK(ZeroPageArena(0).touched().empty());
}

TEST_CASE("merge_ranges: the union of two range lists", "[device_memory][zero_pages]") {
    std::vector<ByteRange> a{{0, 10}, {20, 30}}, b{{5, 12}, {30, 40}, {50, 60}};
    auto merged = slmp::devicemodel::merge_ranges(a, b);
    REQUIRE(merged.size() == 3);
    CHECK((merged[0].begin == 0 && merged[0].end == 12));
    CHECK((merged[1].begin == 20 && merged[1].end == 40));
    CHECK((merged[2].begin == 50 && merged[2].end == 60));
}

TEST_CASE("device memory: possibly_nonzero covers every written device, and a clear dirties nothing new",
          "[device_memory][zero_pages]") {
    using namespace slmp::devicemodel;
    DeviceSizes sizes{};
    sizes[static_cast<std::size_t>(Area::D)] = 100000;
    sizes[static_cast<std::size_t>(Area::M)] = 100000;
    DeviceMemory memory(sizes, 0);
    const auto* d = find_by_symbol("D");
    const auto* m = find_by_symbol("M");
    memory.set_value(*d, 70000, 5);
    memory.set_bit(*m, 12345, true);
    auto covers = [&](const DeviceSpec& spec, std::uint32_t number) {
        for (const auto& r : memory.possibly_nonzero(spec))
            if (number >= r.first && number < r.end) return true;
        return false;
    };
    CHECK(covers(*d, 70000));
    CHECK(covers(*m, 12345));
    if (pagemap_readable()) {
        CHECK_FALSE(covers(*d, 10));
        CHECK_FALSE(covers(*m, 90000));
    }
    const auto before = memory;
    CHECK(before == memory);
    CHECK(before.value(*d, 70000) == 5);
    clear_devices(memory, LatchMap{}, ClearScope::All);
    CHECK(memory.value(*d, 70000) == 0);
    CHECK_FALSE(memory.bit(*m, 12345));
    CHECK_FALSE(before == memory);
}
