// Which devices survive what: the latch rules used by Remote RUN's clear modes,
// Remote Latch Clear, Remote RESET, power-on and snapshot restore.
//
// - L (latch relay) is always latched; file registers R/ZR live in
//   battery-backed memory and are never cleared by these operations.
// - Configured latch ranges (any area) are latched.
// - X is the field's input state, not program memory: it is never cleared.
// - SM/SD belong to the system and are rebuilt by the runtime, not cleared here.
#pragma once

#include <cstdint>
#include <span>
#include <vector>

#include "devicemodel/device_memory.hpp"
#include "devicemodel/device_table.hpp"
#include "devicemodel/runtime_config.hpp"

namespace slmp::devicemodel {

class LatchMap {
public:
    explicit LatchMap(std::span<const LatchRange> ranges = {}) : ranges_(ranges.begin(), ranges.end()) {}
    bool latched(Area area, std::uint32_t number) const;

private:
    std::vector<LatchRange> ranges_;
};

// Areas the device clears may touch (everything but X, R, ZR, SM and SD).
bool clearable(Area area);

// Every stored part of an area: the plain device, or contact, coil and value.
std::vector<const DeviceSpec*> stored_parts(Area area);

enum class ClearScope : std::uint8_t {
    NonLatched,   // Remote RUN clear mode 01, power-on, Remote RESET
    All,          // Remote RUN clear mode 02, Remote Latch Clear
};
void clear_devices(DeviceMemory& memory, const LatchMap& latch, ClearScope scope);

}  // namespace slmp::devicemodel
