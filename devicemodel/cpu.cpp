#include "devicemodel/cpu.hpp"

#include <algorithm>

#include "devicemodel/drives.hpp"
#include "devicemodel/node.hpp"

namespace slmp::devicemodel {

namespace {

DeviceSizes only(Area area, std::uint32_t points) {
    DeviceSizes sizes{};
    sizes[static_cast<std::size_t>(area)] = points;
    return sizes;
}

}  // namespace

Cpu::Cpu(CpuProfile profile) : profile_(std::move(profile)), memory_(profile_.sizes) {
    if (profile_.station_buffer_words > 0)
        station_buffer_ = std::make_unique<DeviceMemory>(only(Area::G, profile_.station_buffer_words));
    publish_device_sizes();
    runtime_.configure({}, memory_);   // powered on with the default parameters
    drives_ = std::make_shared<DriveSet>(profile_.drives);   // in memory until configured
    node_ = std::make_shared<Node>();
}

Module* Cpu::module(std::uint16_t io_number) {
    auto it = modules_.find(io_number);
    return it == modules_.end() ? nullptr : it->second.get();
}

void Cpu::add_module(std::uint16_t io_number, std::string model, std::uint32_t buffer_words,
                     std::uint32_t head_address) {
    modules_[io_number] = std::make_unique<Module>(
        Module{std::move(model), head_address, DeviceMemory(only(Area::G, buffer_words), 0)});
}

DeviceMemory* Cpu::network(std::uint16_t number) {
    auto it = networks_.find(number);
    return it == networks_.end() ? nullptr : it->second.get();
}

void Cpu::add_network(std::uint16_t number, const DeviceSizes& sizes) {
    networks_[number] = std::make_unique<DeviceMemory>(sizes, 0);
}

bool Cpu::in_range(Area area, std::uint64_t start, std::uint64_t count) const {
    const auto& start_only = profile_.start_only_range_check;
    if (std::find(start_only.begin(), start_only.end(), area) != start_only.end())
        return count > 0 && start < memory_.size(area);
    return memory_.contains(area, start, count);
}

// Clients build their address catalogues from these registers
// (real-CPU measurements), so they must always match the configured sizes.
void Cpu::publish_device_sizes() {
    const auto* sd = find_by_symbol("SD");
    for (const auto& reg : profile_.size_registers) {
        auto points = profile_.size(reg.area);
        memory_.set_value(*sd, reg.sd, points & 0xFFFF);
        if (reg.bits == 32) memory_.set_value(*sd, reg.sd + 1u, points >> 16);
    }
}

}  // namespace slmp::devicemodel
