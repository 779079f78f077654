// How one label value travels (SLMP Reference Manual §5.3): 32-bit types
// as one 32-bit value (ASCII: 8 digits, high first), LREAL as one 64-bit
// value, everything else (bits, words, strings) as 16-bit words. Shared by
// the label handlers and the client encoder/decoder, so both sides agree.
#pragma once

#include <cstdint>
#include <vector>

#include "devicemodel/label_types.hpp"
#include "protocol/fields.hpp"

namespace slmp::protocol {

// 16, 32 or 64: the unit a value of `type` is sent in.
unsigned label_value_bits(devicemodel::BasicType type);
// One value, `words` long (low word first), in its unit.
void write_label_value(FieldWriter& out, devicemodel::BasicType type, const std::vector<std::uint16_t>& words);
std::vector<std::uint16_t> read_label_value(FieldReader& in, devicemodel::BasicType type, std::uint32_t words);

}  // namespace slmp::protocol
