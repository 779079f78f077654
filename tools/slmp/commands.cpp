#include "tools/slmp/commands.hpp"

#include <array>
#include <sstream>

namespace slmp::cli {
namespace {

// clang-format off
// A plain array counts its rows itself (adding a command is one row), and its
// aggregate initialisation keeps each row's `accepts` list alive: a copy made
// by std::to_array would leave the initializer_lists dangling.
const CommandSpec kCommands[] = {
    {"read", "DEVICE [POINTS]", "0401 Device Read: POINTS words (default 1), or bits with --bits", {"bits"}, run_read},
    {"write", "DEVICE VALUE...", "1401 Device Write: words (-32768..65535, 0x..), or 0/1 with --bits", {"bits"}, run_write},
    {"random", "read|write ITEM...", "0403 Read Random / 1402 Write Random: read D0 M100 --dword D200; "
                                     "write D0=1 --dword D200=70000; write --bits M0=1 Y2F=0", {"bits", "dword"}, run_random},
    {"monitor", "ITEM...", "poll D100, M0, D100-D109 ... with 0401 every --interval until Ctrl-C or --count",
                           {"interval", "count"}, run_monitor},
    {"label", "read|write NAME...", "041C/041A label read: LabelW DDD[0]:20; 141B/141A label write: LabelW 5, "
                                    "DDD[0] 1 2 3 (docs/labels.md)", {}, run_label},
    {"file", "ls|get|put|rm ...", "file drives (1810-182A): ls [4:[DIR]], get 4:A.CSV [LOCAL], put LOCAL 4:A.CSV, "
                                  "rm 4:A.CSV; --file-password P for a file with one (docs/files.md)",
                                  {"file-password"}, run_file},
    {"run", "", "1001 Remote RUN (--force: mode 0003; --clear none|nonlatch|all)", {"force", "clear"}, run_remote_run},
    {"stop", "", "1002 Remote STOP", {}, run_remote_stop},
    {"pause", "", "1003 Remote PAUSE (--force: mode 0003)", {"force"}, run_remote_pause},
    {"reset", "", "1006 Remote RESET (a real CPU answers nothing when it resets)", {}, run_remote_reset},
    {"latch-clear", "", "1005 Remote Latch Clear (the CPU must be in STOP)", {}, run_remote_latch_clear},
    {"type", "", "0101 Read Type Name: model name and model code", {}, run_type},
    {"selftest", "[DATA]", "0619 Self Test: loopback of DATA (default 0123456789ABCDEF)", {}, run_selftest},
    {"nodes", "", "0E30 Node Search: the node's IP, MAC, station (host name), model code, status and port "
                  "(an SLMP-compatible device's port; docs/nodes.md); --broadcast: every node answering a broadcast",
     {"broadcast"}, run_nodes},
    {"status", "", "0E44 Status Read and 0E53 Status Read2: the node's status code and state", {}, run_status},
    {"lock", "PASSWORD", "1631 Remote Password Lock", {}, run_lock},
    {"unlock", "PASSWORD", "1630 Remote Password Unlock", {}, run_unlock},
    {"ondemand", "--wait", "2101 Ondemand: wait for --count pushes (default 1), --timeout each; over UDP a 0101 "
                           "first makes the simulator know this client", {"wait", "count"}, run_ondemand},
    {"probe", "--out FILE", "find what the port does (read-only unless --allow-writes RANGES) and write it as a "
                            "slmp-sim profile (docs/twin.md)", {"out", "allow-writes", "record", "silence"}, run_probe},
    {"diff", "--against HOST:PORT", "send generated requests (every command, limits +-1, bad devices, 3E/4E, "
                                    "binary/ASCII) to both servers and list every difference (docs/twin.md)",
                                    {"against", "profile", "record", "silence"}, run_diff},
};
// clang-format on

}  // namespace

const CommandSpec* find_command(std::string_view name) {
    for (const auto& c : kCommands)
        if (c.name == name) return &c;
    return nullptr;
}

std::string commands_help() {
    std::ostringstream out;
    out << "Commands:\n";
    for (const auto& c : kCommands) {
        std::string head = std::string(c.name) + (c.usage.empty() ? "" : " " + std::string(c.usage));
        out << "  " << head;
        out << std::string(head.size() < 28 ? 28 - head.size() : 1, ' ') << c.summary << '\n';
    }
    out << "\nExit status: 0 ok, 1 the PLC answered an error end code, 2 usage error, 3 connection error or timeout.\n";
    return out.str();
}

}  // namespace slmp::cli
