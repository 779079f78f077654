#include "tools/slmp/arguments.hpp"

#include <charconv>
#include <cstdio>
#include <limits>

#include "tools/slmp/errors.hpp"

namespace slmp::cli {
namespace {

// A signed or unsigned integer, decimal or 0x hex, within [min, max].
long long parse_integer(const std::string& text, long long min, long long max, const char* what) {
    std::string_view digits = text;
    bool negative = false;
    if (!digits.empty() && (digits[0] == '-' || digits[0] == '+')) {
        negative = digits[0] == '-';
        digits.remove_prefix(1);
    }
    int base = 10;
    if (digits.size() > 2 && (digits.starts_with("0x") || digits.starts_with("0X"))) {
        digits.remove_prefix(2);
        base = 16;
    }
    unsigned long long magnitude = 0;
    auto [ptr, ec] = std::from_chars(digits.data(), digits.data() + digits.size(), magnitude, base);
    bool parsed = !digits.empty() && ec == std::errc{} && ptr == digits.data() + digits.size() &&
                  magnitude <= static_cast<unsigned long long>(std::numeric_limits<long long>::max());
    long long value = negative ? -static_cast<long long>(magnitude) : static_cast<long long>(magnitude);
    if (!parsed || value < min || value > max)
        throw UsageError("'" + text + "' is not a " + what + " (" + std::to_string(min) + ".." + std::to_string(max) +
                         ", decimal or 0x hex)");
    return value;
}

}  // namespace

devicemodel::DeviceAddress parse_device(const std::string& text, devicemodel::Numbering numbering) {
    std::string error;
    auto address = devicemodel::parse_address(text, numbering, &error);
    if (!address) throw UsageError(error);
    return *address;
}

std::uint16_t parse_points(const std::string& text) {
    return static_cast<std::uint16_t>(parse_integer(text, 1, 65535, "point count"));
}

std::uint16_t parse_word(const std::string& text) {
    return static_cast<std::uint16_t>(parse_integer(text, -32768, 65535, "word value"));
}

std::uint32_t parse_dword(const std::string& text) {
    return static_cast<std::uint32_t>(parse_integer(text, -2147483648LL, 4294967295LL, "double-word value"));
}

bool parse_bit(const std::string& text) {
    if (text == "1" || text == "on" || text == "ON") return true;
    if (text == "0" || text == "off" || text == "OFF") return false;
    throw UsageError("'" + text + "' is not a bit value (0 or 1)");
}

Assignment parse_assignment(const std::string& text) {
    auto eq = text.find('=');
    if (eq == std::string::npos || eq == 0 || eq + 1 == text.size())
        throw UsageError("'" + text + "' is not DEVICE=VALUE (e.g. D100=5)");
    return {text.substr(0, eq), text.substr(eq + 1)};
}

DeviceRange parse_range(const std::string& text, devicemodel::Numbering numbering) {
    auto dash = text.find('-');
    if (dash == std::string::npos) return {parse_device(text, numbering), 1};
    auto start = parse_device(text.substr(0, dash), numbering);
    auto end = parse_device(text.substr(dash + 1), numbering);
    if (end.spec != start.spec || end.number < start.number)
        throw UsageError("'" + text + "' is not a range: write START-END of one device, e.g. D100-D119");
    return {start, end.number - start.number + 1};
}

bool is_bit_device(const devicemodel::DeviceAddress& device) { return device.spec->unit == devicemodel::Unit::Bit; }

std::vector<std::string> value_labels(const devicemodel::DeviceAddress& start, std::size_t count, bool bit_units,
                                      devicemodel::Numbering numbering) {
    std::vector<std::string> labels;
    const unsigned per_device = bit_units ? 1 : devicemodel::words_per_device(*start.spec);
    const unsigned step = !bit_units && is_bit_device(start) ? 16 : 1;
    for (std::size_t i = 0; i < count; ++i) {
        devicemodel::DeviceAddress at{start.spec, static_cast<std::uint32_t>(start.number + (i / per_device) * step)};
        auto label = devicemodel::format_address(at, numbering);
        if (per_device > 1 && i % per_device != 0) label += "+" + std::to_string(i % per_device);
        labels.push_back(label);
    }
    return labels;
}

std::string word_hex(std::uint32_t value, int digits) {
    char text[16];
    std::snprintf(text, sizeof text, "%0*X", digits, value);
    return text;
}

}  // namespace slmp::cli
