// The JW memory map (JW-51CM manual, docs/jw51cm.md): data memory is byte
// addressed by file (DSEG 0–7) and byte address; every byte a host can name
// lives in a run of the station's device memory, so SLMP, the HTTP API,
// snapshots and persistence reach the same cells. Bit-device runs hold 8
// relays a byte (relay …0 = bit 0); word-device runs hold 2 bytes a word, the
// lower address in the low byte (inferred; the manual does not say, and it is
// how SLMP binary lays words out).
#pragma once

#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "devicemodel/device_memory.hpp"
#include "devicemodel/device_table.hpp"

namespace slmp::jw51cm {

struct Region {
    std::uint8_t file = 0;           // DSEG
    std::uint32_t first_byte = 0;    // file byte address of the region's first byte
    std::uint32_t bytes = 0;
    devicemodel::DeviceAddress base; // the device holding the first byte
    std::string name;                // for messages: "file 0 relays 00000-15777"
};

class MemoryMap {
public:
    // Defaults: file 0 relays 00000–15777 on M0–M7167 (M index = relay number
    // read as octal), file 0 bytes 0o1600–0o3777 on D2560–D3135, registers
    // 09000–99777 (0o4000–0o15777) on D0–D2559, bytes 0o16000–0o17777 on
    // D3136–D3647; files 1–7 of `file_bytes` each on ZR, file f from
    // ZR(file_bytes/2·(f−1)). T/C 0–1777 (octal) on TN/TS.
    explicit MemoryMap(std::uint32_t file_bytes = 16384, std::uint32_t timers = 1024);

    const std::vector<Region>& regions() const { return regions_; }
    std::uint32_t file_size(std::uint8_t file) const;   // bytes a file has (0: none)
    std::uint32_t timers() const { return timers_; }
    const devicemodel::DeviceAddress& timer_values() const { return timer_values_; }
    const devicemodel::DeviceAddress& timer_contacts() const { return timer_contacts_; }

    // Why a region or the timers cannot fit `memory`, or empty.
    std::string check(const devicemodel::DeviceMemory& memory) const;

    // The region holding byte `address` of `file`, or null.
    const Region* find(std::uint8_t file, std::uint32_t address) const;
    bool contains(std::uint8_t file, std::uint32_t address, std::uint32_t count) const;

private:
    std::vector<Region> regions_;
    std::uint32_t timers_;
    devicemodel::DeviceAddress timer_values_, timer_contacts_;
};

// Byte access through the map; callers check contains() first.
class ByteAccess {
public:
    ByteAccess(devicemodel::DeviceMemory& memory, const MemoryMap& map) : memory_(memory), map_(map) {}
    std::uint8_t byte(std::uint8_t file, std::uint32_t address) const;
    void set_byte(std::uint8_t file, std::uint32_t address, std::uint8_t value);

private:
    devicemodel::DeviceMemory& memory_;
    const MemoryMap& map_;
};

}  // namespace slmp::jw51cm
