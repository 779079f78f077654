#include "frontends/hostlink/addresses.hpp"

#include <cctype>

namespace slmp::hostlink {

namespace {

// The areas a channel/word number names; T/C stay MELSEC names (TN, TS), since
// "TC" is MELSEC's timer coil.
constexpr Area kNamed[] = {Area::Cio, Area::Hr, Area::Lr, Area::Ar, Area::Dm, Area::Vr};

}  // namespace

std::optional<NamedCell> resolve_name(const MemoryMap& map, std::string_view text, std::string* error) {
    error->clear();
    for (auto area : kNamed) {
        const auto& i = info(area);
        if (text.size() <= i.key.size()) continue;
        bool key = true;
        for (std::size_t k = 0; k < i.key.size(); ++k)
            key = key && std::toupper(static_cast<unsigned char>(text[k])) == i.key[k];
        if (!key) continue;
        auto digits = text.substr(i.key.size());
        std::uint64_t number = 0;
        for (char c : digits) {
            if (!std::isdigit(static_cast<unsigned char>(c)) || digits.size() > 6) {
                *error = std::string(text) + ": a host-link " + std::string(i.key) + " address is " + std::string(i.key) +
                         " and a decimal number (" + std::string(i.key) + "0100)";
                return std::nullopt;
            }
            number = number * 10 + static_cast<unsigned>(c - '0');
        }
        const auto& b = map.binding(area);
        if (number >= b.size) {
            *error = std::string(text) + " is past the " + std::string(i.name) + ": " + std::string(i.key) + "0–" +
                     std::string(i.key) + std::to_string(b.size - 1) + " (hostlink.areas." + std::string(i.key) +
                     ".size sets its size)";
            return std::nullopt;
        }
        NamedCell cell;
        cell.device = b.base;
        const bool bits = b.base.spec->unit == devicemodel::Unit::Bit;
        auto n = static_cast<std::uint32_t>(number);
        cell.device.number += i.element == Element::LongWord ? 2 * n : bits ? 16 * n : n;
        cell.long_word = i.element == Element::LongWord;
        return cell;
    }
    return std::nullopt;
}

}  // namespace slmp::hostlink
