// Codes as the API and the metrics show them: four upper-case hex digits
// ("0401", "C059"), as the manuals and GX Works write them.
#pragma once

#include <cstdint>
#include <cstdio>
#include <string>

namespace slmp::control {

inline std::string hex4(std::uint32_t value) {
    char text[12];
    std::snprintf(text, sizeof text, "%04X", value);
    return text;
}

}  // namespace slmp::control
