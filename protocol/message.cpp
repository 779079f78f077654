#include "protocol/message.hpp"

#include "protocol/fields.hpp"

namespace slmp::protocol {

std::vector<std::uint8_t> encode_frame(Direction direction, const FrameHeader& header,
                                       std::span<const std::uint8_t> payload, std::span<const std::uint8_t> more) {
    FieldWriter w(header.codec);
    // One allocation for the whole frame (the longest header is 30 ASCII characters).
    w.bytes().reserve(32 + payload.size() + more.size());
    // Subheaders are fixed byte patterns in binary ("50 00") and fixed text in
    // ASCII ("5000"): both are the hex number 0x5000 written most significant
    // byte first, which u8 pairs produce in either codec.
    std::uint8_t first = header.kind == FrameKind::E3 ? 0x50 : header.kind == FrameKind::E4 ? 0x54 : 0x68;
    if (direction == Direction::Response) first |= 0x80;
    w.u8(first);
    w.u8(0x00);
    if (header.kind != FrameKind::E3) {
        w.u16(header.serial);
        w.u16(0);
    }
    w.u8(header.route.network);
    w.u8(header.route.station);
    w.u16(header.route.module_io);
    w.u8(header.route.multidrop);
    if (header.kind == FrameKind::Ext) {   // fixed 00, the extended station No. (§3.1.6)
        w.u8(0x00);
        w.u16(header.extended_station);
    }
    w.u16(static_cast<std::uint16_t>(payload.size() + more.size()));
    auto& out = w.bytes();
    out.insert(out.end(), payload.begin(), payload.end());
    out.insert(out.end(), more.begin(), more.end());
    return std::move(out);
}

std::vector<std::uint8_t> encode_frame(Direction direction, FrameKind kind, Codec codec, std::uint16_t serial,
                                       const Route& route, std::span<const std::uint8_t> payload) {
    FrameHeader header;
    header.kind = kind;
    header.codec = codec;
    header.serial = serial;
    header.route = route;
    return encode_frame(direction, header, payload);
}

}  // namespace slmp::protocol
