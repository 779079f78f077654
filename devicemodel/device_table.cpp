#include "devicemodel/device_table.hpp"
#include "devicemodel/device_parts.hpp"

#include <algorithm>
#include <array>
#include <cctype>
#include <charconv>

namespace slmp::devicemodel {
namespace {

using enum Area;
using enum Part;
using enum Unit;
using enum Radix;

// ZR: both manual editions mark it hexadecimal, but iQ-R CPUs and GX Works number
// it in decimal (real-CPU measurements); decimal is the default here and a
// profile may switch its ASCII wire form to hex.
constexpr std::array kDevices = {
    DeviceSpec{"SM", 0x0091, 0x91, "SM", SM, Plain, Bit, Dec, "special relay"},
    DeviceSpec{"SD", 0x00A9, 0xA9, "SD", SD, Plain, Word, Dec, "special register"},
    DeviceSpec{"X", 0x009C, 0x9C, "X*", X, Plain, Bit, Hex, "input"},
    DeviceSpec{"Y", 0x009D, 0x9D, "Y*", Y, Plain, Bit, Hex, "output"},
    DeviceSpec{"M", 0x0090, 0x90, "M*", M, Plain, Bit, Dec, "internal relay"},
    DeviceSpec{"L", 0x0092, 0x92, "L*", L, Plain, Bit, Dec, "latch relay"},
    DeviceSpec{"F", 0x0093, 0x93, "F*", F, Plain, Bit, Dec, "annunciator"},
    DeviceSpec{"V", 0x0094, 0x94, "V*", V, Plain, Bit, Dec, "edge relay"},
    DeviceSpec{"B", 0x00A0, 0xA0, "B*", B, Plain, Bit, Hex, "link relay"},
    DeviceSpec{"S", 0x0098, 0x98, "S*", S, Plain, Bit, Dec, "step relay"},
    DeviceSpec{"D", 0x00A8, 0xA8, "D*", D, Plain, Word, Dec, "data register"},
    DeviceSpec{"W", 0x00B4, 0xB4, "W*", W, Plain, Word, Hex, "link register"},
    DeviceSpec{"TS", 0x00C1, 0xC1, "TS", T, Contact, Bit, Dec, "timer contact"},
    DeviceSpec{"TC", 0x00C0, 0xC0, "TC", T, Coil, Bit, Dec, "timer coil"},
    DeviceSpec{"TN", 0x00C2, 0xC2, "TN", T, Value, Word, Dec, "timer current value"},
    DeviceSpec{"LTS", 0x0051, -1, "", LT, Contact, Bit, Dec, "long timer contact"},
    DeviceSpec{"LTC", 0x0050, -1, "", LT, Coil, Bit, Dec, "long timer coil"},
    DeviceSpec{"LTN", 0x0052, -1, "", LT, Value, DoubleWord, Dec, "long timer current value"},
    DeviceSpec{"STS", 0x00C7, 0xC7, "SS", ST, Contact, Bit, Dec, "retentive timer contact"},
    DeviceSpec{"STC", 0x00C6, 0xC6, "SC", ST, Coil, Bit, Dec, "retentive timer coil"},
    DeviceSpec{"STN", 0x00C8, 0xC8, "SN", ST, Value, Word, Dec, "retentive timer current value"},
    DeviceSpec{"LSTS", 0x0059, -1, "", LST, Contact, Bit, Dec, "long retentive timer contact"},
    DeviceSpec{"LSTC", 0x0058, -1, "", LST, Coil, Bit, Dec, "long retentive timer coil"},
    DeviceSpec{"LSTN", 0x005A, -1, "", LST, Value, DoubleWord, Dec, "long retentive timer current value"},
    DeviceSpec{"CS", 0x00C4, 0xC4, "CS", C, Contact, Bit, Dec, "counter contact"},
    DeviceSpec{"CC", 0x00C3, 0xC3, "CC", C, Coil, Bit, Dec, "counter coil"},
    DeviceSpec{"CN", 0x00C5, 0xC5, "CN", C, Value, Word, Dec, "counter current value"},
    DeviceSpec{"LCS", 0x0055, -1, "", LC, Contact, Bit, Dec, "long counter contact"},
    DeviceSpec{"LCC", 0x0054, -1, "", LC, Coil, Bit, Dec, "long counter coil"},
    DeviceSpec{"LCN", 0x0056, -1, "", LC, Value, DoubleWord, Dec, "long counter current value"},
    DeviceSpec{"SB", 0x00A1, 0xA1, "SB", SB, Plain, Bit, Hex, "link special relay"},
    DeviceSpec{"SW", 0x00B5, 0xB5, "SW", SW, Plain, Word, Hex, "link special register"},
    DeviceSpec{"DX", 0x00A2, 0xA2, "DX", X, Plain, Bit, Hex, "direct access input"},
    DeviceSpec{"DY", 0x00A3, 0xA3, "DY", Y, Plain, Bit, Hex, "direct access output"},
    DeviceSpec{"Z", 0x00CC, 0xCC, "Z*", Z, Plain, Word, Dec, "index register"},
    DeviceSpec{"LZ", 0x0062, -1, "", LZ, Plain, DoubleWord, Dec, "long index register"},
    DeviceSpec{"R", 0x00AF, 0xAF, "R*", R, Plain, Word, Dec, "file register (block switching)"},
    DeviceSpec{"ZR", 0x00B0, 0xB0, "ZR", ZR, Plain, Word, Dec, "file register (serial number access)"},
    DeviceSpec{"RD", 0x002C, -1, "", RD, Plain, Word, Dec, "refresh data register"},
    DeviceSpec{"G", 0x00AB, 0xAB, "G*", G, Plain, Word, Dec, "buffer memory", true},
    DeviceSpec{"HG", 0x002E, -1, "", HG, Plain, Word, Dec, "CPU buffer memory fixed-cycle area", true},
};

constexpr std::array<std::string_view, static_cast<std::size_t>(Area::Count)> kAreaNames = {
    "X", "Y", "M", "L", "F", "V", "B", "SB", "S", "SM",
    "D", "W", "SW", "SD", "R", "ZR", "RD", "Z", "LZ",
    "T", "ST", "C", "LT", "LST", "LC", "G", "HG"};

bool iequals(std::string_view a, std::string_view b) {
    return a.size() == b.size() &&
           std::equal(a.begin(), a.end(), b.begin(), [](char x, char y) {
               return std::toupper(static_cast<unsigned char>(x)) ==
                      std::toupper(static_cast<unsigned char>(y));
           });
}

// Strips the '*' or ' ' padding of an ASCII device name.
std::string_view unpadded(std::string_view text) {
    auto end = text.find_first_of("* ");
    return end == std::string_view::npos ? text : text.substr(0, end);
}

}  // namespace

std::span<const DeviceSpec> all_devices() { return kDevices; }

const DeviceSpec* find_by_symbol(std::string_view symbol) {
    for (const auto& spec : kDevices)
        if (iequals(spec.symbol, symbol)) return &spec;
    return nullptr;
}

const DeviceSpec* find_by_iqr_code(std::uint16_t code) {
    for (const auto& spec : kDevices)
        if (spec.iqr_code == code) return &spec;
    return nullptr;
}

const DeviceSpec* find_by_part(Area area, Part part) {
    for (const auto& spec : all_devices())
        if (spec.area == area && spec.part == part && !spec.extension_only) return &spec;
    return nullptr;
}

const DeviceSpec* find_by_q_code(std::uint8_t code) {
    for (const auto& spec : kDevices)
        if (spec.q_code == code) return &spec;
    return nullptr;
}

const DeviceSpec* find_by_ascii(std::string_view text, std::size_t width) {
    if (text.size() != width) return nullptr;
    // Padding may only follow the name: "D* *" is fine, "*D**" is not.
    auto name = unpadded(text);
    if (name.empty() || text.substr(name.size()).find_first_not_of("* ") != std::string_view::npos)
        return nullptr;
    for (const auto& spec : kDevices) {
        if (width == 2) {
            if (!spec.ascii_q.empty() && unpadded(spec.ascii_q) == name) return &spec;
        } else if (spec.symbol == name) {
            return &spec;
        }
    }
    return nullptr;
}

std::string ascii_name(const DeviceSpec& spec, std::size_t width) {
    std::string name(width == 2 ? spec.ascii_q : spec.symbol);
    name.resize(width, '*');
    return name;
}

std::string_view area_name(Area area) { return kAreaNames[static_cast<std::size_t>(area)]; }

std::optional<Area> area_by_name(std::string_view name) {
    for (std::size_t i = 0; i < kAreaNames.size(); ++i)
        if (iequals(kAreaNames[i], name)) return static_cast<Area>(i);
    return std::nullopt;
}

unsigned words_per_device(const DeviceSpec& spec) {
    if (spec.unit != Unit::DoubleWord) return 1;
    return spec.area == Area::LT || spec.area == Area::LST ? 4 : 2;
}

namespace {
thread_local Numbering scoped_numbering;
}

NumberingScope::NumberingScope(Numbering numbering) : previous_(scoped_numbering) { scoped_numbering = numbering; }
NumberingScope::~NumberingScope() { scoped_numbering = previous_; }
Numbering NumberingScope::current() { return scoped_numbering; }

Radix radix_of(const DeviceSpec& spec, Numbering numbering) {
    return spec.area == Area::X || spec.area == Area::Y ? numbering.xy : spec.radix;
}

std::string_view radix_name(Radix radix) {
    switch (radix) {
    case Oct: return "octal";
    case Dec: return "decimal";
    case Hex: return "hexadecimal";
    }
    return "?";
}

std::optional<DeviceAddress> parse_address(std::string_view text, std::string* error) {
    return parse_address(text, NumberingScope::current(), error);
}

std::optional<DeviceAddress> parse_address(std::string_view text, Numbering numbering, std::string* error) {
    auto fail = [&](std::string message) -> std::optional<DeviceAddress> {
        if (error) *error = std::move(message);
        return std::nullopt;
    };
    // The longest symbol that prefixes the text wins: "LTN0" is LTN, not L.
    const DeviceSpec* best = nullptr;
    for (const auto& spec : kDevices) {
        if (text.size() > spec.symbol.size() && iequals(text.substr(0, spec.symbol.size()), spec.symbol) &&
            (!best || spec.symbol.size() > best->symbol.size()))
            best = &spec;
    }
    if (!best) return fail("unknown device in address '" + std::string(text) + "' (expected e.g. D100, M0, X1F, ZR1000)");
    auto digits = text.substr(best->symbol.size());
    std::uint32_t number = 0;
    auto radix = radix_of(*best, numbering);
    auto [ptr, ec] = std::from_chars(digits.data(), digits.data() + digits.size(), number, static_cast<int>(radix));
    if (ec != std::errc{} || ptr != digits.data() + digits.size())
        return fail("bad device number '" + std::string(digits) + "' in address '" + std::string(text) + "' (" +
                    std::string(best->symbol) + " is numbered in " + std::string(radix_name(radix)) +
                    (radix == Oct ? " on this CPU: " + std::string(best->symbol) + "7 is followed by " +
                                        std::string(best->symbol) + "10"
                                  : "") +
                    ")");
    return DeviceAddress{best, number};
}

std::string format_address(const DeviceAddress& address) { return format_address(address, NumberingScope::current()); }

std::string format_address(const DeviceAddress& address, Numbering numbering) {
    char digits[16];
    auto [ptr, ec] = std::to_chars(digits, digits + sizeof digits, address.number,
                                   static_cast<int>(radix_of(*address.spec, numbering)));
    std::string text(address.spec->symbol);
    for (char* p = digits; p != ptr; ++p) text += static_cast<char>(std::toupper(static_cast<unsigned char>(*p)));
    return text;
}

}  // namespace slmp::devicemodel
