// One simulated CPU: its profile and its device memory. Everything that touches
// device memory goes through a Cpu, on the server's single core thread.
#pragma once

#include <map>
#include <memory>
#include <string>

#include "devicemodel/cpu_profile.hpp"
#include "devicemodel/device_memory.hpp"
#include "devicemodel/labels.hpp"
#include "devicemodel/runtime.hpp"

namespace slmp::devicemodel {

class DriveSet;   // file drives (devicemodel/drives.hpp), kept out of this widely included header
class Node;       // the SLMP-compatible device's identity and parameters (devicemodel/node.hpp), likewise

// An intelligent function module's buffer memory, reached as U(io)\G(n) by the
// 008x device commands and as bytes by Extend Unit 0601/1601.
struct Module {
    std::string model;
    std::uint32_t head_address;   // 0601/1601 start address of buffer word 0 (the module's table entry)
    DeviceMemory memory;          // area G only
};

class Cpu {
public:
    explicit Cpu(CpuProfile profile);

    const CpuProfile& profile() const { return profile_; }
    DeviceMemory& memory() { return memory_; }
    const DeviceMemory& memory() const { return memory_; }

    // Whether [start, start + count) devices may be accessed: the whole span must
    // fit, except in areas where the profile checks only the start (iQ-R R/ZR).
    bool in_range(Area area, std::uint64_t start, std::uint64_t count) const;

    // Modules by start I/O number ÷ 16 (the "U" number); null when none is there.
    Module* module(std::uint16_t io_number);
    void add_module(std::uint16_t io_number, std::string model, std::uint32_t buffer_words, std::uint32_t head_address);
    const std::map<std::uint16_t, std::unique_ptr<Module>>& modules() const { return modules_; }
    // Link devices (X Y B SB W SW) of the network module on network `number` (J□\...).
    DeviceMemory* network(std::uint16_t number);
    void add_network(std::uint16_t number, const DeviceSizes& sizes);
    const std::map<std::uint16_t, std::unique_ptr<DeviceMemory>>& networks() const { return networks_; }
    // What Memory Read/Write 0613/1613 reach: the CPU buffer memory (area G of
    // this CPU) unless the profile gives the port a buffer memory of its own.
    DeviceMemory& station_buffer() { return station_buffer_ ? *station_buffer_ : memory_; }
    // The port's own buffer memory; null when 0613/1613 reach the CPU buffer.
    DeviceMemory* own_station_buffer() { return station_buffer_.get(); }

    // Operating state, scan cycle, timers, special registers, remote password
    // (devicemodel/runtime.hpp); its operations take memory() explicitly.
    // Global labels (devicemodel/labels.hpp); their values live in memory().
    LabelTable& labels() { return labels_; }
    const LabelTable& labels() const { return labels_; }

    Runtime& runtime() { return runtime_; }
    const Runtime& runtime() const { return runtime_; }

    // The CPU's file drives (1810-182A): the family's drives in memory until
    // the configuration attaches folders (config::attach_drives).
    DriveSet& drives() { return *drives_; }
    const DriveSet& drives() const { return *drives_; }
    void set_drives(std::shared_ptr<DriveSet> drives) { drives_ = std::move(drives); }

    // What the node commands 0E30-0E53 read and change (devicemodel/node.hpp):
    // CPU No.1's is the station's, on a port whose profile has "node_commands".
    Node& node() { return *node_; }
    const Node& node() const { return *node_; }

private:
    void publish_device_sizes();

    CpuProfile profile_;
    DeviceMemory memory_;
    std::unique_ptr<DeviceMemory> station_buffer_;
    std::map<std::uint16_t, std::unique_ptr<Module>> modules_;
    std::map<std::uint16_t, std::unique_ptr<DeviceMemory>> networks_;
    LabelTable labels_;
    Runtime runtime_{profile_.family};
    std::shared_ptr<DriveSet> drives_;
    std::shared_ptr<Node> node_;
};

}  // namespace slmp::devicemodel
