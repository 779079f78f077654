#include "devicemodel/label_types.hpp"

#include <algorithm>
#include <array>
#include <cctype>

namespace slmp::devicemodel {
namespace {

struct BasicName {
    std::string_view gx;     // as GX Works3 writes it
    std::string_view iec;    // IEC short name
    std::string_view iec2;   // second IEC alias ("WORD", "DWORD"), or ""
    BasicType type;
};
constexpr std::array kBasicNames = {
    BasicName{"Bit", "BOOL", "", BasicType::Bit},
    BasicName{"Word [Signed]", "INT", "", BasicType::Word},
    BasicName{"Word [Unsigned]/Bit String [16-bit]", "UINT", "WORD", BasicType::UWord},
    BasicName{"Double Word [Signed]", "DINT", "", BasicType::DWord},
    BasicName{"Double Word [Unsigned]/Bit String [32-bit]", "UDINT", "DWORD", BasicType::UDWord},
    BasicName{"FLOAT [Single Precision]", "REAL", "", BasicType::Real},
    BasicName{"FLOAT [Double Precision]", "LREAL", "", BasicType::LReal},
    BasicName{"Time", "TIME", "", BasicType::Time},
};

struct TimerName {
    std::string_view gx, iec;
    TimerKind kind;
};
constexpr std::array kTimerNames = {
    TimerName{"Timer", "TIMER", TimerKind::Timer},
    TimerName{"Counter", "COUNTER", TimerKind::Counter},
    TimerName{"Retentive Timer", "RETENTIVETIMER", TimerKind::RetentiveTimer},
    TimerName{"Long Timer", "LTIMER", TimerKind::LongTimer},
    TimerName{"Long Counter", "LCOUNTER", TimerKind::LongCounter},
    TimerName{"Long Retentive Timer", "LRETENTIVETIMER", TimerKind::LongRetentiveTimer},
};

// GX Works3's default string length when none is given.
constexpr std::uint16_t kDefaultChars = 32;
// GX Works3 allows up to 255 characters in a string label.
constexpr std::uint32_t kMaxChars = 255;
// One array dimension: elements 0..65535 at most (chosen; the label area limits the rest).
constexpr std::uint64_t kMaxDimension = 65536;

bool same(std::string_view a, std::string_view b) {
    return a.size() == b.size() && std::equal(a.begin(), a.end(), b.begin(), [](char x, char y) {
               return std::tolower(static_cast<unsigned char>(x)) == std::tolower(static_cast<unsigned char>(y));
           });
}

std::string_view trim(std::string_view s) {
    while (!s.empty() && s.front() == ' ') s.remove_prefix(1);
    while (!s.empty() && s.back() == ' ') s.remove_suffix(1);
    return s;
}

std::optional<std::uint32_t> decimal(std::string_view s) {
    s = trim(s);
    if (s.empty() || s.size() > 9 || !std::all_of(s.begin(), s.end(), [](char c) { return c >= '0' && c <= '9'; }))
        return std::nullopt;
    std::uint32_t v = 0;
    for (char c : s) v = v * 10 + static_cast<std::uint32_t>(c - '0');
    return v;
}

// "(0..19)" or "(0..1,0..19)" after a type: the array's dimensions.
bool parse_dims(std::string_view s, std::vector<std::uint32_t>& dims, std::string* error) {
    auto fail = [&](std::string why) {
        if (error) *error = std::move(why);
        return false;
    };
    while (!s.empty()) {
        auto comma = s.find(',');
        auto part = trim(s.substr(0, comma));
        s = comma == std::string_view::npos ? std::string_view{} : s.substr(comma + 1);
        auto dots = part.find("..");
        if (dots == std::string_view::npos)
            return fail("array range '" + std::string(part) + "' is not written as 0..n");
        auto low = decimal(part.substr(0, dots));
        auto high = decimal(part.substr(dots + 2));
        if (!low || !high) return fail("array range '" + std::string(part) + "' is not written as 0..n");
        if (*low != 0) return fail("array range '" + std::string(part) + "' does not start at 0");
        if (std::uint64_t{*high} + 1 > kMaxDimension)
            return fail("array range '" + std::string(part) + "' has more than 65536 elements");
        dims.push_back(*high + 1);
    }
    if (dims.empty() || dims.size() > 3) return fail("an array has 1 to 3 dimensions");
    return true;
}

// "String(32)", "String [Unicode](32)", "STRING[32]", "WSTRING", "STRING".
std::optional<LabelType> parse_string_type(std::string_view text, std::string* error) {
    struct Form {
        std::string_view prefix;
        char open, close;
        BasicType type;
    };
    constexpr std::array kForms = {Form{"String [Unicode]", '(', ')', BasicType::WString},
                                   Form{"String", '(', ')', BasicType::String},
                                   Form{"WSTRING", '[', ']', BasicType::WString},
                                   Form{"STRING", '[', ']', BasicType::String}};
    for (const auto& f : kForms) {
        if (text.size() < f.prefix.size() || !same(text.substr(0, f.prefix.size()), f.prefix)) continue;
        auto rest = trim(text.substr(f.prefix.size()));
        LabelType t{LabelType::Kind::Basic, f.type, kDefaultChars};
        if (rest.empty()) return t;
        if (rest.front() != f.open || rest.back() != f.close) continue;
        auto n = decimal(rest.substr(1, rest.size() - 2));
        if (!n || *n == 0 || *n > kMaxChars) {
            if (error) *error = "string length in '" + std::string(text) + "' must be 1 to 255 characters";
            return std::nullopt;
        }
        t.chars = static_cast<std::uint16_t>(*n);
        return t;
    }
    return std::nullopt;
}

}  // namespace

std::uint32_t basic_words(BasicType type, std::uint16_t chars) {
    switch (type) {
        case BasicType::Bit:
        case BasicType::UWord:
        case BasicType::Word: return 1;
        case BasicType::UDWord:
        case BasicType::DWord:
        case BasicType::Real:
        case BasicType::Time: return 2;
        case BasicType::LReal: return 4;
        // §2.6: chars + N bytes, N = 1 when chars is odd, 2 when even.
        case BasicType::String: return (chars + (chars % 2 ? 1u : 2u)) / 2;
        case BasicType::WString: return chars + 1u;
    }
    return 1;
}

std::uint32_t data_bytes(BasicType type, std::uint16_t chars) { return basic_words(type, chars) * 2; }

std::uint32_t element_words(const LabelType& type) {
    switch (type.kind) {
        case LabelType::Kind::Basic: return basic_words(type.basic, type.chars);
        case LabelType::Kind::Timer: return is_long(type.timer) ? 4 : 2;
        case LabelType::Kind::Struct: return type.structure ? type.structure->words : 0;
    }
    return 0;
}

std::uint32_t element_count(const std::vector<std::uint32_t>& dims) {
    std::uint64_t n = 1;
    for (auto d : dims) n *= d;
    return static_cast<std::uint32_t>(std::min<std::uint64_t>(n, 0xFFFFFFFFu));
}

std::uint32_t storage_words(const LabelType& type, const std::vector<std::uint32_t>& dims) {
    auto n = std::uint64_t{element_count(dims)};
    std::uint64_t words = type.kind == LabelType::Kind::Basic && type.basic == BasicType::Bit && !dims.empty()
                              ? (n + 15) / 16
                              : n * element_words(type);
    return static_cast<std::uint32_t>(std::min<std::uint64_t>(words, 0xFFFFFFFFu));
}

std::optional<ParsedType> parse_label_type(std::string_view text,
                                           const std::function<const StructType*(std::string_view)>& find_structure,
                                           std::string* error) {
    text = trim(text);
    ParsedType parsed;
    // A trailing "(a..b,...)" is the array part; "String(32)" keeps its own parentheses.
    if (!text.empty() && text.back() == ')') {
        auto open = text.rfind('(');
        if (open != std::string_view::npos && text.find("..", open) != std::string_view::npos) {
            if (!parse_dims(text.substr(open + 1, text.size() - open - 2), parsed.dims, error)) return std::nullopt;
            text = trim(text.substr(0, open));
        }
    }
    for (const auto& b : kBasicNames)
        if (same(text, b.gx) || same(text, b.iec) || (!b.iec2.empty() && same(text, b.iec2))) {
            parsed.type = LabelType{LabelType::Kind::Basic, b.type};
            return parsed;
        }
    for (const auto& t : kTimerNames)
        if (same(text, t.gx) || same(text, t.iec)) {
            parsed.type.kind = LabelType::Kind::Timer;
            parsed.type.timer = t.kind;
            return parsed;
        }
    std::string string_error;
    if (auto s = parse_string_type(text, &string_error)) {
        parsed.type = *s;
        return parsed;
    }
    if (!string_error.empty()) {
        if (error) *error = string_error;
        return std::nullopt;
    }
    if (const auto* st = find_structure ? find_structure(text) : nullptr) {
        parsed.type.kind = LabelType::Kind::Struct;
        parsed.type.structure = st;
        return parsed;
    }
    if (error) *error = "unknown data type '" + std::string(text) + "'";
    return std::nullopt;
}

std::string_view timer_kind_name(TimerKind kind) {
    for (const auto& t : kTimerNames)
        if (t.kind == kind) return t.gx;
    return "?";
}

std::string format_label_type(const LabelType& type, const std::vector<std::uint32_t>& dims) {
    std::string out;
    switch (type.kind) {
        case LabelType::Kind::Basic:
            if (type.basic == BasicType::String) out = "String(" + std::to_string(type.chars) + ")";
            else if (type.basic == BasicType::WString) out = "String [Unicode](" + std::to_string(type.chars) + ")";
            else
                for (const auto& b : kBasicNames)
                    if (b.type == type.basic) out = b.gx;
            break;
        case LabelType::Kind::Timer: out = timer_kind_name(type.timer); break;
        case LabelType::Kind::Struct: out = type.structure ? type.structure->name : "?"; break;
    }
    if (!dims.empty()) {
        out += "(";
        for (std::size_t i = 0; i < dims.size(); ++i) out += (i ? ",0.." : "0..") + std::to_string(dims[i] - 1);
        out += ")";
    }
    return out;
}

}  // namespace slmp::devicemodel
