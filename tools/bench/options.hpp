// slmp-bench command line: what to send, where, how hard and for how long.
#pragma once

#include <sys/types.h>

#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "tools/bench/targets.hpp"

namespace slmp::bench {

struct Options {
    std::string host = "127.0.0.1";
    std::uint16_t port = 5000;
    // Where connection i goes: targets[i % size]. --host/--port make one
    // target; --targets (text kept for the report) any number.
    std::vector<Target> targets;
    std::string targets_text;
    bool udp = false;
    bool ascii = false;
    bool e4 = false;                  // 4E frames (serial numbers); required for depth > 1
    unsigned connections = 1;
    unsigned depth = 1;               // requests in flight per connection
    double duration = 5.0;            // seconds measured; 0 = no time limit (needs requests)
    std::uint64_t requests = 0;       // requests measured in all; 0 = no count limit
    double warmup = 0.5;              // seconds run before measuring, not counted
    double timeout = 2.0;             // seconds per request before it counts as lost
    std::vector<std::string> mix{"read1"};
    std::string device;               // start device for every operation; empty = defaults
    bool octal_xy = false;            // --device's X/Y (and ASCII frames) in octal, as on an FX5
    bool json = false;
    bool allow_remote = false;        // a non-loopback target must be asked for explicitly
    pid_t server_pid = 0;             // sample this process's CPU time over the run; 0 = none
};

// Parses and validates argv. Returns nullopt when the program should exit now
// (after --help, or after printing a usage error); `exit_code` says with what.
std::optional<Options> parse_options(int argc, char** argv, int& exit_code);

}  // namespace slmp::bench
