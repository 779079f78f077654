#include "devicemodel/zero_page_arena.hpp"

#include <fcntl.h>
#include <sys/mman.h>
#include <unistd.h>

#include <algorithm>
#include <cstdint>
#include <cstdlib>
#include <cstring>
#include <new>
#include <utility>

namespace slmp::devicemodel {
namespace {

std::size_t page_size() {
    static const std::size_t size = [] {
        long n = ::sysconf(_SC_PAGESIZE);
        return n > 0 ? static_cast<std::size_t>(n) : std::size_t{4096};
    }();
    return size;
}

// /proc/self/pagemap, opened once per process: a snapshot asks it once per
// stored part, and opening it each time would cost more than the answer. A
// descriptor inherited across fork() describes the parent, so a child opens
// its own for each question. -1 where it cannot be opened.
class PagemapFile {
public:
    PagemapFile() {
        if (shared().pid == ::getpid()) {
            fd_ = shared().fd;
        } else {
            fd_ = ::open("/proc/self/pagemap", O_RDONLY | O_CLOEXEC);
            owned_ = true;
        }
    }
    ~PagemapFile() {
        if (owned_ && fd_ >= 0) ::close(fd_);
    }
    PagemapFile(const PagemapFile&) = delete;
    PagemapFile& operator=(const PagemapFile&) = delete;
    int fd() const { return fd_; }

private:
    struct Shared {
        int fd = ::open("/proc/self/pagemap", O_RDONLY | O_CLOEXEC);
        pid_t pid = ::getpid();
    };
    static const Shared& shared() {
        static const Shared s;
        return s;
    }
    int fd_ = -1;
    bool owned_ = false;
};

// pagemap entry bits (Documentation/admin-guide/mm/pagemap.rst): a page that
// is neither present nor swapped out was never faulted in, so it is zero.
constexpr std::uint64_t kPresent = 1ull << 63;
constexpr std::uint64_t kSwapped = 1ull << 62;

void append(std::vector<ByteRange>& out, std::size_t begin, std::size_t end) {
    if (begin >= end) return;
    if (!out.empty() && out.back().end == begin) out.back().end = end;
    else out.push_back({begin, end});
}

// Whether a page of `bytes` bytes is all zero (memcmp against a zero block is
// vectorised; the pages are 4 KiB, the block 512 bytes).
bool all_zero(const std::byte* p, std::size_t bytes) {
    static constexpr std::byte kZero[512] = {};
    while (bytes >= sizeof kZero) {
        if (std::memcmp(p, kZero, sizeof kZero) != 0) return false;
        p += sizeof kZero;
        bytes -= sizeof kZero;
    }
    return bytes == 0 || std::memcmp(p, kZero, bytes) == 0;
}

}  // namespace

ZeroPageArena::ZeroPageArena(std::size_t bytes) : size_(bytes) {
    if (bytes == 0) return;
    if (bytes < kMapThreshold) {
        data_ = static_cast<std::byte*>(std::calloc(bytes, 1));
        if (!data_) throw std::bad_alloc();
        return;
    }
    // MAP_NORESERVE: untouched pages are not committed either, so a plant of
    // idle stations does not need their full size in overcommit accounting.
    void* p = ::mmap(nullptr, bytes, PROT_READ | PROT_WRITE, MAP_PRIVATE | MAP_ANONYMOUS | MAP_NORESERVE, -1, 0);
    if (p == MAP_FAILED) throw std::bad_alloc();
#ifdef MADV_NOHUGEPAGE
    ::madvise(p, bytes, MADV_NOHUGEPAGE);   // advice only: a kernel without THP refuses it, harmlessly
#endif
    data_ = static_cast<std::byte*>(p);
    mapped_ = true;
}

ZeroPageArena::ZeroPageArena(const ZeroPageArena& other) : ZeroPageArena(other.size_) {
    if (!mapped_) {
        if (size_ > 0) std::memcpy(data_, other.data_, size_);
        return;
    }
    // Page by page, and only pages that hold something: a page the source
    // only read is present (the zero page) but copying it would dirty ours.
    const auto page = page_size();
    for (const auto& r : other.touched()) {
        for (auto at = r.begin; at < r.end;) {
            const auto end = std::min(r.end, (at / page + 1) * page);
            if (!all_zero(other.data_ + at, end - at)) std::memcpy(data_ + at, other.data_ + at, end - at);
            at = end;
        }
    }
}

ZeroPageArena::ZeroPageArena(ZeroPageArena&& other) noexcept
    : data_(std::exchange(other.data_, nullptr)), size_(std::exchange(other.size_, 0)),
      mapped_(std::exchange(other.mapped_, false)) {}

ZeroPageArena& ZeroPageArena::operator=(const ZeroPageArena& other) {
    if (this != &other) *this = ZeroPageArena(other);
    return *this;
}

ZeroPageArena& ZeroPageArena::operator=(ZeroPageArena&& other) noexcept {
    if (this != &other) {
        release();
        data_ = std::exchange(other.data_, nullptr);
        size_ = std::exchange(other.size_, 0);
        mapped_ = std::exchange(other.mapped_, false);
    }
    return *this;
}

ZeroPageArena::~ZeroPageArena() { release(); }

void ZeroPageArena::release() noexcept {
    if (!data_) return;
    if (mapped_) ::munmap(data_, size_);
    else std::free(data_);
    data_ = nullptr;
    size_ = 0;
    mapped_ = false;
}

std::vector<ByteRange> ZeroPageArena::touched(std::size_t begin, std::size_t end) const {
    std::vector<ByteRange> out;
    end = std::min(end, size_);
    if (begin >= end) return out;
    if (!mapped_) {
        out.push_back({begin, end});
        return out;
    }
    const auto page = page_size();
    const auto first_page = begin / page;
    const auto end_page = (end + page - 1) / page;
    const auto base_page = reinterpret_cast<std::uintptr_t>(data_) / page;   // mmap'd: page-aligned
    PagemapFile pagemap;
    std::uint64_t entries[512];
    for (auto p = first_page; p < end_page;) {
        const auto n = std::min<std::size_t>(std::size(entries), end_page - p);
        const auto offset = static_cast<off_t>((base_page + p) * sizeof(std::uint64_t));
        const auto got = pagemap.fd() < 0 ? -1 : ::pread(pagemap.fd(), entries, n * sizeof(std::uint64_t), offset);
        if (got != static_cast<ssize_t>(n * sizeof(std::uint64_t))) {
            // No answer: every page from here on counts as touched.
            append(out, std::max(begin, p * page), end);
            return out;
        }
        for (std::size_t k = 0; k < n; ++k)
            if (entries[k] & (kPresent | kSwapped))
                append(out, std::max(begin, (p + k) * page), std::min(end, (p + k + 1) * page));
        p += n;
    }
    return out;
}

bool ZeroPageArena::operator==(const ZeroPageArena& other) const {
    if (size_ != other.size_) return false;
    for (const auto& r : merge_ranges(touched(), other.touched()))
        if (std::memcmp(data_ + r.begin, other.data_ + r.begin, r.end - r.begin) != 0) return false;
    return true;
}

std::vector<ByteRange> merge_ranges(const std::vector<ByteRange>& a, const std::vector<ByteRange>& b) {
    std::vector<ByteRange> out;
    out.reserve(a.size() + b.size());
    std::size_t i = 0, j = 0;
    while (i < a.size() || j < b.size()) {
        const bool take_a = j == b.size() || (i < a.size() && a[i].begin <= b[j].begin);
        const auto& r = take_a ? a[i++] : b[j++];
        if (!out.empty() && r.begin <= out.back().end) out.back().end = std::max(out.back().end, r.end);
        else out.push_back(r);
    }
    return out;
}

}  // namespace slmp::devicemodel
