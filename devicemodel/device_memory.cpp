#include "devicemodel/device_memory.hpp"

#include <algorithm>
#include <type_traits>
#include <utility>

namespace slmp::devicemodel {
namespace {

bool is_timer_or_counter(Area area) {
    return area == Area::T || area == Area::ST || area == Area::C || area == Area::LT ||
           area == Area::LST || area == Area::LC;
}

bool is_bit_area(Area area) { return area <= Area::SM; }

}  // namespace

DeviceMemory::DeviceMemory(const DeviceSizes& sizes, std::uint32_t slack_words)
    : sizes_(sizes), stores_(static_cast<std::size_t>(Area::Count)) {
    // Two passes over the same layout: the first adds up the bytes, the second
    // (once the arena exists) hands each store its slice. Slices start on a
    // cache line; every store's pages are zero until written.
    struct Points {
        std::uint32_t bits = 0, coils = 0, values = 0;
    };
    std::vector<Points> points(stores_.size());
    for (std::size_t i = 0; i < stores_.size(); ++i) {
        auto area = static_cast<Area>(i);
        auto n = sizes[i];
        if (area == Area::R) continue;  // lives in ZR
        if (area == Area::ZR) n = std::max(n, sizes[static_cast<std::size_t>(Area::R)]) + slack_words;
        if (is_bit_area(area)) points[i] = {n, 0, 0};
        else if (is_timer_or_counter(area)) points[i] = {n, n, n};
        else points[i] = {0, 0, n};
    }
    auto lay_out = [&](auto&& place) {
        std::size_t offset = 0;
        auto slice = [&](std::uint32_t n, std::size_t element) {
            const auto at = offset;
            if (n > 0) offset = (offset + std::size_t{n} * element + 63) / 64 * 64;
            return at;
        };
        for (std::size_t i = 0; i < stores_.size(); ++i) {
            const auto bits = slice(points[i].bits, 1);
            const auto coils = slice(points[i].coils, 1);
            const auto values = slice(points[i].values, sizeof(std::uint32_t));
            place(i, bits, coils, values);
        }
        return offset;
    };
    arena_ = ZeroPageArena(lay_out([](auto...) {}));
    lay_out([&](std::size_t i, std::size_t bits, std::size_t coils, std::size_t values) {
        auto* base = arena_.data();
        auto& s = stores_[i];
        if (points[i].bits) s.bits = {reinterpret_cast<std::uint8_t*>(base + bits), points[i].bits};
        if (points[i].coils) s.coils = {reinterpret_cast<std::uint8_t*>(base + coils), points[i].coils};
        if (points[i].values) s.values = {reinterpret_cast<std::uint32_t*>(base + values), points[i].values};
    });
}

namespace {

// The same slice of another arena (a copy's).
template <class T>
std::span<T> rebased(std::span<T> plane, const std::byte* from, std::byte* to) {
    if (plane.empty()) return {};
    const auto offset = reinterpret_cast<const std::byte*>(plane.data()) - from;
    return {reinterpret_cast<T*>(to + offset), plane.size()};
}

}  // namespace

DeviceMemory::DeviceMemory(const DeviceMemory& other)
    : sizes_(other.sizes_), arena_(other.arena_), stores_(other.stores_), label_area_(other.label_area_),
      observer_(other.observer_) {
    for (auto& s : stores_) {
        s.bits = rebased(s.bits, other.arena_.data(), arena_.data());
        s.coils = rebased(s.coils, other.arena_.data(), arena_.data());
        s.values = rebased(s.values, other.arena_.data(), arena_.data());
    }
}

DeviceMemory& DeviceMemory::operator=(const DeviceMemory& other) {
    if (this != &other) *this = DeviceMemory(other);
    return *this;
}

bool DeviceMemory::operator==(const DeviceMemory& other) const {
    if (sizes_ != other.sizes_ || label_area_ != other.label_area_ || stores_.size() != other.stores_.size())
        return false;
    // The same sizes but another slack would lay the arena out differently.
    for (std::size_t i = 0; i < stores_.size(); ++i) {
        const auto& a = stores_[i];
        const auto& b = other.stores_[i];
        if (a.bits.size() != b.bits.size() || a.coils.size() != b.coils.size() || a.values.size() != b.values.size())
            return false;
    }
    return arena_ == other.arena_;
}

std::vector<DeviceRange> DeviceMemory::possibly_nonzero(const DeviceSpec& spec) const {
    return nonzero_in_pages(spec, nullptr);
}

std::vector<DeviceRange> DeviceMemory::possibly_nonzero(const DeviceSpec& spec, const std::vector<ByteRange>& touched_pages) const {
    return nonzero_in_pages(spec, &touched_pages);
}

// touched_pages: the arena's, or nullptr to ask the arena for the part's pages only.
std::vector<DeviceRange> DeviceMemory::nonzero_in_pages(const DeviceSpec& spec, const std::vector<ByteRange>* touched_pages) const {
    const auto& s = store(spec.area);
    const auto* base = arena_.data();
    auto devices = [&](const auto& plane) {
        std::vector<DeviceRange> out;
        if (plane.empty()) return out;
        using T = typename std::remove_reference_t<decltype(plane)>::value_type;
        const auto begin = static_cast<std::size_t>(reinterpret_cast<const std::byte*>(plane.data()) - base);
        const auto end = begin + plane.size_bytes();
        auto add = [&](ByteRange r) {
            r.begin = std::max(r.begin, begin);
            r.end = std::min(r.end, end);
            if (r.begin >= r.end) return;
            const auto first = static_cast<std::uint32_t>((r.begin - begin) / sizeof(T));
            const auto last = static_cast<std::uint32_t>((r.end - begin + sizeof(T) - 1) / sizeof(T));
            if (!out.empty() && out.back().end >= first) out.back().end = std::max(out.back().end, last);
            else out.push_back({first, last});
        };
        if (!touched_pages) {
            for (const auto& r : arena_.touched(begin, end)) add(r);
            return out;
        }
        const auto& pages = *touched_pages;
        auto it = std::lower_bound(pages.begin(), pages.end(), begin, [](const ByteRange& r, std::size_t at) { return r.end <= at; });
        for (; it != pages.end() && it->begin < end; ++it) add(*it);
        return out;
    };
    if (spec.unit == Unit::Bit) return devices(spec.part == Part::Coil ? s.coils : s.bits);
    return devices(s.values);
}

DeviceMemory::Store& DeviceMemory::store(Area area) { return stores_[static_cast<std::size_t>(storage_area(area))]; }
const DeviceMemory::Store& DeviceMemory::store(Area area) const {
    return stores_[static_cast<std::size_t>(storage_area(area))];
}

bool DeviceMemory::contains(Area area, std::uint64_t start, std::uint64_t count) const {
    return start + count <= size(area);
}

bool DeviceMemory::bit(const DeviceSpec& spec, std::uint32_t number) const {
    const auto& s = store(spec.area);
    const auto& plane = spec.part == Part::Coil ? s.coils : s.bits;
    return number < plane.size() && plane[number] != 0;
}

void DeviceMemory::set_bit(const DeviceSpec& spec, std::uint32_t number, bool on) {
    auto& s = store(spec.area);
    auto& plane = spec.part == Part::Coil ? s.coils : s.bits;
    if (number >= plane.size()) return;
    std::uint8_t now = on ? 1 : 0;
    // Not written when unchanged: a clear of an untouched page must not dirty it.
    if (plane[number] == now) return;
    if (observer_) observer_->written(spec, number, 1);
    plane[number] = now;
}

void DeviceMemory::read_part(const DeviceSpec& spec, std::uint32_t first, std::span<std::uint32_t> out) const {
    const auto& s = store(spec.area);
    if (spec.unit == Unit::Bit) {
        const auto& plane = spec.part == Part::Coil ? s.coils : s.bits;
        const auto n = first < plane.size() ? std::min(out.size(), plane.size() - first) : 0;
        for (std::size_t i = 0; i < n; ++i) out[i] = plane[first + i] != 0 ? 1 : 0;
        std::fill(out.begin() + static_cast<std::ptrdiff_t>(n), out.end(), 0);
        return;
    }
    const auto n = first < s.values.size() ? std::min(out.size(), s.values.size() - first) : 0;
    const std::uint32_t mask = spec.unit == Unit::Word ? 0xFFFF : 0xFFFFFFFF;
    for (std::size_t i = 0; i < n; ++i) out[i] = s.values[first + i] & mask;
    std::fill(out.begin() + static_cast<std::ptrdiff_t>(n), out.end(), 0);
}

void DeviceMemory::write_part(const DeviceSpec& spec, std::uint32_t first, std::span<const std::uint32_t> in) {
    auto& s = store(spec.area);
    if (spec.unit == Unit::Bit) {
        auto& plane = spec.part == Part::Coil ? s.coils : s.bits;
        const auto n = first < plane.size() ? std::min(in.size(), plane.size() - first) : 0;
        for (std::size_t i = 0; i < n; ++i) {
            const std::uint8_t now = in[i] != 0 ? 1 : 0;
            const auto number = first + i;
            if (plane[number] == now) continue;
            if (observer_) observer_->written(spec, static_cast<std::uint32_t>(number), 1);
            plane[number] = now;
        }
        return;
    }
    const auto n = first < s.values.size() ? std::min(in.size(), s.values.size() - first) : 0;
    const std::uint32_t mask = spec.unit == Unit::Word ? 0xFFFF : 0xFFFFFFFF;
    for (std::size_t i = 0; i < n; ++i) {
        const auto now = in[i] & mask;
        const auto number = first + i;
        if (s.values[number] == now) continue;
        if (observer_) observer_->written(spec, static_cast<std::uint32_t>(number), 1);
        s.values[number] = now;
    }
}

std::uint32_t DeviceMemory::value(const DeviceSpec& spec, std::uint32_t number) const {
    if (spec.unit == Unit::Bit) return bit(spec, number) ? 1 : 0;
    const auto& values = store(spec.area).values;
    if (number >= values.size()) return 0;
    return spec.unit == Unit::Word ? values[number] & 0xFFFF : values[number];
}

void DeviceMemory::set_value(const DeviceSpec& spec, std::uint32_t number, std::uint32_t value) {
    if (spec.unit == Unit::Bit) return set_bit(spec, number, value != 0);
    auto& values = store(spec.area).values;
    if (number >= values.size()) return;
    auto now = spec.unit == Unit::Word ? value & 0xFFFF : value;
    if (values[number] == now) return;   // as set_bit: an unchanged page stays clean
    if (observer_) observer_->written(spec, number, 1);
    values[number] = now;
}

void DeviceMemory::read_words(const DeviceSpec& spec, std::uint32_t start, std::span<std::uint16_t> out) const {
    if (spec.unit == Unit::Bit) {
        for (std::size_t i = 0; i < out.size(); ++i) {
            std::uint16_t word = 0;
            for (unsigned b = 0; b < 16; ++b)
                if (bit(spec, start + static_cast<std::uint32_t>(i * 16 + b))) word |= static_cast<std::uint16_t>(1u << b);
            out[i] = word;
        }
        return;
    }
    if (spec.unit == Unit::Word) {
        // The bulk path of a 960-word read: straight from the store, one bounds
        // check for the whole read; words past the store read 0.
        const auto& values = store(spec.area).values;
        const std::size_t stored = start < values.size() ? std::min(out.size(), values.size() - start) : 0;
        std::size_t i = 0;
        for (; i + 16 <= stored; i += 16)   // blocks of a fixed size: vectorised at -O2 too
            for (std::size_t k = 0; k < 16; ++k) out[i + k] = static_cast<std::uint16_t>(values[start + i + k]);
        for (; i < stored; ++i) out[i] = static_cast<std::uint16_t>(values[start + i]);
        std::fill(out.begin() + static_cast<std::ptrdiff_t>(stored), out.end(), std::uint16_t{0});
        return;
    }
    const auto per_device = words_per_device(spec);
    const auto& s = store(spec.area);
    for (std::size_t i = 0; i < out.size(); ++i) {
        auto number = start + static_cast<std::uint32_t>(i / per_device);
        auto v = value(spec, number);
        switch (i % per_device) {
            case 0: out[i] = static_cast<std::uint16_t>(v); break;
            case 1: out[i] = static_cast<std::uint16_t>(v >> 16); break;
            case 2:  // status word of a long timer: b0 coil, b1 contact
                out[i] = static_cast<std::uint16_t>((number < s.coils.size() && s.coils[number] ? 1 : 0) |
                                                    (number < s.bits.size() && s.bits[number] ? 2 : 0));
                break;
            default: out[i] = 0; break;  // system word
        }
    }
}

void DeviceMemory::write_words(const DeviceSpec& spec, std::uint32_t start, std::span<const std::uint16_t> in) {
    if (spec.unit == Unit::Bit) {
        for (std::size_t i = 0; i < in.size(); ++i)
            for (unsigned b = 0; b < 16; ++b)
                set_bit(spec, start + static_cast<std::uint32_t>(i * 16 + b), (in[i] >> b) & 1u);
        return;
    }
    if (spec.unit == Unit::Word) {
        for (std::size_t i = 0; i < in.size(); ++i) set_value(spec, start + static_cast<std::uint32_t>(i), in[i]);
        return;
    }
    const auto per_device = words_per_device(spec);
    auto& s = store(spec.area);
    for (std::size_t i = 0; i < in.size(); ++i) {
        auto number = start + static_cast<std::uint32_t>(i / per_device);
        if (number >= s.values.size()) continue;
        auto& v = s.values[number];
        // LTN/LSTN carry a status word (coil, contact); LCN and LZ do not.
        auto status = [&] { return per_device == 4 ? s.coils[number] | s.bits[number] << 1 : 0; };
        const auto before = std::pair(v, status());
        switch (i % per_device) {
            case 0: v = (v & 0xFFFF0000u) | in[i]; break;
            case 1: v = (v & 0x0000FFFFu) | (std::uint32_t{in[i]} << 16); break;
            case 2:
                s.coils[number] = in[i] & 1u;
                s.bits[number] = (in[i] >> 1) & 1u;
                break;
            default: break;  // system word: not stored
        }
        if (observer_ && before != std::pair(v, status())) observer_->written(spec, number, 1);
    }
}

}  // namespace slmp::devicemodel
