// Operand text of docs/program.md "Operands" parsed into its parts, before the compiler
// resolves it against an instruction's operand type and the profile's sizes
// (docs/program.md "Operands").
#pragma once

#include <cstdint>
#include <optional>
#include <string>
#include <string_view>

#include "devicemodel/device_table.hpp"

namespace slmp::program::detail {

struct ParsedOperand {
    enum class Kind : std::uint8_t { Device, Digits, Integer, Real, String, Pointer, Nesting };
    Kind kind = Kind::Device;
    // Device and Digits: the device. `spec` is null for T, ST, C, LT, LST, LC
    // written without a part letter ("T0"): contact, coil or value by use.
    const devicemodel::DeviceSpec* spec = nullptr;
    devicemodel::Area area = devicemodel::Area::D;
    std::uint32_t number = 0;
    std::uint8_t digits = 0;          // Digits: n of Kn
    int bit = -1;                     // D0.F: 15
    std::uint8_t index = 0xFF;        // Z/LZ register, 0xFF none
    bool index_long = false;
    std::int64_t integer = 0;         // Integer (K, H), Pointer, Nesting
    bool hex = false;                 // Integer written with H
    float real = 0;                   // Real (E)
    std::string text;                 // String: the characters
};

bool is_timer_or_counter(devicemodel::Area area);

// Parses one operand; on failure returns nullopt with `error` naming the problem.
std::optional<ParsedOperand> parse_operand(std::string_view text, devicemodel::Numbering numbering, std::string& error);

}  // namespace slmp::program::detail
