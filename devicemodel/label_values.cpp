#include "devicemodel/label_values.hpp"

#include <algorithm>
#include <bit>
#include <charconv>
#include <cmath>
#include <cstdlib>
#include <cstring>
#include <sstream>

#include "devicemodel/utf16.hpp"

namespace slmp::devicemodel {
namespace {

std::uint64_t joined(const std::vector<std::uint16_t>& w, std::size_t n) {
    std::uint64_t v = 0;
    for (std::size_t i = 0; i < n && i < w.size(); ++i) v |= std::uint64_t{w[i]} << (16 * i);
    return v;
}
std::vector<std::uint16_t> split(std::uint64_t v, std::size_t n) {
    std::vector<std::uint16_t> w(n);
    for (std::size_t i = 0; i < n; ++i) w[i] = static_cast<std::uint16_t>(v >> (16 * i));
    return w;
}

bool in_range(BasicType t, std::int64_t v) {
    switch (t) {
        case BasicType::Bit: return v == 0 || v == 1;
        case BasicType::Word: return v >= -32768 && v <= 32767;
        case BasicType::UWord: return v >= 0 && v <= 65535;
        case BasicType::DWord:
        case BasicType::Time: return v >= -2147483648LL && v <= 2147483647LL;
        case BasicType::UDWord: return v >= 0 && v <= 4294967295LL;
        default: return true;
    }
}

std::string range_text(BasicType t) {
    switch (t) {
        case BasicType::Bit: return "0 or 1 (OFF/ON)";
        case BasicType::Word: return "-32768 to 32767";
        case BasicType::UWord: return "0 to 65535";
        case BasicType::DWord: return "-2147483648 to 2147483647";
        case BasicType::Time: return "-2147483648 to 2147483647 ms";
        case BasicType::UDWord: return "0 to 4294967295";
        default: return "a number";
    }
}

}  // namespace

LabelScalar decode_label_scalar(BasicType type, const std::vector<std::uint16_t>& w) {
    LabelScalar s;
    switch (type) {
        case BasicType::Bit: s.integer = joined(w, 1) & 1; break;
        case BasicType::UWord: s.integer = static_cast<std::int64_t>(joined(w, 1)); break;
        case BasicType::Word: s.integer = static_cast<std::int16_t>(joined(w, 1)); break;
        case BasicType::UDWord: s.integer = static_cast<std::int64_t>(joined(w, 2)); break;
        case BasicType::DWord:
        case BasicType::Time: s.integer = static_cast<std::int32_t>(joined(w, 2)); break;
        case BasicType::Real:
            s.kind = LabelScalar::Kind::Float;
            s.real = std::bit_cast<float>(static_cast<std::uint32_t>(joined(w, 2)));
            break;
        case BasicType::LReal:
            s.kind = LabelScalar::Kind::Float;
            s.real = std::bit_cast<double>(joined(w, 4));
            break;
        case BasicType::String:
            s.kind = LabelScalar::Kind::Text;
            for (auto word : w) {
                auto lo = static_cast<char>(word & 0xFF), hi = static_cast<char>(word >> 8);
                if (!lo) break;
                s.text += lo;
                if (!hi) break;
                s.text += hi;
            }
            break;
        case BasicType::WString:
            s.kind = LabelScalar::Kind::Text;
            s.text = utf16_to_utf8(std::vector<std::uint16_t>(w.begin(), std::find(w.begin(), w.end(), 0)));
            break;
    }
    return s;
}

std::optional<std::vector<std::uint16_t>> encode_label_scalar(BasicType type, std::uint32_t words,
                                                              const LabelScalar& value, std::string* error) {
    auto fail = [&](std::string why) -> std::optional<std::vector<std::uint16_t>> {
        if (error) *error = std::move(why);
        return std::nullopt;
    };
    const bool text_type = type == BasicType::String || type == BasicType::WString;
    if (text_type != (value.kind == LabelScalar::Kind::Text))
        return fail(text_type ? "a string label takes text" : "this label takes a number, not text");
    switch (type) {
        case BasicType::Real:
        case BasicType::LReal: {
            double v = value.kind == LabelScalar::Kind::Float ? value.real : static_cast<double>(value.integer);
            if (type == BasicType::Real) return split(std::bit_cast<std::uint32_t>(static_cast<float>(v)), 2);
            return split(std::bit_cast<std::uint64_t>(v), 4);
        }
        case BasicType::String: {
            if (value.text.size() + 1 > words * 2u)
                return fail("\"" + value.text + "\" is longer than the label's " + std::to_string(words * 2 - 1) +
                            " characters");
            std::vector<std::uint16_t> w(words, 0);
            for (std::size_t i = 0; i < value.text.size(); ++i)
                w[i / 2] = static_cast<std::uint16_t>(w[i / 2] | static_cast<unsigned char>(value.text[i]) << (i % 2 ? 8 : 0));
            return w;
        }
        case BasicType::WString: {
            auto units = utf8_to_utf16(value.text);
            if (units.size() + 1 > words)
                return fail("\"" + value.text + "\" is longer than the label's " + std::to_string(words - 1) +
                            " characters");
            units.resize(words, 0);
            return units;
        }
        default: {
            if (value.kind == LabelScalar::Kind::Float) {
                if (std::trunc(value.real) != value.real) return fail("this label takes a whole number");
                LabelScalar whole;
                whole.integer = static_cast<std::int64_t>(value.real);
                return encode_label_scalar(type, words, whole, error);
            }
            if (!in_range(type, value.integer))
                return fail(std::to_string(value.integer) + " is out of range; use " + range_text(type));
            return split(static_cast<std::uint64_t>(value.integer), basic_words(type, 0));
        }
    }
}

std::string format_label_scalar(const LabelScalar& value) {
    switch (value.kind) {
        case LabelScalar::Kind::Int: return std::to_string(value.integer);
        case LabelScalar::Kind::Float: {
            std::ostringstream os;
            os.precision(17);
            os << value.real;
            return os.str();
        }
        case LabelScalar::Kind::Text: return value.text;
    }
    return "";
}

std::optional<LabelScalar> parse_label_scalar(BasicType type, std::string_view text, std::string* error) {
    LabelScalar s;
    if (type == BasicType::String || type == BasicType::WString) {
        s.kind = LabelScalar::Kind::Text;
        s.text = std::string(text);
        return s;
    }
    if (type == BasicType::Bit) {
        constexpr std::pair<std::string_view, int> kWords[] = {{"ON", 1}, {"on", 1}, {"true", 1},
                                                               {"OFF", 0}, {"off", 0}, {"false", 0}};
        for (auto [word, v] : kWords)
            if (text == word) {
                s.integer = v;
                return s;
            }
    }
    if (type == BasicType::Real || type == BasicType::LReal) {
        std::string copy(text);
        char* end = nullptr;
        s.kind = LabelScalar::Kind::Float;
        s.real = std::strtod(copy.c_str(), &end);
        if (copy.empty() || *end != '\0') {
            if (error) *error = "'" + copy + "' is not a number";
            return std::nullopt;
        }
        return s;
    }
    auto [ptr, ec] = std::from_chars(text.data(), text.data() + text.size(), s.integer);
    if (ec != std::errc() || ptr != text.data() + text.size()) {
        if (error) *error = "'" + std::string(text) + "' is not a whole number";
        return std::nullopt;
    }
    return s;
}

}  // namespace slmp::devicemodel
