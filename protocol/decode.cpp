// decode: bytes -> Request. The frame (3E/4E, binary/ASCII), the monitoring
// timer, command and subcommand, the table's row, the CPU the access route
// selects, and the row decoder's operands. Pure: nothing here reads or
// changes device memory, so the scenario hook may look at the result and
// still decide that the CPU never sees the request.
#include "protocol/command_table.hpp"
#include "protocol/engine.hpp"

namespace slmp::protocol {
namespace {

// The own station (§3.1.3–§3.1.5): anything else would need routing, which a
// CPU's built-in port cannot do. Module I/O 03FF is the connected CPU, 03E0–03E3
// CPU No.1–4 of a multi-CPU system. The codes are chosen; see docs/end-codes.md.
EndCode check_route(const Route& route, const CpuSet& cpus, std::size_t& target) {
    if (route.network != 0x00) return EndCode::RouteNetworkNotFound;
    if (route.station != 0xFF || route.multidrop != 0x00) return EndCode::RouteStationNotFound;
    if (route.module_io == 0x03FF) {
        target = 0;
        return EndCode::Ok;
    }
    if (route.module_io < 0x03E0 || route.module_io > 0x03E3) return EndCode::RouteNotCpu;
    target = route.module_io - 0x03E0u;
    return cpus[target] ? EndCode::Ok : EndCode::RouteNotCpu;
}

Request::Frame frame_status(FrameScan::Status status) {
    switch (status) {
        case FrameScan::Status::NeedMore: return Request::Frame::NeedMore;
        case FrameScan::Status::Garbage: return Request::Frame::Garbage;
        case FrameScan::Status::TooLarge: return Request::Frame::TooLarge;
        case FrameScan::Status::Complete: break;
    }
    return Request::Frame::Complete;
}

}  // namespace

bool Request::reads_devices() const { return spec && spec->device_command() && !spec->writes(); }
bool Request::writes_devices() const { return spec && spec->device_command() && spec->writes(); }

Request Engine::decode(std::span<const std::uint8_t> input, DataCodePolicy policy) const {
    Request request;
    auto scan = scan_frame(input, Direction::Request, policy, options_.max_frame_bytes);
    request.frame = frame_status(scan.status);
    request.size = scan.size;
    request.header = scan.header;
    if (!request.complete()) return request;

    // After the header: monitoring timer, command, subcommand (2 bytes each).
    const auto& header = request.header;
    auto body = input.subspan(header.header_size, header.data_length);
    FieldReader in(header.codec, body, CodecOptions{ports_[0].zr_ascii_hex});
    in.u16("monitoring timer");
    request.command = in.u16("command");
    request.subcommand = in.u16("subcommand");
    if (!in.ok()) {
        request.header_error = in.error();
        request.header_error_field = in.error_field();
        return request;
    }
    request.has_command = true;
    request.data = body.subspan(body.size() - in.remaining());
    request.route_error = check_route(header.route, cpus_, request.target);
    request.spec = find_command(request.command, request.subcommand);
    if (request.spec && request.spec->decode) {
        // The target CPU's limits apply; a request with a bad route is refused
        // before its operands matter, but the scenario hook still sees them.
        const auto& port = ports_[request.route_error == EndCode::Ok ? request.target : 0];
        DecodeContext context{in, *request.spec, port, request.operands};
        request.spec->decode(context);
    }
    return request;
}

}  // namespace slmp::protocol
