#include "protocol/error_response.hpp"

#include "protocol/fields.hpp"
#include "protocol/message.hpp"

namespace slmp::protocol {

std::vector<std::uint8_t> encode_error_response(const FrameHeader& request, std::uint16_t command,
                                                std::uint16_t subcommand, EndCode code) {
    FieldWriter w(request.codec);
    w.u16(raw(code));
    w.u8(request.route.network);
    w.u8(request.route.station);
    w.u16(request.route.module_io);
    w.u8(request.route.multidrop);
    w.u16(command);
    w.u16(subcommand);
    return encode_frame(Direction::Response, request.kind, request.codec, request.serial, request.route, w.bytes());
}

}  // namespace slmp::protocol
