// SLMP end codes: one enum, one description table. Which code a situation gets
// on which CPU is decided by the profile (devicemodel/cpu_profile.hpp); these
// are the names the code base uses for them.
// Sources: ../shared/spec/hardware-behaviour.md §2, slmp-frames-and-devices.md §3.5.
#pragma once

#include <cstdint>
#include <string_view>

namespace slmp::protocol {

enum class EndCode : std::uint16_t {
    Ok = 0x0000,
    LatchClearNotInStop = 0x4013,
    DeviceNotAccessible = 0x4030,       // device this command/path may not touch
    DeviceOutOfRange = 0x4031,          // iQ-R: start or span past the configured size
    RouteNetworkNotFound = 0x4A01,      // request for another network (chosen, see docs/end-codes.md)
    RouteStationNotFound = 0x4A02,      // request for another station on network 0 (chosen)
    RouteNotCpu = 0x4B02,               // module I/O that is not this CPU (chosen)
    AsciiConversion = 0xC050,           // ASCII data that is not hexadecimal
    WordPointsOverLimit = 0xC051,
    BitPointsOverLimit = 0xC052,
    AddressOutOfRange = 0xC056,         // Q/L: request beyond the device range
    UnsupportedCommand = 0xC059,
    DeviceNotSpecifiable = 0xC05B,      // unknown device code / device not usable as plain device
    BadRequestContent = 0xC05C,
    LengthMismatch = 0xC061,
    RemotePasswordLocked = 0xC201,
};

constexpr EndCode end_code(std::uint16_t raw) { return static_cast<EndCode>(raw); }
constexpr std::uint16_t raw(EndCode code) { return static_cast<std::uint16_t>(code); }

// One line saying what the code means, for logs, the CLI and docs.
std::string_view describe(EndCode code);

}  // namespace slmp::protocol
