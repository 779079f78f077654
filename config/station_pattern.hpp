// Names of a plant's stations as users write them for a group: a name, or a
// pattern in which '*' stands for any run of characters ("press-*", "*-7").
// Shared by scenario files that name their stations and the plant's HTTP
// routes that address a group (docs/plants.md).
#pragma once

#include <string>
#include <string_view>
#include <vector>

#include "config/json_path.hpp"

namespace slmp::config {

// "stations": "press-*" or ["press-1", "oven-*"] — a scenario file's key, a
// group request's. Throws ConfigError (through `at`) for anything else.
std::vector<std::string> parse_station_patterns(const JsonAt& at);

bool station_pattern_matches(std::string_view pattern, std::string_view name);
// Whether any of `patterns` matches `name`.
bool station_patterns_match(const std::vector<std::string>& patterns, std::string_view name);

}  // namespace slmp::config
