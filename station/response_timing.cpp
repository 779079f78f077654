#include "station/response_timing.hpp"

#include <cmath>

#include "protocol/fields.hpp"

namespace slmp::station {

using protocol::DeviceOperand;

ResponseTiming::ResponseTiming(config::TimingModel model, double jitter, std::uint64_t seed)
    : model_(model), jitter_(jitter), state_(seed) {}

double ResponseTiming::next_unit() {
    // splitmix64: a fixed, portable sequence (std distributions differ between libraries).
    std::uint64_t z = (state_ += 0x9E3779B97F4A7C15ull);
    z = (z ^ (z >> 30)) * 0xBF58476D1CE4E5B9ull;
    z = (z ^ (z >> 27)) * 0x94D049BB133111EBull;
    z ^= z >> 31;
    return static_cast<double>(z >> 11) * 0x1.0p-53;
}

std::uint64_t ResponseTiming::words(const protocol::Request& request) {
    std::uint64_t words = 0;
    for (const auto& d : request.operands.devices) {
        switch (d.unit) {
            case DeviceOperand::Unit::Bit: words += (d.points + 15) / 16; break;
            case DeviceOperand::Unit::Word: words += d.points; break;
            case DeviceOperand::Unit::DoubleWord: words += 2ull * d.points; break;
        }
    }
    return words;
}

std::chrono::microseconds ResponseTiming::modelled(const protocol::Request& request, std::chrono::microseconds scan_wait) {
    const bool ascii = request.header.codec == protocol::Codec::Ascii;
    const double ke = ascii ? model_.ke_ascii_ms : model_.ke_binary_ms;
    const double kdt = ascii ? model_.kdt_ascii_ms : model_.kdt_binary_ms;
    double ms = ke + kdt * static_cast<double>(words(request));
    if (jitter_ > 0) ms *= 1 + jitter_ * (2 * next_unit() - 1);
    auto time = std::chrono::microseconds(std::llround(ms * 1000));
    if (model_.scan_wait) time += scan_wait;
    return time;
}

std::chrono::milliseconds ResponseTiming::monitoring_timer(const protocol::FrameHeader& h, std::span<const std::uint8_t> input) {
    if (input.size() < h.header_size) return std::chrono::milliseconds{0};
    // 3E/4E/station-extended: the timer is the first field the length counts
    // (decode.cpp reads it the same way); 1E: the header's last field, after
    // the subheader and the PC No. (docs/frames.md), in the same 250 ms units.
    const std::size_t unit = h.codec == protocol::Codec::Binary ? 1 : 2;
    const auto at = h.kind == protocol::FrameKind::E1 ? 2 * unit : h.header_size;
    protocol::FieldReader in(h.codec, input.subspan(at));
    const auto units = in.u16("monitoring timer");
    if (!in.ok()) return std::chrono::milliseconds{0};
    return std::chrono::milliseconds{250} * units;
}

}  // namespace slmp::station
