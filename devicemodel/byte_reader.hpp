// The project's little-endian binary files (device snapshots, station snapshot
// files, the front ends' unit state, a program's saved state): one reader and
// one writer. The reader takes bytes that may be damaged or cut short: every
// read says when the bytes ran out instead of reading past them, and the
// caller decides what that means for its file.
#pragma once

#include <cstddef>
#include <cstdint>
#include <optional>
#include <span>
#include <string>
#include <string_view>
#include <vector>

namespace slmp::devicemodel {

class ByteReader {
public:
    explicit ByteReader(std::span<const std::uint8_t> in) : in_(in) {}

    std::optional<std::uint8_t> u8() {
        if (pos_ >= in_.size()) return std::nullopt;
        return in_[pos_++];
    }
    std::optional<std::uint32_t> u32() { return little_endian<std::uint32_t>(); }
    std::optional<std::uint64_t> u64() { return little_endian<std::uint64_t>(); }
    // The next n bytes.
    std::optional<std::span<const std::uint8_t>> bytes(std::size_t n) {
        if (in_.size() - pos_ < n) return std::nullopt;
        auto out = in_.subspan(pos_, n);
        pos_ += n;
        return out;
    }
    // A name as the files write it: u8 length, then its bytes.
    std::optional<std::string> name() {
        auto n = u8();
        if (!n) return std::nullopt;
        auto text = bytes(*n);
        if (!text) return std::nullopt;
        return std::string(text->begin(), text->end());
    }
    bool done() const { return pos_ == in_.size(); }

private:
    template <class T>
    std::optional<T> little_endian() {
        if (in_.size() - pos_ < sizeof(T)) return std::nullopt;
        T v = 0;
        for (std::size_t i = 0; i < sizeof(T); ++i) v |= T{in_[pos_ + i]} << (8 * i);
        pos_ += sizeof(T);
        return v;
    }

    std::span<const std::uint8_t> in_;
    std::size_t pos_ = 0;
};

// Writes what ByteReader reads, into `out`.
class ByteWriter {
public:
    void u8(std::uint8_t v) { out.push_back(v); }
    void u32(std::uint32_t v) { little_endian(v); }
    void u64(std::uint64_t v) { little_endian(v); }
    // Sets the u32 written at `at` (a count known only later).
    void u32_at(std::size_t at, std::uint32_t v) {
        for (std::size_t i = 0; i < 4; ++i) out[at + i] = static_cast<std::uint8_t>(v >> (8 * i));
    }
    void bytes(std::span<const std::uint8_t> b) { out.insert(out.end(), b.begin(), b.end()); }
    // A name as the files write it: u8 length, then its bytes.
    void name(std::string_view s) {
        u8(static_cast<std::uint8_t>(s.size()));
        out.insert(out.end(), s.begin(), s.end());
    }

    std::vector<std::uint8_t> out;

private:
    template <class T>
    void little_endian(T v) {
        for (std::size_t i = 0; i < sizeof(T); ++i) out.push_back(static_cast<std::uint8_t>(v >> (8 * i)));
    }
};

}  // namespace slmp::devicemodel
