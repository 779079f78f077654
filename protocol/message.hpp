// Wrapping a payload in a 3E/4E header, for responses (server) and requests
// (client). The payload is already encoded by a FieldWriter; the length field
// is its size, so it is always right (the "patch the length at the end" idea).
#pragma once

#include <cstdint>
#include <span>
#include <vector>

#include "protocol/frame.hpp"

namespace slmp::protocol {

// 3E, 4E or the station-number-extended frame (binary), with the header's
// serial, route and extended station No. The payload is `payload` followed by
// `more` (a response's end code, then its data: no copy of the data first).
std::vector<std::uint8_t> encode_frame(Direction direction, const FrameHeader& header,
                                       std::span<const std::uint8_t> payload, std::span<const std::uint8_t> more = {});
std::vector<std::uint8_t> encode_frame(Direction direction, FrameKind kind, Codec codec, std::uint16_t serial,
                                       const Route& route, std::span<const std::uint8_t> payload);

}  // namespace slmp::protocol
