#include "devicemodel/cpu.hpp"

#include <algorithm>

namespace slmp::devicemodel {

Cpu::Cpu(CpuProfile profile) : profile_(std::move(profile)), memory_(profile_.sizes) { publish_device_sizes(); }

bool Cpu::in_range(Area area, std::uint64_t start, std::uint64_t count) const {
    const auto& start_only = profile_.start_only_range_check;
    if (std::find(start_only.begin(), start_only.end(), area) != start_only.end())
        return count > 0 && start < memory_.size(area);
    return memory_.contains(area, start, count);
}

// Clients build their address catalogues from these registers
// (hardware-behaviour.md §6), so they must always match the configured sizes.
void Cpu::publish_device_sizes() {
    const auto* sd = find_by_symbol("SD");
    for (const auto& reg : profile_.size_registers) {
        auto points = profile_.size(reg.area);
        memory_.set_value(*sd, reg.sd, points & 0xFFFF);
        if (reg.bits == 32) memory_.set_value(*sd, reg.sd + 1u, points >> 16);
    }
}

}  // namespace slmp::devicemodel
