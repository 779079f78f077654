#include "scenarios/device_values.hpp"

#include <algorithm>
#include <bit>
#include <cmath>

namespace slmp::scenarios {

using devicemodel::Unit;

std::uint32_t devices_per_value(const DeviceRef& device) {
    if (!device.label.empty()) return 1;   // a label: its own size, checked when it was declared
    if (device.address.spec->unit != Unit::Word) return 1;
    return device.format == ValueFormat::Int16 ? 1 : 2;
}

namespace {

std::uint32_t saturated_int32(double value) {
    return static_cast<std::uint32_t>(static_cast<std::int64_t>(std::clamp(std::round(value), -2147483648.0, 4294967295.0)));
}

// A label stores its value in words as the label commands carry it (low word
// first); devicemodel's element access finds those words wherever they live.
void write_label(devicemodel::DeviceMemory& memory, const devicemodel::LabelRef& label, ValueFormat format, double value) {
    std::uint32_t v = 0;
    std::size_t words = 2;
    if (label.basic == devicemodel::BasicType::Bit) {
        v = value != 0, words = 1;
    } else if (format == ValueFormat::Int16) {
        v = static_cast<std::uint16_t>(static_cast<std::int32_t>(std::clamp(std::round(value), -32768.0, 65535.0))), words = 1;
    } else {
        v = format == ValueFormat::Float32 ? std::bit_cast<std::uint32_t>(static_cast<float>(value)) : saturated_int32(value);
    }
    const std::uint16_t data[2] = {static_cast<std::uint16_t>(v & 0xFFFF), static_cast<std::uint16_t>(v >> 16)};
    devicemodel::write_element(memory, label, 0, std::span(data, words));
}

double read_label(const devicemodel::DeviceMemory& memory, const devicemodel::LabelRef& label, ValueFormat format) {
    auto data = devicemodel::read_element(memory, label, 0);
    const std::uint32_t v = (data.empty() ? 0u : data[0]) | (data.size() > 1 ? std::uint32_t(data[1]) << 16 : 0u);
    if (label.basic == devicemodel::BasicType::Bit) return v & 1;
    switch (format) {
        case ValueFormat::Int16: return static_cast<std::int16_t>(v & 0xFFFF);
        case ValueFormat::Int32: return static_cast<std::int32_t>(v);
        case ValueFormat::Float32: return std::bit_cast<float>(v);
    }
    return 0;
}

}  // namespace

void write_number(devicemodel::DeviceMemory& memory, const DeviceRef& device, double value) {
    if (device.bound) return write_label(memory, *device.bound, device.format, value);
    const auto& spec = *device.address.spec;
    const auto n = device.address.number;
    if (spec.unit == Unit::Bit) {
        memory.set_bit(spec, n, value != 0);
        return;
    }
    if (spec.unit == Unit::DoubleWord) {   // LZ: one 32-bit device
        memory.set_value(spec, n, saturated_int32(value));
        return;
    }
    switch (device.format) {
        case ValueFormat::Int16:
            memory.set_value(spec, n, static_cast<std::uint16_t>(static_cast<std::int32_t>(std::clamp(std::round(value), -32768.0, 65535.0))));
            return;
        case ValueFormat::Int32: {
            auto v = saturated_int32(value);
            memory.set_value(spec, n, v & 0xFFFF);
            memory.set_value(spec, n + 1, v >> 16);
            return;
        }
        case ValueFormat::Float32: {
            auto v = std::bit_cast<std::uint32_t>(static_cast<float>(value));
            memory.set_value(spec, n, v & 0xFFFF);
            memory.set_value(spec, n + 1, v >> 16);
            return;
        }
    }
}

double read_number(const devicemodel::DeviceMemory& memory, const DeviceRef& device) {
    if (device.bound) return read_label(memory, *device.bound, device.format);
    const auto& spec = *device.address.spec;
    const auto n = device.address.number;
    if (spec.unit == Unit::Bit) return memory.bit(spec, n) ? 1 : 0;
    if (spec.unit == Unit::DoubleWord) return static_cast<std::int32_t>(memory.value(spec, n));
    switch (device.format) {
        case ValueFormat::Int16: return static_cast<std::int16_t>(memory.value(spec, n) & 0xFFFF);
        case ValueFormat::Int32:
            return static_cast<std::int32_t>((memory.value(spec, n) & 0xFFFF) | (memory.value(spec, n + 1) & 0xFFFF) << 16);
        case ValueFormat::Float32:
            return std::bit_cast<float>(static_cast<std::uint32_t>((memory.value(spec, n) & 0xFFFF) |
                                                                   (memory.value(spec, n + 1) & 0xFFFF) << 16));
    }
    return 0;
}

bool fits(const devicemodel::DeviceMemory& memory, const devicemodel::DeviceAddress& address, std::uint32_t count) {
    return memory.contains(address.spec->area, address.number, count);
}

bool overlaps(const DeviceRange& a, const DeviceRange& b) {
    return a.area == b.area && a.first <= b.last && b.first <= a.last;
}

}  // namespace slmp::scenarios
