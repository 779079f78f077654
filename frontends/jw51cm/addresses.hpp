// JW names of cells for other tools (the HTTP API's device endpoints), in
// octal as Sharp writes them (JW-51CM manual, docs/jw51cm.md): a relay `04033`
// (5 octal digits), a register `09000` (N9ooo: file-0 byte 0o4000 + N·0o1000
// + ooo) and a file address `F1:0200` (file, octal byte address) — resolved
// through the memory map to the device that holds the cell: relay 04033 is
// M2075, register 09000 is D0 (a word holds two registers, the lower address
// in the low byte, so a register or file address must be even).
#pragma once

#include <optional>
#include <string>
#include <string_view>

#include "devicemodel/device_table.hpp"
#include "frontends/jw51cm/memory_map.hpp"

namespace slmp::jw51cm {

// Octal digits to a number ("1410" -> 0o1410); nullopt when one is 8 or 9, or
// there are none or more than 7. Sharp's addresses, T/C numbers and parameter
// addresses are all written this way.
std::optional<std::uint32_t> octal(std::string_view digits);

// nullopt with *error empty: `text` is not a JW name (try the device table).
// nullopt with *error set: it is one, and the message says what is wrong.
std::optional<devicemodel::DeviceAddress> resolve_name(const MemoryMap& map, std::string_view text, std::string* error);

}  // namespace slmp::jw51cm
