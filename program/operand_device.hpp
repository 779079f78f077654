// The one device an operand names, parsed as the compiler parses it ("X0",
// "D100", "D0.F", "T0"), for code outside the engine that shows or checks a
// program's devices (the HTTP API's monitor, the station's coil check).
#pragma once

#include <cstdint>
#include <optional>
#include <string_view>

#include "devicemodel/device_table.hpp"

namespace slmp::program {

// `spec` is null for a timer or counter written without a part letter
// (contact, coil or value by use); `bit` is -1 unless a bit of a word.
struct OperandDevice {
    const devicemodel::DeviceSpec* spec = nullptr;
    devicemodel::Area area = devicemodel::Area::D;
    std::uint32_t number = 0;
    int bit = -1;
};
// nullopt for constants, digit designations and indexed operands, which name
// no single device, and for text that is no operand.
std::optional<OperandDevice> operand_device(std::string_view text, devicemodel::Numbering numbering);

}  // namespace slmp::program
