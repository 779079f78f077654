// From a device field to the memory it names, for every device command.
// One place decides: which memory (the CPU's own, a network's link devices, a
// module's or a CPU's buffer memory), the index-register and indirect
// modifications, which devices a command may not name, and the range check.
#pragma once

#include <cstdint>
#include <string_view>

#include "devicemodel/cpu.hpp"
#include "protocol/command_table.hpp"

namespace slmp::protocol {

// Which command names the device; each has its own list of devices it may not
// name (SLMP Reference Manual §5.2 "devices that cannot be specified",
// corrected by real-CPU measurements where real CPUs differ).
enum class Use : std::uint8_t { BatchRead, BatchWrite, RandomRead, RandomWrite, Monitor, BlockRead, BlockWrite };

struct Target {
    devicemodel::DeviceMemory* memory = nullptr;
    const devicemodel::DeviceSpec* spec = nullptr;
    std::uint32_t number = 0;
    const devicemodel::Cpu* owner = nullptr;   // set when `memory` is a CPU's own device memory
};

// Resolves a field; Ok or the end code the profile gives for the problem.
EndCode resolve(CommandContext& ctx, const DeviceField& field, Use use, Target& target);

// Whether `devices` devices from the target's number exist (the CPU's own
// memory follows the profile's start-only rule for R/ZR).
bool fits(const Target& target, std::uint64_t devices);

// How many devices `words` words starting at the target cover: 16 a word for
// bit devices, one a word for word devices, one per 2 (or 4) words for long ones.
std::uint64_t devices_in_words(const devicemodel::DeviceSpec& spec, std::uint64_t words);

}  // namespace slmp::protocol
