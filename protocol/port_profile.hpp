// What one CPU's SLMP port answers differently from another's, as plain data:
// the frames it serves, what it does with requests it does not serve, its end
// codes and its limits. Loaded with the CPU's facts from the same profile file
// (config/profiles/*.json, by config/); the CPU's own facts — identity, device
// sizes, special registers, password rule — are devicemodel::CpuProfile.
// Facts: real-CPU measurements.
#pragma once

#include <array>
#include <cstdint>
#include <vector>

#include "devicemodel/device_table.hpp"
#include "devicemodel/drive_spec.hpp"

namespace slmp::protocol {

// How a port reacts to a request it does not serve.
struct Refusal {
    enum class Kind : std::uint8_t { Serve, EndCode, Close, Silence };
    Kind kind = Kind::Serve;      // Serve: the port serves the request normally
    std::uint16_t end_code = 0;   // for EndCode
};

struct PointLimit {
    std::uint32_t max = 0;
    std::uint16_t end_code = 0;
};

// A limit that depends on the subcommand family: Q form (00□0/00□1) or iQ-R
// form (00□2/00□3). With the Q form's extended subcommands (0080/0081) each
// point or block counts twice (SLMP Reference Manual §5.2, *1).
struct FormLimit {
    std::uint32_t q = 0;
    std::uint32_t iqr = 0;
    std::uint16_t end_code = 0;
};

struct PortProfile {
    Refusal frame_4e;                 // what a 4E request gets
    // The A-compatible 1E frame (docs/frames.md): served, or its bytes are no
    // frame at all (skipped unanswered, as an iQ-R built-in port does).
    bool frame_1e = false;
    std::uint8_t pc_type_1e = 0;      // 1E PC type read 15 answers this
    // The station-number-extended frame (68 00; CC-Link IE TSN modules): served,
    // or not a frame at all (skipped unanswered, as a port without it does).
    bool station_extended_frame = false;
    // A network/Ethernet module's port passes a request that names another
    // network/station on (docs/plants.md, "Networks and routes"); a CPU's
    // built-in port reaches only its own station (4A01/4A02).
    bool relays = false;
    // The port is an SLMP-compatible device's (JA §3.12-3.14): it serves the
    // node commands 0E30-0E53. The Mitsubishi CPUs' and modules' ports are
    // their clients (iQ Sensor Solution) and answer C059 (docs/nodes.md).
    bool node_commands = false;
    // Commands per connection (SLMP Reference Manual §3.3): 1 + pipeline_buffer ÷ connections
    // requests may wait in the port's receive buffer; 0 = no limit. Requests
    // beyond it get `pipeline_over_limit` (docs/end-codes.md: CEE0).
    std::uint32_t pipeline_buffer = 0;
    Refusal pipeline_over_limit{Refusal::Kind::EndCode, 0xCEE0};
    Refusal iqr_subcommands;          // what 0002/0003 (iQ-R form) requests get
    // Commands refused beyond what the port family refuses (the command table's families).
    std::vector<std::uint16_t> unsupported_commands;
    std::uint16_t not_supported_code = 0xC059;

    std::uint16_t out_of_range_code = 0x4031;      // start or span past the device size
    std::uint16_t not_accessible_code = 0x4030;    // device this command/path may not touch
    std::uint16_t unknown_device_code = 0xC05B;    // device code the CPU does not know
    std::uint16_t bad_unit_code = 0xC05C;          // bit units on a word device and the like
    // A write while the CPU is in RUN on a port with online change disabled
    // (0055: the L/Q E71-style code; SLMP Reference Manual ch. 6).
    std::uint16_t online_change_code = 0x0055;
    // A write or remote operation while the CPU's system protect is on
    // (4004, inferred: the 4xxx "system protect" code of Q/L CPUs).
    std::uint16_t system_protect_code = 0x4004;
    bool online_change = true;                     // the port's default: writes served in RUN
    // The ports' default for TCP clients at once (profile "max_connections"):
    // the CPU's connection count, 64 when a profile file does not say.
    unsigned max_connections = 64;
    // What each refused file operation answers (profile "file_end_codes",
    // docs/end-codes.md), indexed by devicemodel::FileFault; [None] is 0.
    std::array<std::uint16_t, devicemodel::kFileFaultCount> file_end_codes{};

    PointLimit batch_words;           // 0401/1401 word units
    PointLimit batch_bits_binary;     // 0401/1401 bit units, binary code
    PointLimit batch_bits_ascii;      // 0401/1401 bit units, ASCII code
    std::uint32_t loopback_max_bytes = 960;
    FormLimit random_read_points;     // 0403: word + double-word points
    FormLimit random_write_weight;    // 1402 word units: 12·words + 14·double words
    FormLimit random_write_bits;      // 1402 bit units: points
    FormLimit monitor_points;         // 0801: word + double-word points
    FormLimit block_count;            // 0406/1406: word blocks + bit blocks
    PointLimit block_points;          // 0406/1406: total points (1406 adds 4 or 9 per block)
    // Over-limit 008x random/monitor access answers this instead (QJ71E71-100:
    // 4080); 0 = the limit's own code.
    std::uint16_t extended_over_limit_code = 0;
    Refusal mixed_block_write;        // 1406 with word and bit blocks in one request

    std::vector<devicemodel::Area> read_only;   // S over built-in Ethernet
    bool zr_ascii_hex = false;        // ASCII frames number ZR in hex (the manuals' form)
};

}  // namespace slmp::protocol
