// slmp-bench --baseline-server: the cheapest server that still answers the
// benchmark's requests correctly, to measure this machine's ceiling — what the
// kernel, loopback and a plain epoll loop cost per request — next to slmp-sim.
//
// Plain Linux epoll, no Asio: every system call is visible in this file, and
// nothing else runs per request. N threads, each with its own epoll set:
//   TCP  one listener, accepted by thread 0 and dealt round-robin to the
//        threads (their epoll sets), so 16 connections on 2 threads are 8 + 8
//        — SO_REUSEPORT listeners would split them by a hash, often 10 + 6;
//   UDP  one SO_REUSEPORT socket per thread on the same port; the kernel
//        spreads the client sockets over them by a hash of their addresses.
// Each read answers every whole request in it (baseline_answer.hpp) with one
// send. No timeouts, no limits besides the request size, no device memory.
#pragma once

#include <cstdint>
#include <optional>
#include <string>

namespace slmp::bench::baseline {

struct ServerOptions {
    unsigned threads = 1;
    std::string bind = "127.0.0.1";
    std::uint16_t tcp_port = 5000;   // 0 = any free port
    std::uint16_t udp_port = 5000;   // 0 = any free port
    std::string ready_file;          // written atomically once listening: {"tcp":[P],"udp":[P],"threads":N,"pid":N}
};

// Serves until SIGINT or SIGTERM; returns the exit status (0, or 1 when a
// socket could not be opened, with the reason on stderr).
int serve(const ServerOptions& options);

// `slmp-bench --baseline-server [options]`: parses the mode's own options and
// serves. Exit status 2 for a usage error.
int baseline_main(int argc, char** argv);

}  // namespace slmp::bench::baseline
