// Host-link names of cells for other tools (the HTTP API's device endpoints):
// an area key and a decimal channel or word number, as the manual writes them
// — CIO0010, HR5, LR0, AR27, DM0100, VR3 — resolved through the station's
// memory map to the device that holds the cell (DM0100 is D100 by default).
#pragma once

#include <optional>
#include <string>
#include <string_view>

#include "devicemodel/device_table.hpp"
#include "frontends/hostlink/memory_map.hpp"

namespace slmp::hostlink {

struct NamedCell {
    devicemodel::DeviceAddress device;   // channel n of a bit-device area: its first bit (16 a channel)
    bool long_word = false;              // VR: two words, low word first (read it as dwords)
};

// nullopt with *error empty: `text` is not a host-link name (try the device
// table). nullopt with *error set: it is one, and the message says what is wrong.
std::optional<NamedCell> resolve_name(const MemoryMap& map, std::string_view text, std::string* error);

}  // namespace slmp::hostlink
