#include "scenarios/request_view.hpp"

#include "protocol/command_table.hpp"
#include "protocol/device_access.hpp"
#include "protocol/fields.hpp"
#include "scenarios/device_values.hpp"

namespace slmp::scenarios {
namespace {

using protocol::DeviceField;
using protocol::FieldReader;

struct Decoder {
    FieldReader& in;
    const protocol::CommandSpec& spec;
    RequestView& view;

    DeviceField field() {
        return spec.extended ? in.extended_device(spec.form, "device") : in.device(spec.form, "device");
    }
    // `units` points of the command's access unit (bits, words, or one value of `words` words).
    void add(const DeviceField& f, std::uint64_t units, bool in_words) {
        if (!in.ok() || !f.spec || f.extension.kind != protocol::DeviceExtension::Kind::None || units == 0) return;
        auto count = in_words ? protocol::devices_in_words(*f.spec, units) : units;
        view.devices.push_back({f.spec->area, f.number, static_cast<std::uint32_t>(f.number + count - 1)});
    }
    // 0403 / 0801 and 1402 word units: word points, double-word points, devices (with data for 1402).
    void random(bool with_data) {
        auto words = in.u8("word points");
        auto dwords = in.u8("double-word points");
        for (unsigned i = 0; i < words + dwords && in.ok(); ++i) {
            auto f = field();
            if (with_data) i < words ? void(in.u16("data")) : void(in.u32("data"));
            add(f, i < words ? 1 : 2, true);
        }
    }
    void random_bits() {
        auto points = in.u8("bit points");
        for (unsigned i = 0; i < points && in.ok(); ++i) {
            auto f = field();
            spec.form == protocol::DeviceForm::Q ? void(in.u8("set/reset")) : void(in.u16("set/reset"));
            add(f, 1, false);
        }
    }
    // 0406 / 1406: word blocks, bit blocks; each block device, points (in words), data for 1406.
    void blocks(bool with_data) {
        auto word_blocks = in.u8("word blocks");
        auto bit_blocks = in.u8("bit blocks");
        for (unsigned i = 0; i < word_blocks + bit_blocks && in.ok(); ++i) {
            auto f = field();
            auto points = in.u16("points");
            if (with_data) in.words(points, "data");
            add(f, points, true);
        }
    }
};

}  // namespace

RequestView view_request(std::span<const std::uint8_t> input, protocol::DataCodePolicy policy,
                         std::size_t max_frame_bytes, const devicemodel::CpuProfile& profile) {
    using namespace protocol;
    RequestView view;
    auto scan = scan_frame(input, Direction::Request, policy, max_frame_bytes);
    if (scan.status != FrameScan::Status::Complete) return view;
    view.complete = true;
    view.size = scan.size;
    view.header = scan.header;
    FieldReader in(scan.header.codec, input.subspan(scan.header.header_size, scan.header.data_length),
                   CodecOptions{profile.zr_ascii_hex});
    in.u16("monitoring timer");
    view.command = in.u16("command");
    view.subcommand = in.u16("subcommand");
    view.has_command = in.ok();
    const auto* spec = view.has_command ? find_command(view.command, view.subcommand) : nullptr;
    if (!spec || spec->access == protocol::Access::None) return view;

    Decoder d{in, *spec, view};
    const bool bits = spec->access == protocol::Access::Bits;
    switch (view.command) {
        case 0x0401:
        case 0x1401: {
            auto f = d.field();
            auto points = in.u16("points");
            d.add(f, points, !bits);
            break;
        }
        case 0x0403: d.random(false); break;
        case 0x0801: d.random(false); break;
        case 0x1402: bits ? d.random_bits() : d.random(true); break;
        case 0x0406: d.blocks(false); break;
        case 0x1406: d.blocks(true); break;
        default: return view;
    }
    view.access = view.command == 0x1401 || view.command == 0x1402 || view.command == 0x1406 ? Access::Write : Access::Read;
    return view;
}

bool touches(const RequestView& request, const std::vector<DeviceRange>& ranges) {
    for (const auto& d : request.devices)
        for (const auto& r : ranges)
            if (overlaps(d, r)) return true;
    return false;
}

}  // namespace slmp::scenarios
