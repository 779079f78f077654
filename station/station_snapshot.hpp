// A whole station at one moment, for POST /api/snapshots, POST /api/reset and
// --snapshot (docs/ci.md, "Snapshots"). Device memory is held in the state
// directory's format (devicemodel/snapshot.hpp, SM/SD included), so whatever
// that format covers a snapshot covers too; the running CPU's state
// (operating state and holds, error, timers' tracking, scan statistics,
// password failures and lock-out) is a copy of its devicemodel::Runtime.
//
// Not held: the per-connection remote-password unlock (it belongs to the
// connection, as on the real CPU), the scenarios' progress (a restore starts
// the snapshot's scenarios afresh) and the clock's mode and speed (the test
// harness's, not the PLC's). Restoring sets the CPU clock back to the
// snapshot's time, so timers, SM/SD clocks and the calendar agree with it.
#pragma once

#include <chrono>
#include <cstdint>
#include <filesystem>
#include <map>
#include <span>
#include <string>
#include <vector>

#include "devicemodel/node.hpp"
#include "devicemodel/runtime.hpp"
#include "scenarios/scenario.hpp"

namespace slmp::station {

struct CpuSnapshot {
    std::vector<std::uint8_t> memory;                                 // devicemodel snapshot, SM/SD included
    devicemodel::Runtime runtime;                                     // when has_runtime
    bool has_runtime = true;                                          // false: read from a file
    devicemodel::RunSwitch run_switch = devicemodel::RunSwitch::Run;  // a file's (CPU No.1)
    std::map<std::uint16_t, std::vector<std::uint8_t>> modules;       // by U number (buffer memory G)
    std::map<std::uint16_t, std::vector<std::uint8_t>> networks;      // by network No. (link devices)
    std::vector<std::uint8_t> station_buffer;                         // the port's own, when the profile has one
    // The node of the node commands (identity after IP Address Set, parameters,
    // a write under way; docs/nodes.md): in memory only, not in the file form.
    devicemodel::Node node;
    bool has_node = true;                                             // false: read from a file
};

struct StationSnapshot {
    std::vector<CpuSnapshot> cpus;                                    // CPU No.1 first
    std::vector<std::vector<scenarios::Scenario>> scenarios;          // by runner, in load order
    bool has_scenarios = true;                                        // false: read from a file (keep what runs)
    std::chrono::steady_clock::time_point clock{};                    // CPU time when taken
    bool has_clock = false;                                           // false in a bare station
    std::chrono::system_clock::time_point taken{};
    // The front ends' unit state by part (station/frontend_state.hpp); a part
    // missing here leaves that front end as it is.
    std::map<std::string, std::vector<std::uint8_t>> units;

    std::size_t memory_bytes() const;
};

// The file form (GET /api/snapshots/{name}/file, --snapshot): device memory of
// every store and the RUN/STOP switch; the rest of the runtime, the scenarios
// and the clock are not in it. Layout: "SLMPSTN1" | u32 blobs | per blob
// u8 n + name ("cpu1", "module 3", "network 1", "station buffer", "switch") |
// u32 n + bytes; each memory blob is a devicemodel snapshot with its checksum;
// "unit <part>" blobs hold the front ends' unit state.
std::vector<std::uint8_t> encode_station_file(const StationSnapshot& snapshot);
// Throws config::ConfigError naming the file and what is wrong.
StationSnapshot decode_station_file(std::span<const std::uint8_t> bytes, const std::string& source);

}  // namespace slmp::station
