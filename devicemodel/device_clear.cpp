#include "devicemodel/device_clear.hpp"

#include <algorithm>

namespace slmp::devicemodel {

bool LatchMap::latched(Area area, std::uint32_t number) const {
    if (area == Area::L || area == Area::R || area == Area::ZR) return true;
    for (const auto& r : ranges_)
        if (r.area == area && number >= r.first && number - r.first < r.count) return true;
    return false;
}

bool clearable(Area area) {
    return area != Area::X && area != Area::R && area != Area::ZR && area != Area::SM && area != Area::SD;
}

std::vector<const DeviceSpec*> stored_parts(Area area) {
    std::vector<const DeviceSpec*> parts;
    for (const auto& spec : all_devices()) {
        if (spec.area != area) continue;
        bool seen = false;
        for (const auto* p : parts) seen = seen || p->part == spec.part;
        if (!seen) parts.push_back(&spec);   // X before DX: the first row of a part wins
    }
    return parts;
}

void clear_devices(DeviceMemory& memory, const LatchMap& latch, ClearScope scope) {
    for (std::size_t i = 0; i < static_cast<std::size_t>(Area::Count); ++i) {
        auto area = static_cast<Area>(i);
        if (!clearable(area)) continue;
        auto size = memory.size(area);
        // Only where a value may be non-zero: an idle CPU's clear (Remote
        // RESET, a RUN with clear mode) reads none of its untouched pages.
        for (const auto* part : stored_parts(area))
            for (const auto& range : memory.possibly_nonzero(*part))
                for (auto n = range.first; n < std::min(range.end, size); ++n) {
                    if (scope == ClearScope::NonLatched && latch.latched(area, n)) continue;
                    memory.set_value(*part, n, 0);
                }
    }
}

}  // namespace slmp::devicemodel
