// Tracking between a redundant pair's CPUs (redundant_tracking.hpp).
#include "station/redundant_tracking.hpp"

#include <algorithm>

#include "devicemodel/device_table.hpp"

namespace slmp::station {

namespace {

using devicemodel::Area;

bool bit_points(const devicemodel::DeviceSpec& spec) { return spec.unit == devicemodel::Unit::Bit; }

std::span<const std::uint8_t> bits_of(const devicemodel::DeviceMemory& m, const devicemodel::DeviceSpec& spec) {
    return spec.part == devicemodel::Part::Coil ? m.coil_plane(spec.area) : m.bit_plane(spec.area);
}
std::span<std::uint8_t> bits_of(devicemodel::DeviceMemory& m, const devicemodel::DeviceSpec& spec) {
    return spec.part == devicemodel::Part::Coil ? m.coil_plane(spec.area) : m.bit_plane(spec.area);
}

// The range's points of a plane (cut to the plane: never past it).
template <typename T>
std::span<T> points(std::span<T> plane, const Tracking::Range& r) {
    if (r.first >= plane.size()) return {};
    return plane.subspan(r.first, std::min<std::size_t>(r.count, plane.size() - r.first));
}

// Copies the differing runs of `want` into `have`; the memory's observer hears each run.
template <typename T>
void write_differences(std::span<T> have, const std::vector<T>& want, const Tracking::Range& r,
                       devicemodel::DeviceMemory& memory) {
    const auto n = std::min(have.size(), want.size());
    for (std::size_t at = 0; at < n;) {
        if (have[at] == want[at]) {
            ++at;
            continue;
        }
        auto end = at + 1;
        while (end < n && have[end] != want[end]) ++end;
        std::copy(want.begin() + static_cast<std::ptrdiff_t>(at), want.begin() + static_cast<std::ptrdiff_t>(end),
                  have.begin() + static_cast<std::ptrdiff_t>(at));
        memory.notify(*r.spec, r.first + static_cast<std::uint32_t>(at), static_cast<std::uint32_t>(end - at));
        at = end;
    }
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
    image->ranges.reserve(ranges_.size());
    for (const auto& r : ranges_) {
        auto& to = image->ranges.emplace_back();
        if (bit_points(*r.spec)) {
            const auto from = points(bits_of(control, *r.spec), r);
            to.bits.assign(from.begin(), from.end());
        } else {
            const auto from = points(control.value_plane(r.spec->area), r);
            to.values.assign(from.begin(), from.end());
        }
    }
    return image;
}

void Tracking::apply(const TrackingImage& image, devicemodel::DeviceMemory& standby) const {
    for (std::size_t i = 0; i < ranges_.size() && i < image.ranges.size(); ++i) {
        const auto& r = ranges_[i];
        if (bit_points(*r.spec)) write_differences(points(bits_of(standby, *r.spec), r), image.ranges[i].bits, r, standby);
        else write_differences(points(standby.value_plane(r.spec->area), r), image.ranges[i].values, r, standby);
    }
}

}  // namespace slmp::station
