// What a scenario can match in a request before the CPU sees it: the frame
// (3E/4E, binary/ASCII), the command and subcommand, and the devices a device
// command reads or writes. Decoded from the bytes with the protocol's own
// frame scanner and FieldReader, without touching device memory.
#pragma once

#include <cstdint>
#include <span>
#include <string>
#include <vector>

#include "devicemodel/cpu_profile.hpp"
#include "protocol/frame.hpp"
#include "scenarios/scenario.hpp"

namespace slmp::scenarios {

struct RequestView {
    bool complete = false;              // a whole request frame is at the start of the input
    std::size_t size = 0;               // its length in bytes
    protocol::FrameHeader header;
    bool has_command = false;           // command and subcommand could be read
    std::uint16_t command = 0;
    std::uint16_t subcommand = 0;
    Access access = Access::Any;        // Read or Write for device commands
    std::vector<DeviceRange> devices;   // the CPU's own devices the request names (008x: plain devices only)

    // Filled by the caller: who sent it.
    Transport transport = Transport::Tcp;
    std::uint64_t connection = 0;       // n-th TCP connection since start (0 for UDP)
    std::string client;                 // IP address
    std::string peer;                   // "tcp:127.0.0.1:50312", for log lines
};

// Decodes the frame at the start of `input` (nothing when it is incomplete or
// not a frame). Batch, random, block and monitor-registration commands list
// their devices; a field that does not decode just ends the list.
RequestView view_request(std::span<const std::uint8_t> input, protocol::DataCodePolicy policy,
                         std::size_t max_frame_bytes, const devicemodel::CpuProfile& profile);

// Whether any device of the request lies in any of `ranges`.
bool touches(const RequestView& request, const std::vector<DeviceRange>& ranges);

}  // namespace slmp::scenarios
