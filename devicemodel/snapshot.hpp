// Device memory as bytes, for the state directory (the file handling is the
// server's). A snapshot holds every stored device except SM/SD (the system
// rebuilds those; SnapshotContents::WithSystem keeps them too) and ends with a checksum, so a damaged file is recognised
// and refused rather than half-loaded. Remote-operation state is not saved: a
// power cycle erases it on the real CPU (SLMP Reference Manual §5.6).
//
// Layout (all integers little-endian):
//   "SLMPSNAP" u32 version(1) | u8 n + profile name | u32 areas
//   per area: u8 n + area name ("D", "T", ...) | u32 size | u8 parts
//     per part: u8 part | runs of (u32 zeros, u32 literals, literals × u32) covering size
//   the label area (DeviceMemory::label_area_words, when not empty) is one more
//   such entry named "LABEL" (size = words, one part 0); it comes back with
//   RestoreScope::All only (labels are not latched)
//   u64 FNV-1a of everything before it
#pragma once

#include <cstdint>
#include <span>
#include <string>
#include <string_view>
#include <vector>

#include "devicemodel/device_clear.hpp"
#include "devicemodel/device_memory.hpp"

namespace slmp::devicemodel {

// What a snapshot holds: the state directory saves program memory only (the
// system rebuilds SM/SD at power-on); a station snapshot taken over the HTTP
// API (station/station_snapshot.hpp) puts the CPU back as it was, SM/SD too.
enum class SnapshotContents : std::uint8_t { Devices, WithSystem };

std::vector<std::uint8_t> encode_snapshot(const DeviceMemory& memory, std::string_view profile_name,
                                          SnapshotContents contents = SnapshotContents::Devices);

enum class RestoreScope : std::uint8_t {
    Latched,   // like a power cycle: only latched devices (L, R/ZR, latch ranges) come back
    All,       // every device as it was saved
};

struct RestoreResult {
    bool ok = false;
    std::string error;                   // why nothing was restored
    std::vector<std::string> warnings;   // e.g. an area whose size changed (the common part was restored)
};

// Checks the whole snapshot first; on any damage restores nothing.
RestoreResult restore_snapshot(std::span<const std::uint8_t> bytes, DeviceMemory& memory,
                               std::string_view profile_name, const LatchMap& latch, RestoreScope scope);

}  // namespace slmp::devicemodel
