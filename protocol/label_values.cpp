#include "protocol/label_values.hpp"

namespace slmp::protocol {

using devicemodel::BasicType;

unsigned label_value_bits(BasicType type) {
    switch (type) {
        case BasicType::UDWord:
        case BasicType::DWord:
        case BasicType::Real:
        case BasicType::Time: return 32;
        case BasicType::LReal: return 64;
        default: return 16;
    }
}

void write_label_value(FieldWriter& out, BasicType type, const std::vector<std::uint16_t>& w) {
    auto at = [&](std::size_t i) -> std::uint64_t { return i < w.size() ? w[i] : 0; };
    switch (label_value_bits(type)) {
        case 32: return out.u32(static_cast<std::uint32_t>(at(0) | at(1) << 16));
        case 64: return out.u64(at(0) | at(1) << 16 | at(2) << 32 | at(3) << 48);
        default: return out.words(w);
    }
}

std::vector<std::uint16_t> read_label_value(FieldReader& in, BasicType type, std::uint32_t words) {
    switch (label_value_bits(type)) {
        case 32: {
            auto v = in.u32("label data");
            return {static_cast<std::uint16_t>(v), static_cast<std::uint16_t>(v >> 16)};
        }
        case 64: {
            auto v = in.u64("label data");
            return {static_cast<std::uint16_t>(v), static_cast<std::uint16_t>(v >> 16),
                    static_cast<std::uint16_t>(v >> 32), static_cast<std::uint16_t>(v >> 48)};
        }
        default: return in.words(words, "label data");
    }
}

}  // namespace slmp::protocol
