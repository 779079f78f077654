#include "scenarios/incoming.hpp"

#include "protocol/device_access.hpp"
#include "scenarios/device_values.hpp"

namespace slmp::scenarios {

std::string_view to_string(Protocol protocol) { return protocol; }
namespace {

// The devices an operand covers: its points in bits, or in words (a double
// word is two; a bit block's points are words of 16 bits).
std::uint64_t devices_covered(const protocol::DeviceOperand& d) {
    using Unit = protocol::DeviceOperand::Unit;
    if (d.unit == Unit::Bit) return d.points;
    auto words = std::uint64_t{d.points} * (d.unit == Unit::DoubleWord ? 2 : 1);
    return protocol::devices_in_words(*d.field.spec, words);
}

}  // namespace

bool touches(const protocol::Request& request, const std::vector<DeviceRange>& ranges) {
    for (const auto& d : request.operands.devices) {
        if (!d.field.spec || d.field.extension.kind != protocol::DeviceExtension::Kind::None || d.points == 0) continue;
        const DeviceRange named{d.field.spec->area, d.field.number,
                                static_cast<std::uint32_t>(d.field.number + devices_covered(d) - 1)};
        for (const auto& r : ranges)
            if (overlaps(named, r)) return true;
    }
    return false;
}

}  // namespace slmp::scenarios
