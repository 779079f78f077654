// Numbers in and out of device memory the way a PLC program stores them: a
// bit is 0/1, a word a 16-bit value (signed or not), a 32-bit value two words
// low first, a float an IEEE single in two words. Used by the timeline,
// triggers and actions, so they all agree on what "D100 = 50.5" means.
#pragma once

#include <cstdint>

#include "devicemodel/device_memory.hpp"
#include "scenarios/scenario.hpp"

namespace slmp::scenarios {

// A bound label (DeviceRef::bound) is read and written through its element.
// Rounds to the nearest integer and saturates to what the format can hold
// (Int16: -32768..65535, so both signed and unsigned words can be written).
void write_number(devicemodel::DeviceMemory& memory, const DeviceRef& device, double value);
// Int16 reads as signed (-32768..32767), as the CPU's compare instructions do.
double read_number(const devicemodel::DeviceMemory& memory, const DeviceRef& device);

// How many devices a value of this format occupies (bits: 1, words: 1 or 2).
std::uint32_t devices_per_value(const DeviceRef& device);

// Whether devices [number, number + count) exist in `memory`.
bool fits(const devicemodel::DeviceMemory& memory, const devicemodel::DeviceAddress& address, std::uint32_t count);

// Whether two ranges of the same area overlap.
bool overlaps(const DeviceRange& a, const DeviceRange& b);

}  // namespace slmp::scenarios
