// One label value as text for people (HTTP API, slmp CLI): numbers in the
// type's own range and sign, FLOAT as a decimal, TIME in milliseconds, strings
// as UTF-8 text. The words are the element's storage (labels.hpp layout).
#pragma once

#include <cstdint>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "devicemodel/label_types.hpp"

namespace slmp::devicemodel {

struct LabelScalar {
    enum class Kind : std::uint8_t { Int, Float, Text } kind = Kind::Int;
    std::int64_t integer = 0;    // Int (UDWord up to 4294967295 fits)
    double real = 0;             // Float
    std::string text;            // Text (String, WString), up to the NUL
};

LabelScalar decode_label_scalar(BasicType type, const std::vector<std::uint16_t>& words);
// The value in `words` words (strings: padded with NUL; too long is an error).
// Returns nullopt and says why (the type's range, the string's capacity).
std::optional<std::vector<std::uint16_t>> encode_label_scalar(BasicType type, std::uint32_t words,
                                                              const LabelScalar& value, std::string* error);
// Text forms: "5", "-1", "1.5", "ON"/"OFF"/"1"/"0"/"true"/"false" for bits; strings as they are.
std::string format_label_scalar(const LabelScalar& value);
std::optional<LabelScalar> parse_label_scalar(BasicType type, std::string_view text, std::string* error);

}  // namespace slmp::devicemodel
