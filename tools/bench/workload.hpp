// What slmp-bench sends: the operations of --mix, encoded once up front.
//
// Every request is built before the run by protocol/client.hpp, once per
// serial-number slot, so the timed loop only copies pointers: encoding cost
// never lands in the measured latency or steals CPU from the server.
#pragma once

#include <cstddef>
#include <cstdint>
#include <string>
#include <vector>

#include "protocol/frame.hpp"
#include "tools/bench/options.hpp"

namespace slmp::bench {

struct Operation {
    std::string name;                                 // "read1", "write960", ...
    std::vector<std::vector<std::uint8_t>> requests;  // [slot]: 4E serial number = slot; 3E: one entry
    std::size_t response_data = 0;                    // bytes after the end code in a good response
};

struct Workload {
    protocol::FrameKind kind = protocol::FrameKind::E3;
    protocol::Codec codec = protocol::Codec::Binary;
    std::vector<Operation> operations;                // in --mix order; connections take them in turn
};

// Throws std::invalid_argument with a message for the user (unknown operation, bad device).
Workload make_workload(const Options& options);

}  // namespace slmp::bench
