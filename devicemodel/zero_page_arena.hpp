// Zero-filled memory that costs RAM only where it is written: the block behind
// a DeviceMemory's stores (docs/plants.md, "Memory"; issue 33).
//
// A block of kMapThreshold bytes or more is its own private anonymous mapping:
// its pages read as the kernel's shared zero page until written, whatever
// state the heap is in. calloc promised the same and did not keep it: once
// glibc has raised its mmap threshold (it does when a large mmapped block is
// freed) or holds freed memory, calloc hands out recycled heap pages and
// clears them, so every store of every station was private dirty memory.
// Transparent huge pages are declined for the mapping (MADV_NOHUGEPAGE): with
// THP "always" one written word would otherwise cost 2 MiB instead of 4 KiB.
// Smaller blocks come from calloc (a few KiB at most are dirty).
//
// Which pages were ever touched is read from /proc/self/pagemap (present or
// swapped), without reading the pages themselves: a page that is neither was
// never written and is zero. Snapshots, copies, comparisons and clears visit
// only the touched pages, so an idle station's snapshot reads none of its
// memory. Where pagemap cannot be read every page counts as touched: slower,
// never wrong. A page only read is present too (it maps the zero page, which
// is not private memory): it is scanned, not copied.
#pragma once

#include <cstddef>
#include <vector>

namespace slmp::devicemodel {

// Bytes [begin, end) of an arena.
struct ByteRange {
    std::size_t begin = 0;
    std::size_t end = 0;
};

class ZeroPageArena {
public:
    static constexpr std::size_t kMapThreshold = 16 * 1024;

    ZeroPageArena() = default;
    explicit ZeroPageArena(std::size_t bytes);   // all zero; throws std::bad_alloc
    // Copies only the pages of `other` that hold a non-zero byte: the copy of
    // an idle CPU's memory costs no RAM either.
    ZeroPageArena(const ZeroPageArena& other);
    ZeroPageArena(ZeroPageArena&& other) noexcept;
    ZeroPageArena& operator=(const ZeroPageArena& other);
    ZeroPageArena& operator=(ZeroPageArena&& other) noexcept;
    ~ZeroPageArena();

    std::byte* data() { return data_; }
    const std::byte* data() const { return data_; }
    std::size_t size() const { return size_; }

    // The parts of bytes [begin, end) that may hold a non-zero byte, ascending
    // and disjoint (whole pages, clipped to [begin, end)); every other byte is 0.
    std::vector<ByteRange> touched(std::size_t begin, std::size_t end) const;
    std::vector<ByteRange> touched() const { return touched(0, size_); }

    // Same size and the same bytes; reads only pages touched in either.
    bool operator==(const ZeroPageArena& other) const;

private:
    void release() noexcept;

    std::byte* data_ = nullptr;
    std::size_t size_ = 0;
    bool mapped_ = false;   // false: calloc'd (small), every page counts as touched
};

// The union of two ascending lists of disjoint ranges, ascending and disjoint.
std::vector<ByteRange> merge_ranges(const std::vector<ByteRange>& a, const std::vector<ByteRange>& b);

}  // namespace slmp::devicemodel
