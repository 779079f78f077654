// The six comparisons shared by trigger conditions ("D100 >= 50") and the
// rung language's compare contacts (LD>= D100 K50).
#pragma once

#include <cstdint>
#include <optional>
#include <string_view>

namespace slmp::scenarios {

enum class Compare : std::uint8_t { Eq, Ne, Lt, Le, Gt, Ge };

// "=", "==", "<>", "!=", "<", "<=", ">", ">="; nullopt for anything else.
inline std::optional<Compare> parse_compare(std::string_view text) {
    if (text == "=" || text == "==") return Compare::Eq;
    if (text == "<>" || text == "!=") return Compare::Ne;
    if (text == "<") return Compare::Lt;
    if (text == "<=") return Compare::Le;
    if (text == ">") return Compare::Gt;
    if (text == ">=") return Compare::Ge;
    return std::nullopt;
}

template <typename T>
bool compare(T left, Compare op, T right) {
    switch (op) {
        case Compare::Eq: return left == right;
        case Compare::Ne: return left != right;
        case Compare::Lt: return left < right;
        case Compare::Le: return left <= right;
        case Compare::Gt: return left > right;
        case Compare::Ge: return left >= right;
    }
    return false;
}

}  // namespace slmp::scenarios
