// Operand syntax (docs/program.md "Operands"): devices through
// the one device table, plus the timer/counter names without a part letter,
// digit designation, bit of a word, index modification and constants.
#include "program/operands.hpp"
#include "program/operand_device.hpp"

#include "devicemodel/hex.hpp"

#include <array>
#include <cctype>
#include <charconv>
#include <cstdlib>

namespace slmp::program::detail {

using devicemodel::Area;
using devicemodel::DeviceSpec;

bool is_timer_or_counter(Area area) {
    return area == Area::T || area == Area::ST || area == Area::C || area == Area::LT || area == Area::LST ||
           area == Area::LC;
}

namespace {

std::string upper(std::string_view text) {
    std::string out(text);
    for (auto& c : out) c = static_cast<char>(std::toupper(static_cast<unsigned char>(c)));
    return out;
}

bool all_digits(std::string_view text, int radix) {
    if (text.empty()) return false;
    for (char c : text) {
        const bool ok = radix == 16 ? std::isxdigit(static_cast<unsigned char>(c)) != 0
                                    : (c >= '0' && c < static_cast<char>('0' + radix));
        if (!ok) return false;
    }
    return true;
}

struct Symbol {
    std::string_view text;
    const DeviceSpec* spec;
    Area area;
};

// The longest symbol that prefixes `text` and leaves something after it.
std::optional<Symbol> symbol_of(std::string_view text) {
    static constexpr std::array<std::pair<std::string_view, Area>, 6> kBare{
        {{"T", Area::T}, {"ST", Area::ST}, {"C", Area::C}, {"LT", Area::LT}, {"LST", Area::LST}, {"LC", Area::LC}}};
    std::optional<Symbol> best;
    auto consider = [&](std::string_view symbol, const DeviceSpec* spec, Area area) {
        if (text.size() > symbol.size() && text.substr(0, symbol.size()) == symbol &&
            (!best || symbol.size() > best->text.size()))
            best = Symbol{symbol, spec, area};
    };
    for (const auto& spec : devicemodel::all_devices()) consider(spec.symbol, &spec, spec.area);
    for (const auto& [symbol, area] : kBare) consider(symbol, nullptr, area);
    return best;
}

// "Z1" / "LZ0" at the end of a number: splits it off.
bool split_index(std::string_view& number, ParsedOperand& out, std::string& error, std::string_view whole) {
    const auto z = number.find('Z');
    if (z == std::string_view::npos) return true;
    auto index_text = number.substr(z + 1);
    bool is_long = z > 0 && number[z - 1] == 'L';
    number = number.substr(0, is_long ? z - 1 : z);
    unsigned index = 0;
    auto [ptr, ec] = std::from_chars(index_text.data(), index_text.data() + index_text.size(), index);
    if (index_text.empty() || ec != std::errc{} || ptr != index_text.data() + index_text.size() || index > 254) {
        error = "bad index register in '" + std::string(whole) + "' (write e.g. D0Z1 or D0LZ0)";
        return false;
    }
    out.index = static_cast<std::uint8_t>(index);
    out.index_long = is_long;
    return true;
}

bool parse_device(std::string_view text, devicemodel::Numbering numbering, ParsedOperand& out, std::string& error,
                  std::string_view whole) {
    auto symbol = symbol_of(text);
    if (!symbol) {
        error = "'" + std::string(whole) + "' is no device, constant or pointer";
        return false;
    }
    if (symbol->spec && symbol->spec->extension_only) {
        error = std::string(whole) + ": " + std::string(symbol->spec->symbol) + " is only reachable through a module (U..\\G); not in a program";
        return false;
    }
    std::string_view rest = text.substr(symbol->text.size());
    const auto dot = rest.find('.');
    if (dot != std::string_view::npos) {
        auto bit_text = rest.substr(dot + 1);
        rest = rest.substr(0, dot);
        const int bit = bit_text.size() == 1 ? devicemodel::hex_digit(static_cast<unsigned char>(bit_text[0])) : -1;
        if (bit < 0) {
            error = "bad bit number in '" + std::string(whole) + "' (0-F, e.g. D0.F)";
            return false;
        }
        out.bit = bit;   // either case: D0.a is D0.A
    }
    if (!split_index(rest, out, error, whole)) return false;
    const int radix = symbol->spec ? static_cast<int>(devicemodel::radix_of(*symbol->spec, numbering)) : 10;
    std::uint32_t number = 0;
    auto [ptr, ec] = std::from_chars(rest.data(), rest.data() + rest.size(), number, radix);
    if (rest.empty() || ec != std::errc{} || ptr != rest.data() + rest.size()) {
        error = "bad device number in '" + std::string(whole) + "' (" + std::string(symbol->text) + " is numbered in " +
                std::string(devicemodel::radix_name(static_cast<devicemodel::Radix>(radix))) + ")";
        return false;
    }
    out.spec = symbol->spec;
    out.area = symbol->area;
    out.number = number;
    return true;
}

// "E1.5", "E-2.5", "E1.234E+3", "E1.234+3" (GX Developer exponent style, docs/program.md "Operands").
bool parse_real(std::string_view body, float& value) {
    std::string text(body);
    if (text.find('E') == std::string::npos) {
        const auto sign = text.find_first_of("+-", 1);
        if (sign != std::string::npos) text.insert(sign, "E");
    }
    char* end = nullptr;
    value = std::strtof(text.c_str(), &end);
    return !text.empty() && end == text.c_str() + text.size();
}

}  // namespace

std::optional<ParsedOperand> parse_operand(std::string_view raw, devicemodel::Numbering numbering, std::string& error) {
    ParsedOperand out;
    if (raw.empty()) {
        error = "empty operand";
        return std::nullopt;
    }
    if (raw.front() == '"') {
        if (raw.size() < 2 || raw.back() != '"') {
            error = "string constant " + std::string(raw) + " has no closing quote";
            return std::nullopt;
        }
        out.kind = ParsedOperand::Kind::String;
        auto body = raw.substr(1, raw.size() - 2);
        for (std::size_t i = 0; i < body.size(); ++i) {
            out.text += body[i];
            if (body[i] == '"' && i + 1 < body.size() && body[i + 1] == '"') ++i;
        }
        return out;
    }
    const std::string text = upper(raw);
    if (text.front() == '@') {
        error = "'" + std::string(raw) + "': indirect addressing (@) is not supported by slmp-sim yet";
        return std::nullopt;
    }
    const std::string_view view(text);
    const char first = view.front();
    const std::string_view after = view.substr(1);
    if (first == 'K' && !after.empty() && (std::isdigit(static_cast<unsigned char>(after.front())) || after.front() == '-')) {
        std::size_t i = after.front() == '-' ? 1 : 0;
        while (i < after.size() && std::isdigit(static_cast<unsigned char>(after[i]))) ++i;
        const auto digits = after.substr(0, i);
        auto rest = after.substr(i);
        if (rest.empty() || rest.front() == 'Z' || rest.substr(0, 2) == "LZ") {
            out.kind = ParsedOperand::Kind::Integer;
            if (!split_index(rest, out, error, raw)) return std::nullopt;
            auto [ptr, ec] = std::from_chars(digits.data(), digits.data() + digits.size(), out.integer);
            if (ec != std::errc{} || ptr != digits.data() + digits.size()) {
                error = "bad decimal constant '" + std::string(raw) + "'";
                return std::nullopt;
            }
            return out;
        }
        if (digits.size() == 1 && digits.front() != '-') {   // K4M0: digit designation
            out.kind = ParsedOperand::Kind::Digits;
            out.digits = static_cast<std::uint8_t>(digits.front() - '0');
            if (out.digits < 1 || out.digits > 8) {
                error = "'" + std::string(raw) + "': digit designation is K1 to K8";
                return std::nullopt;
            }
            if (!parse_device(rest, numbering, out, error, raw)) return std::nullopt;
            if (out.bit >= 0) {
                error = "'" + std::string(raw) + "': digit designation of a bit of a word is not supported";
                return std::nullopt;
            }
            return out;
        }
        error = "bad constant '" + std::string(raw) + "'";
        return std::nullopt;
    }
    if (first == 'H') {
        auto rest = after;
        ParsedOperand hex;
        if (!rest.empty() && split_index(rest, hex, error, raw) && all_digits(rest, 16)) {
            hex.kind = ParsedOperand::Kind::Integer;
            hex.hex = true;
            std::uint64_t value = 0;
            auto [ptr, ec] = std::from_chars(rest.data(), rest.data() + rest.size(), value, 16);
            if (ec != std::errc{} || value > 0xFFFFFFFFull) {
                error = "hex constant '" + std::string(raw) + "' is wider than 32 bits";
                return std::nullopt;
            }
            hex.integer = static_cast<std::int64_t>(value);
            return hex;
        }
        error.clear();
    }
    if (first == 'E' && !after.empty() &&
        (std::isdigit(static_cast<unsigned char>(after.front())) || after.front() == '-' || after.front() == '+' ||
         after.front() == '.')) {
        out.kind = ParsedOperand::Kind::Real;
        if (!parse_real(after, out.real)) {
            error = "bad real constant '" + std::string(raw) + "' (write e.g. E1.5, E-2.5, E1.234E+3)";
            return std::nullopt;
        }
        return out;
    }
    if ((first == 'P' || first == 'N') && all_digits(after, 10)) {
        out.kind = first == 'P' ? ParsedOperand::Kind::Pointer : ParsedOperand::Kind::Nesting;
        std::from_chars(after.data(), after.data() + after.size(), out.integer);
        return out;
    }
    if (!parse_device(view, numbering, out, error, raw)) return std::nullopt;
    return out;
}

}  // namespace slmp::program::detail

namespace slmp::program {

std::optional<OperandDevice> operand_device(std::string_view text, devicemodel::Numbering numbering) {
    std::string error;
    auto parsed = detail::parse_operand(text, numbering, error);
    if (!parsed || parsed->kind != detail::ParsedOperand::Kind::Device || parsed->index != 0xFF) return std::nullopt;
    return OperandDevice{parsed->spec, parsed->area, parsed->number, parsed->bit};
}

}  // namespace slmp::program
