// decode for the A-compatible 1E frame: the 1E row names the command table
// row that serves it, and a device command's decoder reads the A-compatible
// fields into the same Operands as the 3E path, so the rest of the request
// path (scenarios, execute, recording, metrics) sees a 0401/1401/... request.
#include "protocol/command_table.hpp"
#include "protocol/engine.hpp"
#include "protocol/frame_1e.hpp"

namespace slmp::protocol {

void Engine::decode_1e(Request& request, std::span<const std::uint8_t> input, StationNumbers own) const {
    const auto& header = request.header;
    const auto* row = find_command_1e(header.command_1e);   // scan_1e framed only known commands
    request.command = row->command;
    request.subcommand = row->subcommand;
    request.has_command = true;
    request.data = input.subspan(header.header_size, request.size - header.header_size);
    // PC No. FF is the own station; so is the port's own station No. when set
    // (a 1E frame has no network No.). Anything else would be another station.
    const auto pc = header.route.station;
    if (pc != 0xFF && !(own.configured() && pc == own.station)) request.route_error = EndCode::RouteStationNotFound;
    request.spec = find_command(row->command, row->subcommand);
    if (request.spec && row->decode) {
        FieldReader in(header.codec, request.data, codec_options(0));
        DecodeContext context{in, *request.spec, ports_[0], request.operands, true};
        row->decode(context);
    }
}

}  // namespace slmp::protocol
