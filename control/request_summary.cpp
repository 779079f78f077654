#include "control/request_summary.hpp"

#include "protocol/command_table.hpp"
#include "protocol/fields.hpp"
#include "protocol/frame.hpp"

namespace slmp::control {

std::optional<RequestDevices> request_devices(std::span<const std::uint8_t> frame,
                                              const devicemodel::CpuProfile& profile) {
    using namespace protocol;
    auto scan = scan_frame(frame, Direction::Request, DataCodePolicy::Auto, frame.size());
    if (scan.status != FrameScan::Status::Complete) return std::nullopt;
    FieldReader in(scan.header.codec, frame.subspan(scan.header.header_size, scan.header.data_length),
                   CodecOptions{profile.zr_ascii_hex});
    in.u16("monitoring timer");
    auto command = in.u16("command");
    auto subcommand = in.u16("subcommand");
    const auto* spec = find_command(command, subcommand);
    // Batch read/write without the extension specification is "head device,
    // points"; other commands lay their devices out differently.
    bool batch = (command == 0x0401 || command == 0x1401) && subcommand <= 0x0003;
    if (!in.ok() || !batch || !spec || spec->access == Access::None) return std::nullopt;
    auto device = in.device(spec->form, "start device");
    auto points = in.u16("device points");
    if (!in.ok() || !device.spec) return std::nullopt;
    return RequestDevices{devicemodel::format_address({device.spec, device.number}), points,
                          spec->access == Access::Bits ? "bits" : "words"};
}

std::string_view command_name(std::uint16_t command, std::uint16_t subcommand) {
    const auto* spec = protocol::find_command(command, subcommand);
    return spec ? spec->name : std::string_view{};
}

}  // namespace slmp::control
