// The protocol core's one entry point: bytes in, an Outcome out. No I/O, no
// threads; the TCP and UDP front ends and the unit tests all call process().
#pragma once

#include <cstdint>
#include <span>
#include <string>
#include <vector>

#include "devicemodel/cpu.hpp"
#include "protocol/end_code.hpp"
#include "protocol/frame.hpp"

namespace slmp::protocol {

// Per-connection state (one per TCP connection; one per UDP port). It grows
// with monitor registrations and the remote password lock.
struct Session {
    std::uint64_t id = 0;
};

struct EngineOptions {
    std::size_t max_frame_bytes = 8192;   // a larger length field closes the connection
};

struct Outcome {
    enum class Action : std::uint8_t {
        NeedMore,   // no whole frame yet; nothing consumed
        Respond,    // send `response`
        Silent,     // consume and send nothing (garbage, frames the port ignores)
        Close,      // close the connection (oversized frame, profile says so)
    };
    Action action = Action::NeedMore;
    std::size_t consumed = 0;
    std::vector<std::uint8_t> response;
    std::string note;              // why a request was rejected or ignored; empty on success
    std::uint16_t command = 0;
    std::uint16_t subcommand = 0;
    EndCode end_code = EndCode::Ok;
};

class Engine {
public:
    Engine(devicemodel::Cpu& cpu, EngineOptions options = {}) : cpu_(cpu), options_(options) {}

    // Looks at the start of `input` and handles at most one frame.
    Outcome process(std::span<const std::uint8_t> input, DataCodePolicy policy, Session& session);

    devicemodel::Cpu& cpu() { return cpu_; }
    const EngineOptions& options() const { return options_; }

private:
    devicemodel::Cpu& cpu_;
    EngineOptions options_;
};

}  // namespace slmp::protocol
