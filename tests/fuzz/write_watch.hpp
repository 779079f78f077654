// The fuzz targets' write observer: notes the first stored value a request
// changes (devicemodel/device_memory.hpp reports every change), so checking
// "a rejected request wrote nothing" is O(1) per request.
#pragma once

#include <cstdint>
#include <string>

#include "devicemodel/device_memory.hpp"

namespace slmp::fuzz {

class WriteWatch final : public devicemodel::WriteObserver {
public:
    void written(const devicemodel::DeviceSpec& spec, std::uint32_t first, std::uint32_t) override {
        if (!changed) {
            changed = true;
            what = std::string(spec.symbol) + std::to_string(first);
        }
    }
    void label_area_written(std::uint32_t index) override {
        if (!changed) {
            changed = true;
            what = "label area word " + std::to_string(index);
        }
    }
    bool changed = false;
    std::string what;   // the first device changed, e.g. "D100"
};

}  // namespace slmp::fuzz
