#include "control/observers/request_summary.hpp"

#include "protocol/command_table.hpp"

namespace slmp::control {

std::optional<RequestDevices> request_devices(const protocol::Request& request, devicemodel::Numbering numbering) {
    using Unit = protocol::DeviceOperand::Unit;
    const auto* spec = request.spec;
    const auto& devices = request.operands.devices;
    if (!spec || !spec->device_command() || spec->extended() || devices.size() != 1) return std::nullopt;
    const auto& d = devices.front();
    if (!d.field.spec || d.unit == Unit::DoubleWord || d.bit_block) return std::nullopt;
    return RequestDevices{devicemodel::format_address({d.field.spec, d.field.number}, numbering), d.points,
                          d.unit == Unit::Bit ? "bits" : "words"};
}

std::string_view command_name(std::uint16_t command, std::uint16_t subcommand) {
    const auto* spec = protocol::find_command(command, subcommand);
    return spec ? spec->name : std::string_view{};
}

}  // namespace slmp::control
