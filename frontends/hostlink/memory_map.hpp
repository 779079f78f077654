// The Ladder Motion memory map (Ladder Motion host-link manual, docs/hostlink.md): each area the
// manual names — CIO channels, HR, LR, AR, DM, VR, the timer/counter present
// values, set values and up flags — bound to a run of the station's device
// memory (devicemodel::DeviceMemory). The binding is the alias table: DM0100 is
// D100 by default, so SLMP, the HTTP API, snapshots and persistence reach the
// same cells (§11.2). Ranges are not documented by the manual; every size is
// configurable, the defaults are the C2000H-era OMRON sizes §4 quotes.
#pragma once

#include <array>
#include <cstdint>
#include <optional>
#include <string>
#include <string_view>

#include "devicemodel/device_memory.hpp"
#include "devicemodel/device_table.hpp"

namespace slmp::hostlink {

enum class Area : std::uint8_t { Cio, Hr, Lr, Ar, Dm, Vr, TcPresent, TcSet, TcUp, Count };

// What one element of an area is: a 16-bit channel/word with a bit view, a
// 32-bit VR (two words, low word first), or a single flag bit.
enum class Element : std::uint8_t { Channel, LongWord, Flag };

struct AreaInfo {
    Area area;
    std::string_view key;           // the configuration key: "CIO", "DM", "TC_UP" ...
    Element element;
    std::string_view default_device;   // where the area starts in device memory
    std::uint32_t default_size;        // elements (channels, words, VRs, T/C numbers)
    std::string_view name;             // for messages and docs
};

// The nine areas, in the manual's order.
const std::array<AreaInfo, static_cast<std::size_t>(Area::Count)>& area_infos();
const AreaInfo& info(Area area);
std::optional<Area> area_by_key(std::string_view key);

struct Binding {
    devicemodel::DeviceAddress base;   // element 0 of the area
    std::uint32_t size = 0;            // elements
};

class MemoryMap {
public:
    MemoryMap();   // the defaults of area_infos()

    const Binding& binding(Area area) const { return bindings_[static_cast<std::size_t>(area)]; }
    void bind(Area area, Binding binding) { bindings_[static_cast<std::size_t>(area)] = binding; }
    std::uint32_t size(Area area) const { return binding(area).size; }

    // Why a binding cannot serve its area (wrong device unit, runs past the
    // device's configured size), or empty when every area fits `memory`.
    // The message names the area's key and the fix.
    std::string check(const devicemodel::DeviceMemory& memory) const;

private:
    std::array<Binding, static_cast<std::size_t>(Area::Count)> bindings_;
};

// Element access through a binding. Callers check ranges first (MemoryMap::size).
class AreaAccess {
public:
    AreaAccess(devicemodel::DeviceMemory& memory, const MemoryMap& map) : memory_(memory), map_(map) {}

    std::uint16_t word(Area area, std::uint32_t index) const;        // Channel areas
    void set_word(Area area, std::uint32_t index, std::uint16_t value);
    std::uint32_t long_word(std::uint32_t index) const;               // VR
    void set_long_word(std::uint32_t index, std::uint32_t value);
    // A bit of a Channel area by bit index 16·channel + bit, or a Flag area's flag.
    bool bit(Area area, std::uint32_t index) const;
    void set_bit(Area area, std::uint32_t index, bool on);

private:
    devicemodel::DeviceMemory& memory_;
    const MemoryMap& map_;
};

}  // namespace slmp::hostlink
