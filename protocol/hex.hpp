// Upper-case hexadecimal text: the one primitive under every ASCII field.
#pragma once

#include <cstdint>
#include <optional>
#include <span>
#include <string>
#include <vector>

namespace slmp::protocol {

// Parses hex digits (either case; the manual asks senders for upper case but
// real clients are not always careful). nullopt on any other character.
inline std::optional<std::uint32_t> parse_hex(std::span<const std::uint8_t> text) {
    std::uint32_t value = 0;
    for (auto c : text) {
        unsigned digit;
        if (c >= '0' && c <= '9') digit = c - '0';
        else if (c >= 'A' && c <= 'F') digit = c - 'A' + 10;
        else if (c >= 'a' && c <= 'f') digit = c - 'a' + 10;
        else return std::nullopt;
        value = value << 4 | digit;
    }
    return value;
}

// Appends `digits` upper-case hex digits of `value`, most significant first.
inline void append_hex(std::vector<std::uint8_t>& out, std::uint32_t value, unsigned digits) {
    static constexpr char kDigits[] = "0123456789ABCDEF";
    for (unsigned i = digits; i-- > 0;) out.push_back(static_cast<std::uint8_t>(kDigits[(value >> (4 * i)) & 0xF]));
}

// `digits` upper-case hex digits of `value` as text: "0401", "C059".
inline std::string hex_text(std::uint32_t value, unsigned digits) {
    std::vector<std::uint8_t> text;
    append_hex(text, value, digits);
    return std::string(text.begin(), text.end());
}

// A command, subcommand or end code as the manuals and the log lines write it.
inline std::string hex4(std::uint16_t value) { return hex_text(value, 4); }

}  // namespace slmp::protocol
