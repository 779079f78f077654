// Reading the project's little-endian binary files (device snapshots, station
// snapshot files, the front ends' unit state) from bytes that may be damaged or
// cut short: every read says when the bytes ran out instead of reading past
// them, and the caller decides what that means for its file.
#pragma once

#include <cstddef>
#include <cstdint>
#include <optional>
#include <span>
#include <string>

namespace slmp::devicemodel {

class ByteReader {
public:
    explicit ByteReader(std::span<const std::uint8_t> in) : in_(in) {}

    std::optional<std::uint8_t> u8() {
        if (pos_ >= in_.size()) return std::nullopt;
        return in_[pos_++];
    }
    std::optional<std::uint32_t> u32() {
        if (in_.size() - pos_ < 4) return std::nullopt;
        std::uint32_t v = 0;
        for (std::size_t i = 0; i < 4; ++i) v |= std::uint32_t{in_[pos_ + i]} << (8 * i);
        pos_ += 4;
        return v;
    }
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
    std::span<const std::uint8_t> in_;
    std::size_t pos_ = 0;
};

}  // namespace slmp::devicemodel
