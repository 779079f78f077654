// Ondemand (2101/0000): data the CPU sends to a client without a request
// (SLMP Reference Manual §5.11). The manuals give only the command,
// subcommand and data and leave the frame around them to the device; the
// frame chosen here (docs/timing.md, "Ondemand", inferred) is a normal
// response of the client's own shape: 3E (D0 00) or 4E (D4 00, serial 0000),
// the own-station route 00 FF 03FF 00, the data length, end code 0000, then
// 2101 0000 and the data words — so a client's response parser reads it and
// finds the command where a request's would be.
#pragma once

#include <cstdint>
#include <span>
#include <vector>

#include "protocol/frame.hpp"

namespace slmp::protocol {

inline constexpr std::uint16_t kOndemandCommand = 0x2101;
inline constexpr std::size_t kOndemandMaxWords = 960;   // §9: at most 1920 bytes of send data

// `kind` E4 gives the 4E shape; anything else the 3E one (1E and the
// station-number-extended frame have no Ondemand).
std::vector<std::uint8_t> encode_ondemand(FrameKind kind, Codec codec, std::span<const std::uint16_t> words);

}  // namespace slmp::protocol
