// The profile JSON files compiled into the binary (generated at build time).
#pragma once

#include <string_view>
#include <vector>

namespace slmp::config {

struct BuiltinProfile {
    std::string_view name;   // file name without .json
    std::string_view json;
};

const std::vector<BuiltinProfile>& builtin_profiles();

}  // namespace slmp::config
