// What the call monitor shows of a request: the command's name and, for a
// device command that names one run of plain devices (a batch read or write),
// the head device and point count — read off the Request the station decoded,
// never decoded again.
#pragma once

#include <cstdint>
#include <optional>
#include <string>
#include <string_view>

#include "protocol/request.hpp"

namespace slmp::control {

struct RequestDevices {
    std::string device;      // "D100"
    std::uint32_t points = 0;
    std::string_view unit;   // "bits" or "words"
};

// The head device and points of a request naming one run of plain devices;
// nullopt for other requests and for fields that did not decode.
// `numbering`: the CPU's, so an FX5's X/Y head device shows in octal.
std::optional<RequestDevices> request_devices(const protocol::Request& request, devicemodel::Numbering numbering);

// The command table's name for (command, subcommand), or "" when not served.
std::string_view command_name(std::uint16_t command, std::uint16_t subcommand);

}  // namespace slmp::control
