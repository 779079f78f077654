// decode: bytes -> Request. The frame (3E/4E/station-number-extended, binary/ASCII;
// 1E in decode_1e.cpp), the monitoring
// timer, command and subcommand, the table's row, the CPU the access route
// selects, and the row decoder's operands. Pure: nothing here reads or
// changes device memory, so the scenario hook may look at the result and
// still decide that the CPU never sees the request.
#include "protocol/command_table.hpp"
#include "protocol/engine.hpp"

namespace slmp::protocol {
namespace {

// The own station (§3.1.3–§3.1.5): 00/FF, or the port's own network and
// station numbers when they are set; anything else would need routing, which
// a CPU's built-in port cannot do. The codes are chosen; see
// docs/end-codes.md: another network 4A01, another station 4A02.
// Module I/O 03FF is the connected CPU, 03E0–03E3 CPU No.1–4, and on a CPU of
// a redundant pair 03D0–03D3 (the plant chose this CPU of the pair:
// Station::route); anything else 4B02 (chosen).
EndCode check_module_io(const Route& route, const CpuSet& cpus, const RouteIdentity& identity, std::size_t& target) {
    if (route.module_io == 0x03FF || (identity.redundant && route.module_io >= 0x03D0 && route.module_io <= 0x03D3)) {
        target = 0;
        return EndCode::Ok;
    }
    if (route.module_io < 0x03E0 || route.module_io > 0x03E3) return EndCode::RouteNotCpu;
    target = route.module_io - 0x03E0u;
    return cpus[target] ? EndCode::Ok : EndCode::RouteNotCpu;
}

// A routed request: the plant's router resolved its network and station to
// this station. A multidrop station takes its own serial-module route and
// multidrop No.; any other multidrop station behind it is not served (4A02).
EndCode check_routed(const Route& route, const CpuSet& cpus, const RouteIdentity& identity, std::size_t& target) {
    if (identity.multidrop && route.module_io == identity.multidrop_io && route.multidrop == identity.multidrop_number) {
        target = 0;
        return EndCode::Ok;
    }
    if (route.multidrop != 0x00) return EndCode::RouteStationNotFound;
    return check_module_io(route, cpus, identity, target);
}

EndCode check_route(const FrameHeader& header, StationNumbers own, const CpuSet& cpus, const RouteIdentity& identity,
                    std::size_t& target) {
    const auto& route = header.route;
    // Station-number-extended frame (§3.1.6): station 7C defers to the extended
    // station No., whose FFFF is the own station; otherwise that field is 0000.
    if (header.kind == FrameKind::Ext) {
        if (route.station == 0x7C) {
            if (route.network != 0x00 && !(own.configured() && route.network == own.network))
                return EndCode::RouteNetworkNotFound;
            if (header.extended_station != 0xFFFF || route.multidrop != 0x00) return EndCode::RouteStationNotFound;
            return check_module_io(route, cpus, identity, target);
        }
        if (header.extended_station != 0x0000) return EndCode::RouteStationNotFound;
    }
    const bool by_numbers = own.configured() && route.network == own.network;
    if (route.network != 0x00 && !by_numbers) return EndCode::RouteNetworkNotFound;
    const bool own_station = by_numbers ? route.station == own.station : route.station == 0xFF;
    if (!own_station || route.multidrop != 0x00) return EndCode::RouteStationNotFound;
    return check_module_io(route, cpus, identity, target);
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

bool file_route_allowed(const Route& route) {
    const auto io = route.module_io;
    return io == 0x03FF || io == 0x03D2 || io == 0x03D3 || (io >= 0x03E0 && io <= 0x03E3);
}

bool Request::reads_devices() const { return spec && spec->device_command() && !spec->writes(); }
bool Request::writes_devices() const { return spec && spec->device_command() && spec->writes(); }

FrameScan Engine::frame(std::span<const std::uint8_t> input, DataCodePolicy policy) const {
    const auto& port = ports_[0];
    return scan_frame(input, Direction::Request, policy, options_.max_frame_bytes,
                      FrameSet{port.frame_1e, port.station_extended_frame});
}

Request Engine::decode(std::span<const std::uint8_t> input, DataCodePolicy policy, StationNumbers own, bool routed) const {
    Request request;
    const auto scan = frame(input, policy);
    request.frame = frame_status(scan.status);
    request.size = scan.size;
    request.header = scan.header;
    if (!request.complete()) return request;
    if (request.header.kind == FrameKind::E1) {
        decode_1e(request, input, own);
        return request;
    }

    // After the header: monitoring timer, command, subcommand (2 bytes each).
    const auto& header = request.header;
    auto body = input.subspan(header.header_size, header.data_length);
    FieldReader in(header.codec, body, codec_options(0));
    in.u16("monitoring timer");
    request.command = in.u16("command");
    request.subcommand = in.u16("subcommand");
    if (!in.ok()) {
        request.header_error = in.error();
        request.header_error_field = in.error_field();
        return request;
    }
    if (header.kind == FrameKind::Ext) {
        // Fixed 00 and the 5-byte system area (§3.1.9), always zero.
        in.u8("fixed value 00");
        in.raw(5, "system area");
        if (!in.ok()) {
            request.header_error = in.error();
            request.header_error_field = in.error_field();
            return request;
        }
    }
    request.has_command = true;
    request.data = body.subspan(body.size() - in.remaining());
    request.routed = routed;
    request.route_error = routed ? check_routed(header.route, cpus_, identity_, request.target)
                                 : check_route(header, own, cpus_, identity_, request.target);
    request.spec = find_command(request.command, request.subcommand);
    // File commands reach only the destinations of §3.1.4's restricted table.
    const auto* any_row = request.spec ? request.spec : find_any_row(request.command);
    if (request.route_error == EndCode::Ok && any_row && any_row->file_route() && !file_route_allowed(header.route))
        request.route_error = EndCode::RouteNotCpu;
    // A module's port passes another station's request on undecoded: that
    // station's CPU decodes it. In the station-number-extended frame a station
    // No. other than 7C comes with extended station No. 0000 (else 4A02 here).
    const bool other_station =
        request.route_error == EndCode::RouteNetworkNotFound || request.route_error == EndCode::RouteStationNotFound;
    const bool stray_extended = header.kind == FrameKind::Ext && header.route.station != 0x7C && header.extended_station != 0;
    request.elsewhere = ports_[0].relays && !routed && other_station && !stray_extended;
    if (request.spec && request.spec->decode && !request.elsewhere) {
        // The target CPU's limits apply; a request with a bad route is refused
        // before its operands matter, but the scenario hook still sees them.
        const auto& port = ports_[request.route_error == EndCode::Ok ? request.target : 0];
        DecodeContext context{in, *request.spec, port, request.operands};
        request.spec->decode(context);
    }
    return request;
}

}  // namespace slmp::protocol
