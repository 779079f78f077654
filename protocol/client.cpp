#include "protocol/client.hpp"

#include "protocol/message.hpp"

namespace slmp::protocol::client {

std::vector<std::uint8_t> build_request(const FrameOptions& options, std::uint16_t command, std::uint16_t subcommand,
                                        const std::function<void(FieldWriter&)>& body) {
    FieldWriter w(options.codec, CodecOptions{.numbering = options.numbering});
    w.u16(options.monitoring_timer);
    w.u16(command);
    w.u16(subcommand);
    if (body) body(w);
    return encode_frame(Direction::Request, options.kind, options.codec, options.serial, options.route, w.bytes());
}

namespace {

std::uint16_t subcommand(DeviceForm form, bool bits) {
    return static_cast<std::uint16_t>((form == DeviceForm::IQR ? 2 : 0) + (bits ? 1 : 0));
}

}  // namespace

std::vector<std::uint8_t> read_words(const FrameOptions& options, const devicemodel::DeviceAddress& start,
                                     std::uint16_t points, DeviceForm form) {
    return build_request(options, 0x0401, subcommand(form, false), [&](FieldWriter& w) {
        w.device(form, start);
        w.u16(points);
    });
}

std::vector<std::uint8_t> read_bits(const FrameOptions& options, const devicemodel::DeviceAddress& start,
                                    std::uint16_t points, DeviceForm form) {
    return build_request(options, 0x0401, subcommand(form, true), [&](FieldWriter& w) {
        w.device(form, start);
        w.u16(points);
    });
}

std::vector<std::uint8_t> write_words(const FrameOptions& options, const devicemodel::DeviceAddress& start,
                                      std::span<const std::uint16_t> values, DeviceForm form) {
    return build_request(options, 0x1401, subcommand(form, false), [&](FieldWriter& w) {
        w.device(form, start);
        w.u16(static_cast<std::uint16_t>(values.size()));
        w.words(values);
    });
}

std::vector<std::uint8_t> write_bits(const FrameOptions& options, const devicemodel::DeviceAddress& start,
                                     std::span<const std::uint8_t> values, DeviceForm form) {
    return build_request(options, 0x1401, subcommand(form, true), [&](FieldWriter& w) {
        w.device(form, start);
        w.u16(static_cast<std::uint16_t>(values.size()));
        w.bits(values);
    });
}

std::optional<Response> parse_response(std::span<const std::uint8_t> bytes, bool* garbage) {
    if (garbage) *garbage = false;
    auto scan = scan_frame(bytes, Direction::Response, DataCodePolicy::Auto, 1u << 20);
    if (scan.status == FrameScan::Status::Garbage || scan.status == FrameScan::Status::TooLarge) {
        if (garbage) *garbage = true;
        return std::nullopt;
    }
    if (scan.status != FrameScan::Status::Complete) return std::nullopt;
    Response response;
    response.header = scan.header;
    response.size = scan.size;
    auto payload = bytes.subspan(scan.header.header_size, scan.header.data_length);
    FieldReader r(scan.header.codec, payload);
    response.end_code = r.u16("end code");
    if (!r.ok()) {
        if (garbage) *garbage = true;
        return std::nullopt;
    }
    auto rest = r.raw(r.remaining(), "data");
    response.data.assign(rest.begin(), rest.end());
    return response;
}

}  // namespace slmp::protocol::client
