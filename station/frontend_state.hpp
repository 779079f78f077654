// The protocol faces' own state, beyond the device memory they map onto
// (frontends/face.hpp: Unit::save/restore; each face's docs page says what).
// Held as named parts, prefixed with the face's name, so a
// station snapshot, its file form and the state directory carry them the same
// way; a part whose size does not match this configuration is refused.
#pragma once

#include <cstdint>
#include <filesystem>
#include <map>
#include <span>
#include <string>
#include <vector>

#include "station/station.hpp"

namespace slmp::station {

using UnitParts = std::map<std::string, std::vector<std::uint8_t>>;

UnitParts take_units(const Station::FrontEnds& frontends);
// Throws config::ConfigError naming the part when it does not fit; then nothing changed.
void give_units(const UnitParts& parts, Station::FrontEnds& frontends);

// The state directory's units.bin: "SLMPUNT1" | u32 parts | per part u8 n +
// name | u32 n + bytes.
std::vector<std::uint8_t> encode_units(const UnitParts& parts);
// Throws config::ConfigError naming `source` when the bytes are not such a file.
UnitParts decode_units(std::span<const std::uint8_t> bytes, const std::string& source);

}  // namespace slmp::station
