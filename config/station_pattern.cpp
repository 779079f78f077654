#include "config/station_pattern.hpp"

namespace slmp::config {

bool station_pattern_matches(std::string_view pattern, std::string_view name) {
    auto star = pattern.find('*');
    if (star == std::string_view::npos) return pattern == name;
    auto head = pattern.substr(0, star);
    if (name.substr(0, head.size()) != head) return false;
    auto rest = pattern.substr(star + 1);
    for (auto from = head.size(); from <= name.size(); ++from)
        if (station_pattern_matches(rest, name.substr(from))) return true;
    return false;
}

bool station_patterns_match(const std::vector<std::string>& patterns, std::string_view name) {
    for (const auto& pattern : patterns)
        if (station_pattern_matches(pattern, name)) return true;
    return false;
}

}  // namespace slmp::config
