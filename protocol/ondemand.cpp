#include "protocol/ondemand.hpp"

#include "protocol/fields.hpp"
#include "protocol/message.hpp"

namespace slmp::protocol {

std::vector<std::uint8_t> encode_ondemand(FrameKind kind, Codec codec, std::span<const std::uint16_t> words) {
    FieldWriter w(codec);
    w.u16(0x0000);   // end code: normal
    w.u16(kOndemandCommand);
    w.u16(0x0000);   // subcommand
    w.words(words);
    const auto shape = kind == FrameKind::E4 ? FrameKind::E4 : FrameKind::E3;
    return encode_frame(Direction::Response, shape, codec, 0, Route{}, w.bytes());
}

}  // namespace slmp::protocol
