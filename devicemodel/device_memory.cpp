#include "devicemodel/device_memory.hpp"

#include <algorithm>
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
    for (std::size_t i = 0; i < stores_.size(); ++i) {
        auto area = static_cast<Area>(i);
        auto points = sizes[i];
        auto& s = stores_[i];
        if (area == Area::R) continue;  // lives in ZR
        if (area == Area::ZR) points = std::max(points, sizes[static_cast<std::size_t>(Area::R)]) + slack_words;
        // resize, not assign: calloc's pages are zero already (ZeroPages).
        if (is_bit_area(area)) {
            s.bits.resize(points);
        } else if (is_timer_or_counter(area)) {
            s.bits.resize(points);
            s.coils.resize(points);
            s.values.resize(points);
        } else {
            s.values.resize(points);
        }
    }
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
    if (observer_ && plane[number] != now) observer_->written(spec, number, 1);
    plane[number] = now;
}

void DeviceMemory::read_part(const DeviceSpec& spec, std::span<std::uint32_t> out) const {
    const auto& s = store(spec.area);
    if (spec.unit == Unit::Bit) {
        const auto& plane = spec.part == Part::Coil ? s.coils : s.bits;
        const auto n = std::min(out.size(), plane.size());
        for (std::size_t i = 0; i < n; ++i) out[i] = plane[i] != 0 ? 1 : 0;
        std::fill(out.begin() + static_cast<std::ptrdiff_t>(n), out.end(), 0);
        return;
    }
    const auto n = std::min(out.size(), s.values.size());
    const std::uint32_t mask = spec.unit == Unit::Word ? 0xFFFF : 0xFFFFFFFF;
    for (std::size_t i = 0; i < n; ++i) out[i] = s.values[i] & mask;
    std::fill(out.begin() + static_cast<std::ptrdiff_t>(n), out.end(), 0);
}

void DeviceMemory::write_part(const DeviceSpec& spec, std::span<const std::uint32_t> in) {
    auto& s = store(spec.area);
    if (spec.unit == Unit::Bit) {
        auto& plane = spec.part == Part::Coil ? s.coils : s.bits;
        const auto n = std::min(in.size(), plane.size());
        for (std::size_t i = 0; i < n; ++i) {
            const std::uint8_t now = in[i] != 0 ? 1 : 0;
            if (plane[i] == now) continue;
            if (observer_) observer_->written(spec, static_cast<std::uint32_t>(i), 1);
            plane[i] = now;
        }
        return;
    }
    const auto n = std::min(in.size(), s.values.size());
    const std::uint32_t mask = spec.unit == Unit::Word ? 0xFFFF : 0xFFFFFFFF;
    for (std::size_t i = 0; i < n; ++i) {
        const auto now = in[i] & mask;
        if (s.values[i] == now) continue;
        if (observer_) observer_->written(spec, static_cast<std::uint32_t>(i), 1);
        s.values[i] = now;
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
    if (observer_ && values[number] != now) observer_->written(spec, number, 1);
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
