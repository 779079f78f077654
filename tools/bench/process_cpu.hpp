// CPU time another process has used, read from /proc/PID/stat (utime + stime,
// every thread of the process). --server-pid samples it at the end of the
// warm-up and at the end of the run, so a report can say what each request
// cost the server, not only how fast it came back.
//
// Resolution is one clock tick (sysconf(_SC_CLK_TCK), 10 ms on Linux): a 5 s
// run of a server using one core is about 500 ticks, so ±0.2 %.
#pragma once

#include <sys/types.h>

#include <optional>
#include <string_view>

namespace slmp::bench {

// Seconds of CPU (user + system) `pid` has used so far; nullopt when the
// process does not exist (any more) or its stat line cannot be read.
std::optional<double> process_cpu_seconds(pid_t pid);

// The fields after the command name of a /proc/PID/stat line, for tests:
// nullopt unless `line` holds utime (field 14) and stime (field 15).
std::optional<double> cpu_seconds_from_stat(std::string_view line, double ticks_per_second);

// The same for this process (getrusage), to show whether the client itself
// ran out of CPU.
double own_cpu_seconds();

}  // namespace slmp::bench
