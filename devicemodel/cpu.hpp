// One simulated CPU: its profile and its device memory. Everything that touches
// device memory goes through a Cpu, on the server's single core thread.
#pragma once

#include "devicemodel/cpu_profile.hpp"
#include "devicemodel/device_memory.hpp"

namespace slmp::devicemodel {

class Cpu {
public:
    explicit Cpu(CpuProfile profile);

    const CpuProfile& profile() const { return profile_; }
    DeviceMemory& memory() { return memory_; }
    const DeviceMemory& memory() const { return memory_; }

    // Whether [start, start + count) devices may be accessed: the whole span must
    // fit, except in areas where the profile checks only the start (iQ-R R/ZR).
    bool in_range(Area area, std::uint64_t start, std::uint64_t count) const;

private:
    void publish_device_sizes();

    CpuProfile profile_;
    DeviceMemory memory_;
};

}  // namespace slmp::devicemodel
