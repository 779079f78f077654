#include "protocol/message.hpp"

#include "protocol/fields.hpp"

namespace slmp::protocol {

std::vector<std::uint8_t> encode_frame(Direction direction, FrameKind kind, Codec codec, std::uint16_t serial,
                                       const Route& route, std::span<const std::uint8_t> payload) {
    FieldWriter w(codec);
    // Subheaders are fixed byte patterns in binary ("50 00") and fixed text in
    // ASCII ("5000"): both are the hex number 0x5000 written most significant
    // byte first, which u8 pairs produce in either codec.
    std::uint8_t first = kind == FrameKind::E3 ? 0x50 : 0x54;
    if (direction == Direction::Response) first |= 0x80;
    w.u8(first);
    w.u8(0x00);
    if (kind == FrameKind::E4) {
        w.u16(serial);
        w.u16(0);
    }
    w.u8(route.network);
    w.u8(route.station);
    w.u16(route.module_io);
    w.u8(route.multidrop);
    w.u16(static_cast<std::uint16_t>(payload.size()));
    auto& out = w.bytes();
    out.insert(out.end(), payload.begin(), payload.end());
    return std::move(out);
}

}  // namespace slmp::protocol
