// Hexadecimal text, the one helper of the tree: the SLMP ASCII codec, codes as
// logs, metrics and the API print them ("0401", "C059"), recordings (bytes as
// lower-case hex), the host link's and the JW-51CM's records, URL escapes.
// Parsers take either case (the manuals ask senders for upper case, but real
// clients are not always careful); writers write upper case unless told.
#pragma once

#include <cstdint>
#include <optional>
#include <span>
#include <string>
#include <string_view>
#include <vector>

namespace slmp::devicemodel {

// The digits of every radix up to 16, upper case: kHexDigits[value % radix].
inline constexpr char kHexDigits[] = "0123456789ABCDEF";
inline constexpr char kHexDigitsLower[] = "0123456789abcdef";

// The value of one hex digit of either case; -1 for any other character.
constexpr int hex_digit(unsigned char c) {
    if (c >= '0' && c <= '9') return c - '0';
    if (c >= 'A' && c <= 'F') return c - 'A' + 10;
    if (c >= 'a' && c <= 'f') return c - 'a' + 10;
    return -1;
}

// Hex digits as one number; nullopt on any other character. The caller bounds
// the length (at most 8 digits fit).
inline std::optional<std::uint32_t> parse_hex(std::span<const std::uint8_t> text) {
    std::uint32_t value = 0;
    for (auto c : text) {
        int digit = hex_digit(c);
        if (digit < 0) return std::nullopt;
        value = value << 4 | static_cast<std::uint32_t>(digit);
    }
    return value;
}
inline std::optional<std::uint32_t> parse_hex(std::string_view text) {
    return parse_hex(std::span<const std::uint8_t>(reinterpret_cast<const std::uint8_t*>(text.data()), text.size()));
}

// Whether `text` is one or more hex digits and no other character.
constexpr bool is_hex(std::string_view text) {
    if (text.empty()) return false;
    for (char c : text)
        if (hex_digit(static_cast<unsigned char>(c)) < 0) return false;
    return true;
}

// Appends `digits` upper-case hex digits of `value`, most significant first.
template <class Out>
void append_hex(Out& out, std::uint32_t value, unsigned digits) {
    using Char = typename Out::value_type;
    for (unsigned i = digits; i-- > 0;) out.push_back(static_cast<Char>(kHexDigits[(value >> (4 * i)) & 0xF]));
}

// `digits` upper-case hex digits of `value` as text: "0401", "C059".
inline std::string hex_text(std::uint32_t value, unsigned digits) {
    std::string text;
    append_hex(text, value, digits);
    return text;
}

// A byte as two digits ("0D"): a host-link FCS, a JW-51CM command.
inline std::string hex2(std::uint8_t value) { return hex_text(value, 2); }

// A command, subcommand or end code as the manuals and the log lines write it.
inline std::string hex4(std::uint16_t value) { return hex_text(value, 4); }

// Bytes as hex text, two digits a byte, no separator (recordings: lower case).
inline std::string bytes_to_hex(std::span<const std::uint8_t> bytes, bool lower_case = false) {
    const char* digits = lower_case ? kHexDigitsLower : kHexDigits;
    std::string text;
    text.reserve(bytes.size() * 2);
    for (auto b : bytes) {
        text += digits[b >> 4];
        text += digits[b & 0xF];
    }
    return text;
}

// Hex text back to bytes; nullopt on an odd length or a non-hex character.
inline std::optional<std::vector<std::uint8_t>> hex_to_bytes(std::string_view text) {
    if (text.size() % 2) return std::nullopt;
    std::vector<std::uint8_t> bytes;
    bytes.reserve(text.size() / 2);
    for (std::size_t i = 0; i < text.size(); i += 2) {
        int high = hex_digit(static_cast<unsigned char>(text[i]));
        int low = hex_digit(static_cast<unsigned char>(text[i + 1]));
        if (high < 0 || low < 0) return std::nullopt;
        bytes.push_back(static_cast<std::uint8_t>(high << 4 | low));
    }
    return bytes;
}

}  // namespace slmp::devicemodel
