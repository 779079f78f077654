// The slmp command line: global options (target, frame, route, output), the
// subcommand, its arguments and its own options. Parsing only; the subcommands
// validate their arguments themselves (commands.hpp).
#pragma once

#include <chrono>
#include <optional>
#include <string>
#include <vector>

#include "protocol/client.hpp"
#include "tools/slmp/client.hpp"

namespace slmp::cli {

struct Options {
    Target target;
    protocol::client::FrameOptions frame;
    protocol::DeviceForm form = protocol::DeviceForm::Q;
    bool json = false;
    std::optional<std::string> password;   // --password: Unlock (1630) before the command
    std::string plant_station;             // --plant-station: look the port up on the simulator's HTTP API
    std::uint16_t api_port = 8080;         // --api-port: where to look it up

    std::string command;
    std::vector<std::string> args;

    // Subcommand options (each subcommand says which of them it accepts).
    bool bits = false;                      // read, write, random write
    std::vector<std::string> dwords;        // random: --dword DEVICE[=VALUE], repeatable
    std::chrono::milliseconds interval{1000};   // monitor
    std::optional<unsigned long> count;     // monitor: stop after N polls
    bool wait = false;                      // ondemand
    bool broadcast = false;                 // nodes: a broadcast search, every answer listed
    bool force = false;                     // run, pause
    std::string clear = "none";             // run
    std::string file_password;              // file: the file's password (empty: none)
    std::string out;                        // probe: the profile file to write
    std::string allow_writes;               // probe: scratch ranges it may write (D9000-D9999,M9000-M9999)
    std::string record;                     // probe, diff: the exchanges as a recording (JSON lines)
    std::string against;                    // diff: HOST:PORT of the second server
    std::string profile;                    // diff: the profile whose limits and sizes the requests probe
    std::optional<std::chrono::milliseconds> silence;   // probe, diff: how long no answer counts as silence
    std::vector<std::string> given;         // names of the subcommand options actually given
};

// Parses argv. Returns nullopt when the program should exit with `exit_code`
// (help printed: 0; usage error printed: 2).
std::optional<Options> parse_options(int argc, char** argv, int& exit_code);

// "500ms", "2s", "1.5s", "1m"; a bare number is refused because its unit would be a guess.
std::optional<std::chrono::milliseconds> parse_duration(const std::string& text);

}  // namespace slmp::cli
