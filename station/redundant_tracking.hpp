// Tracking between the CPUs of a redundant pair (docs/plants.md, "Tracking"):
// at each END of the control system's scan the tracked device ranges are
// copied into an image, which the standby writes over its own devices. After
// a system switch the new control system thus holds the values the old one
// had at its last END. A real pair tracks by its "tracking settings"; the
// default here is every point of M, L, B, D and W and the timers' and
// counters' current values (TN, STN, CN and the long ones, where the CPU has
// them), or the ranges the pair's "tracking" key gives.
//
// Threads: an image is built on the control system's strand and never changed
// after; it travels to the standby's strand as a shared_ptr to const.
#pragma once

#include <cstdint>
#include <memory>
#include <optional>
#include <vector>

#include "config/config.hpp"
#include "devicemodel/device_memory.hpp"

namespace slmp::station {

// The tracked devices at one END of the control system: per tracked range,
// its points as the memory's planes hold them (a byte a bit point, a 32-bit
// value a word, double word or current value), copied whole.
struct TrackingImage {
    struct Points {
        std::vector<std::uint8_t> bits;       // bit devices, contacts, coils
        std::vector<std::uint32_t> values;    // everything else
    };
    std::vector<Points> ranges;
};

class Tracking {
public:
    using Range = config::RedundantConfig::Range;

    // `given`: the pair's "tracking" ranges (none: the default; an empty list
    // tracks nothing). Each range is cut to what both CPUs have (a pair of
    // unlike CPUs tracks the common part).
    Tracking(const std::optional<std::vector<Range>>& given, const devicemodel::DeviceMemory& a, const devicemodel::DeviceMemory& b);

    const std::vector<Range>& ranges() const { return ranges_; }
    std::shared_ptr<const TrackingImage> capture(const devicemodel::DeviceMemory& control) const;
    // Writes the image's points that differ from the standby's, straight into
    // its planes (its write observers hear those runs only).
    void apply(const TrackingImage& image, devicemodel::DeviceMemory& standby) const;

private:
    std::vector<Range> ranges_;
};

}  // namespace slmp::station
