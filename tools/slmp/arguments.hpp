// Turning command-line words into devices and values. Every address goes
// through devicemodel::parse_address (the one device table); every failure is a
// UsageError whose message names the bad word and the accepted form.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "devicemodel/device_table.hpp"

namespace slmp::cli {

// `numbering`: the target's (--octal-xy, or an iQ-F station found by --plant-station).
devicemodel::DeviceAddress parse_device(const std::string& text, devicemodel::Numbering numbering);
// A point count for 0401/1401: 1..65535 (the PLC enforces its own, lower limit
// and answers with its end code, which is what a user testing a PLC wants to see).
std::uint16_t parse_points(const std::string& text);
// A word: -32768..65535, or 0x0000..0xFFFF.
std::uint16_t parse_word(const std::string& text);
// A double word: -2147483648..4294967295, or 0x0..0xFFFFFFFF.
std::uint32_t parse_dword(const std::string& text);
// A bit: 0 or 1 (also on/off).
bool parse_bit(const std::string& text);

// "D100=5" -> {"D100", "5"}.
struct Assignment {
    std::string device;
    std::string value;
};
Assignment parse_assignment(const std::string& text);

// "D100" or "D100-D119" (inclusive, same device) -> start and points.
struct DeviceRange {
    devicemodel::DeviceAddress start;
    std::uint32_t points = 1;
};
DeviceRange parse_range(const std::string& text, devicemodel::Numbering numbering);

bool is_bit_device(const devicemodel::DeviceAddress& device);

// Names for the values of a read starting at `start`: bit units name every
// device; word units name one word each (a bit device's word covers 16 bits:
// M0, M16 ...; a 4-word LTN is LTN0, LTN0+1, ...).
std::vector<std::string> value_labels(const devicemodel::DeviceAddress& start, std::size_t count, bool bit_units,
                                      devicemodel::Numbering numbering);

// Cells for one word value: unsigned decimal, signed decimal, hex.
std::string word_hex(std::uint32_t value, int digits);

}  // namespace slmp::cli
