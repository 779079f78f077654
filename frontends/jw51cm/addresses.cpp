#include "frontends/jw51cm/addresses.hpp"

#include <cctype>

namespace slmp::jw51cm {

namespace {

bool all_digits(std::string_view text) {
    if (text.empty()) return false;
    for (char c : text)
        if (!std::isdigit(static_cast<unsigned char>(c))) return false;
    return true;
}

std::string octal_text(std::uint32_t value) {
    std::string text;
    do {
        text.insert(text.begin(), static_cast<char>('0' + value % 8));
        value /= 8;
    } while (value);
    return text;
}

// The device holding byte `address` of `file`: a bit device's 8 relays from
// relay …0, or a word device's word when the address is even.
std::optional<devicemodel::DeviceAddress> byte_cell(const MemoryMap& map, std::string_view text, std::uint8_t file,
                                                    std::uint32_t address, int bit, std::string* error) {
    const auto* region = map.find(file, address);
    if (!region) {
        *error = std::string(text) + " is past the JW memory: file " + std::to_string(file) + " has " +
                 std::to_string(map.file_size(file)) + " bytes (octal 0–" +
                 octal_text(map.file_size(file) ? map.file_size(file) - 1 : 0) + ")";
        return std::nullopt;
    }
    auto offset = address - region->first_byte;
    devicemodel::DeviceAddress cell = region->base;
    if (region->base.spec->unit == devicemodel::Unit::Bit) {
        cell.number += 8 * offset + static_cast<std::uint32_t>(bit < 0 ? 0 : bit);
        return cell;
    }
    if (bit >= 0) {
        *error = std::string(text) + " names a relay in " + region->name + ", which holds bytes, not relays; "
                 "name its register or file address instead";
        return std::nullopt;
    }
    if (offset % 2) {
        *error = std::string(text) + " is the high byte of " +
                 devicemodel::format_address({cell.spec, cell.number + offset / 2}) +
                 "; name the even address before it (a word holds two bytes, the lower address in the low byte)";
        return std::nullopt;
    }
    cell.number += offset / 2;
    return cell;
}

}  // namespace

std::optional<std::uint32_t> octal(std::string_view digits) {
    if (digits.empty() || digits.size() > 7) return std::nullopt;
    std::uint32_t value = 0;
    for (char c : digits) {
        if (c < '0' || c > '7') return std::nullopt;
        value = value * 8 + static_cast<std::uint32_t>(c - '0');
    }
    return value;
}

std::optional<devicemodel::DeviceAddress> resolve_name(const MemoryMap& map, std::string_view text, std::string* error) {
    error->clear();
    // F<file>:<octal byte address>
    if (text.size() > 3 && (text[0] == 'F' || text[0] == 'f') && std::isdigit(static_cast<unsigned char>(text[1])) &&
        text[2] == ':') {
        auto file = static_cast<std::uint8_t>(text[1] - '0');
        auto address = octal(text.substr(3));
        if (file > 7 || !address) {
            *error = std::string(text) + ": a JW file address is F, the file 0–7, a colon and the byte address in octal (F1:0200)";
            return std::nullopt;
        }
        return byte_cell(map, text, file, *address, -1, error);
    }
    if (text.size() != 5 || !all_digits(text)) return std::nullopt;
    if (text[1] == '9') {   // register N9ooo
        auto low = octal(text.substr(2));
        if (!low) {
            *error = std::string(text) + ": a JW register is N9ooo with ooo in octal (09000–99777)";
            return std::nullopt;
        }
        return byte_cell(map, text, 0, 04000 + static_cast<std::uint32_t>(text[0] - '0') * 01000 + *low, -1, error);
    }
    auto relay = octal(text);
    if (!relay) {
        *error = std::string(text) + ": JW relay numbers are octal (digits 0–7, 00000–15777)";
        return std::nullopt;
    }
    return byte_cell(map, text, 0, *relay >> 3, static_cast<int>(*relay & 7), error);
}

}  // namespace slmp::jw51cm
