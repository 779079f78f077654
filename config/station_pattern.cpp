#include "config/station_pattern.hpp"

#include <algorithm>

namespace slmp::config {

std::vector<std::string> parse_station_patterns(const JsonAt& at) {
    std::vector<std::string> names;
    if (at.json().is_string()) names.push_back(at.string());
    else if (at.json().is_array())
        for (std::size_t i = 0; i < at.json().size(); ++i) names.push_back(at[i].string());
    if (names.empty() || std::find(names.begin(), names.end(), "") != names.end())
        at.fail("no station named", "give a station name, a pattern such as \"press-*\", or a list of them");
    return names;
}

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
