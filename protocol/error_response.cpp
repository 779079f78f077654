#include "protocol/error_response.hpp"

#include "protocol/fields.hpp"
#include "protocol/frame_1e.hpp"
#include "protocol/message.hpp"

namespace slmp::protocol {

std::vector<std::uint8_t> encode_error_response(const FrameHeader& request, std::uint16_t command,
                                                std::uint16_t subcommand, EndCode code) {
    // A 1E error is its one-byte end code (scenarios force codes through here too).
    if (request.kind == FrameKind::E1) return encode_error_1e(request, code);
    FieldWriter w(request.codec);
    w.u16(raw(code));
    if (request.kind == FrameKind::Ext) {
        // §3.2.5: command, subcommand, fixed 00, system area, then the error
        // information ending in fixed 00 and the extended station No.
        w.u16(command);
        w.u16(subcommand);
        for (int i = 0; i < 6; ++i) w.u8(0x00);
        w.u8(request.route.network);
        w.u8(request.route.station);
        w.u16(request.route.module_io);
        w.u8(request.route.multidrop);
        w.u8(0x00);
        w.u16(request.extended_station);
        return encode_frame(Direction::Response, request, w.bytes());
    }
    w.u8(request.route.network);
    w.u8(request.route.station);
    w.u16(request.route.module_io);
    w.u8(request.route.multidrop);
    w.u16(command);
    w.u16(subcommand);
    return encode_frame(Direction::Response, request, w.bytes());
}

}  // namespace slmp::protocol
