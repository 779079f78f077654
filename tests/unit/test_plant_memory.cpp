// Issue 33: an idle station costs (almost) no RAM, whatever state the heap is
// in. 200 R08CPU stations (~5 MiB of device memory each) are built after the
// heap was warmed the way a long-running process warms it (large blocks
// allocated, written and freed: glibc then raises its mmap threshold and hands
// out recycled heap memory), their initial snapshots are taken as the server
// takes them, and the process's private dirty memory is read from
// /proc/self/smaps_rollup at each step. Counts of memory, not time, so the
// bounds are deterministic; the figures are printed for docs/plants.md.
#include <catch2/catch.hpp>

#include <cstdlib>
#include <cstring>
#include <fstream>
#include <iostream>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "config/config.hpp"
#include "devicemodel/snapshot.hpp"
#include "station/station.hpp"
#include "station/station_snapshot.hpp"

namespace {

// Private_Dirty of the whole process in KiB, or nothing where /proc has no
// smaps_rollup (the test is then skipped, not failed).
std::optional<long> private_dirty_kib() {
    std::ifstream in("/proc/self/smaps_rollup");
    std::string key;
    long kib = 0;
    while (in >> key) {
        if (key == "Private_Dirty:" && in >> kib) return kib;
        in.ignore(1 << 20, '\n');
    }
    return std::nullopt;
}

// What a heap looks like after some hours of large requests: glibc serves a
// 1 MiB block with mmap, and freeing it raises the mmap threshold to 1 MiB, so
// later blocks below that come from the heap; the 512 KiB blocks are written
// (dirty) and freed between pins that keep the heap from trimming them away.
// A store that trusts calloc for zero pages gets these dirty pages back.
// Small blocks pinned between the freed ones, freed at the end of the test
// (LeakSanitizer would report them if they outlived it).
#if defined(__SANITIZE_ADDRESS__)
constexpr bool kAddressSanitizer = true;
#elif defined(__has_feature)
#if __has_feature(address_sanitizer)
constexpr bool kAddressSanitizer = true;
#else
constexpr bool kAddressSanitizer = false;
#endif
#else
constexpr bool kAddressSanitizer = false;
#endif

struct Pins {
    std::vector<void*> blocks;
    ~Pins() {
        for (auto* p : blocks) std::free(p);
    }
};

void warm_heap(Pins& pins) {
    std::vector<void*> big;
    for (int i = 0; i < 64; ++i) {
        big.push_back(std::malloc(1 << 20));
        std::memset(big.back(), 0xA5, 1 << 20);
    }
    for (auto* p : big) std::free(p);
    std::vector<void*> freed;
    for (int i = 0; i < 128; ++i) {
        freed.push_back(std::malloc(512 << 10));
        std::memset(freed.back(), 0x5A, 512 << 10);
        pins.blocks.push_back(std::malloc(64));
    }
    for (auto* p : freed) std::free(p);
}

}  // namespace

TEST_CASE("an idle plant's device memory stays untouched after start and snapshots, on a warm heap", "[memory][snapshot]") {
    constexpr int kStations = 200;
    Pins pins;   // kept for the test's life, like a long-lived heap
    warm_heap(pins);
    const auto before = private_dirty_kib();
    if (!before) {
        WARN("no /proc/self/smaps_rollup: memory not measured");
        return;
    }
    auto profile = slmp::config::load_profile("R08CPU");

    std::vector<std::unique_ptr<slmp::station::Station>> stations;
    for (int i = 0; i < kStations; ++i)
        stations.push_back(std::make_unique<slmp::station::Station>(profile, slmp::protocol::EngineOptions{}));
    const auto started = *private_dirty_kib();

    for (auto& s : stations) s->take_initial_snapshot();
    const auto snapshotted = *private_dirty_kib();

    // One station's 1 000 words written (D0..D999), then its snapshot again.
    const auto* d = slmp::devicemodel::find_by_symbol("D");
    auto& written = stations.front()->cpu().memory();
    const auto touched_bytes = [&written] {
        std::size_t bytes = 0;
        for (const auto& range : written.touched_pages()) bytes += range.end - range.begin;
        return bytes;
    };
    const auto touched_before = touched_bytes();
    for (std::uint32_t n = 0; n < 1000; ++n) written.set_value(*d, n, n + 1);
    const auto touched_by_writes = touched_bytes() - touched_before;
    auto again = stations.front()->snapshot();
    const auto after_writes = *private_dirty_kib();

    const double start_per_station = double(started - *before) / kStations;
    const double snapshot_per_station = double(snapshotted - started) / kStations;
    const double idle_per_station = double(snapshotted - *before) / kStations;
    std::cout << "plant memory (" << kStations << " R08CPU stations, warm heap): private dirty KiB per idle station: "
              << start_per_station << " after start, +" << snapshot_per_station << " after the initial snapshots ("
              << idle_per_station << " in all); the station with 1000 words written: +" << (after_writes - snapshotted)
              << " KiB\n";
    CHECK(again.memory_bytes() > 4000);
    // AddressSanitizer's allocator keeps freed blocks in quarantine (dirty), so
    // the heap figures say nothing there; the g++ suite checks the bounds.
    if (kAddressSanitizer) {
        WARN("AddressSanitizer build: the private dirty bounds are not checked");
        return;
    }
    // An R08CPU has ~5 MiB of device memory; an idle station must not pay for
    // it. What an idle station does pay: its objects on the heap, the SM/SD
    // pages the runtime writes at power-on and its (sparse) initial snapshot.
    CHECK(idle_per_station < 96);
    // 1 000 words are 4 KB of values: a few pages of the store. Counted in the
    // store's own touched pages, not the process's private dirty memory, which
    // the snapshot's heap blocks move by a megabyte or more now and then (the
    // process-wide figure is printed above).
    CHECK(touched_by_writes <= 16 * 1024);
}
