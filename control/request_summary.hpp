// What the call monitor shows of a request: the command's name and, for device
// commands, the head device and point count. Decoded again from the request
// bytes only when someone is watching the event stream, so the SLMP path
// itself carries no extra work.
#pragma once

#include <cstdint>
#include <optional>
#include <span>
#include <string>
#include <string_view>

#include "devicemodel/cpu_profile.hpp"

namespace slmp::control {

struct RequestDevices {
    std::string device;      // "D100"
    std::uint32_t points = 0;
    std::string_view unit;   // "bits" or "words"
};

// The head device and points of a device batch request (0401/1401, any form);
// nullopt for other commands and for frames that do not decode.
std::optional<RequestDevices> request_devices(std::span<const std::uint8_t> frame,
                                              const devicemodel::CpuProfile& profile);

// The command table's name for (command, subcommand), or "" when not served.
std::string_view command_name(std::uint16_t command, std::uint16_t subcommand);

}  // namespace slmp::control
