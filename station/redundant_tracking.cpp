// Tracking between a redundant pair's CPUs (redundant_tracking.hpp).
#include "station/redundant_tracking.hpp"

#include <algorithm>

#include "devicemodel/device_table.hpp"

namespace slmp::station {

namespace {

using devicemodel::Area;

std::size_t words_of(const Tracking::Range& r) {
    if (r.spec->unit == devicemodel::Unit::Bit) return r.count / 16;
    return std::size_t{r.count} * devicemodel::words_per_device(*r.spec);
}

// Chosen default (docs/plants.md, "Tracking"): the devices a program keeps its
// state in, whole; not X/Y (the I/O's), not SM/SD (each CPU's own), not the
// file registers (a real pair tracks them only when told).
std::vector<Tracking::Range> default_ranges() {
    std::vector<Tracking::Range> out;
    for (const char* symbol : {"M", "L", "B", "D", "W", "TN", "STN", "CN", "LTN", "LSTN", "LCN"})
        if (const auto* spec = devicemodel::find_by_symbol(symbol)) out.push_back({spec, 0, ~std::uint32_t{0}});
    return out;
}

}  // namespace

Tracking::Tracking(const std::optional<std::vector<Range>>& given, const devicemodel::DeviceMemory& a, const devicemodel::DeviceMemory& b) {
    for (auto r : given ? *given : default_ranges()) {
        const auto size = std::min(a.size(r.spec->area), b.size(r.spec->area));
        if (r.first >= size) continue;
        r.count = std::min<std::uint64_t>(r.count, size - r.first);
        if (r.spec->unit == devicemodel::Unit::Bit) r.count -= r.count % 16;   // whole words of bits
        if (r.count > 0) ranges_.push_back(r);
    }
}

std::shared_ptr<const TrackingImage> Tracking::capture(const devicemodel::DeviceMemory& control) const {
    auto image = std::make_shared<TrackingImage>();
    image->words.reserve(ranges_.size());
    for (const auto& r : ranges_) {
        auto& words = image->words.emplace_back(words_of(r));
        control.read_words(*r.spec, r.first, words);
    }
    return image;
}

void Tracking::apply(const TrackingImage& image, devicemodel::DeviceMemory& standby) const {
    std::vector<std::uint16_t> now;
    for (std::size_t i = 0; i < ranges_.size() && i < image.words.size(); ++i) {
        const auto& r = ranges_[i];
        const auto& want = image.words[i];
        now.resize(want.size());
        standby.read_words(*r.spec, r.first, now);
        const bool bits = r.spec->unit == devicemodel::Unit::Bit;
        const auto per = bits ? 1u : devicemodel::words_per_device(*r.spec);
        // Runs of differing devices (a double-word device is its two words together).
        for (std::size_t at = 0; at < want.size();) {
            if (std::equal(want.begin() + at, want.begin() + at + per, now.begin() + at)) {
                at += per;
                continue;
            }
            auto end = at + per;
            while (end < want.size() && !std::equal(want.begin() + end, want.begin() + end + per, now.begin() + end)) end += per;
            const auto device = static_cast<std::uint32_t>(bits ? at * 16 : at / per);
            standby.write_words(*r.spec, r.first + device,
                                std::span<const std::uint16_t>(want.data() + at, end - at));
            at = end;
        }
    }
}

}  // namespace slmp::station
