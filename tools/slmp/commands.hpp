// The slmp subcommands: one table, one row each (name, usage, the command
// options it accepts, the function that runs it). Each family lives in its own
// file: device_commands.cpp (read, write), random_commands.cpp, monitor_command.cpp,
// label_commands.cpp, remote_commands.cpp (run, stop, pause, reset, latch-clear), info_commands.cpp
// (type, selftest), node_commands.cpp (nodes, status), password_commands.cpp (lock, unlock).
#pragma once

#include <initializer_list>
#include <string>
#include <string_view>

#include "tools/slmp/client.hpp"
#include "tools/slmp/options.hpp"
#include "tools/slmp/output.hpp"

namespace slmp::cli {

// What a subcommand gets. It throws UsageError / ConnectionError / EndCodeError
// on failure; returning means success (exit code 0).
struct Invocation {
    const Options& options;
    Client& client;
    Output& output;
};

using Runner = void (*)(Invocation&);

struct CommandSpec {
    std::string_view name;
    std::string_view usage;     // arguments, as shown in --help
    std::string_view summary;
    std::initializer_list<std::string_view> accepts;   // command options it takes
    Runner run;
};

const CommandSpec* find_command(std::string_view name);
std::string commands_help();

// The runners, one per row.
void run_read(Invocation& in);
void run_write(Invocation& in);
void run_random(Invocation& in);
void run_monitor(Invocation& in);
void run_label(Invocation& in);
void run_file(Invocation& in);
void run_remote_run(Invocation& in);
void run_remote_stop(Invocation& in);
void run_remote_pause(Invocation& in);
void run_remote_reset(Invocation& in);
void run_remote_latch_clear(Invocation& in);
void run_type(Invocation& in);
void run_selftest(Invocation& in);
void run_nodes(Invocation& in);
void run_status(Invocation& in);
void run_lock(Invocation& in);
void run_unlock(Invocation& in);
void run_ondemand(Invocation& in);
void run_probe(Invocation& in);
void run_diff(Invocation& in);

}  // namespace slmp::cli
