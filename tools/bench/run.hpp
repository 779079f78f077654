// Runs one benchmark from options to results.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "tools/bench/options.hpp"
#include "tools/bench/stats.hpp"

namespace slmp::bench {

struct OperationResult {
    std::string name;
    std::uint64_t ok = 0;        // requests answered with end code 0 and the expected data
    Recorder recorder;           // error counts (latency samples already summarised)
    Latency latency;             // over the ok requests only
};

// CPU time over the measured part of the run (--server-pid).
struct CpuUse {
    bool measured = false;       // false without --server-pid, or when the server's stat could not be read
    double server_s = 0;         // CPU seconds of the server process, all threads, user + system
    double client_s = 0;         // CPU seconds of slmp-bench itself over the same time
    double wall_s = 0;           // the time between the two samples
};

struct Results {
    std::string target;          // "tcp 127.0.0.1:5000" as resolved; "tcp <--targets> (N targets)"
    std::size_t targets = 1;
    double seconds = 0;          // measured time: end of warm-up to the last measured outcome
    std::uint64_t sent = 0;      // measured requests sent
    std::vector<OperationResult> operations;   // in --mix order
    OperationResult total;
    std::string fatal;           // non-empty when the run could not take place
    CpuUse cpu;
};

// Throws std::invalid_argument for option values only found wrong here
// (unknown --mix entry, bad --device, a host that is not loopback).
Results run_benchmark(const Options& options);

}  // namespace slmp::bench
