#include "station/log_outcome.hpp"

#include <spdlog/spdlog.h>

namespace slmp::station {

namespace {

// Remote password and remote operations are logged at info (warn when refused):
// an operator wants to see who stopped or unlocked the CPU without debug logs.
bool operator_command(std::uint16_t command) {
    return command == 0x1001 || command == 0x1002 || command == 0x1003 || command == 0x1005 || command == 0x1006 ||
           command == 0x1617 || command == 0x1630 || command == 0x1631;
}

}  // namespace

void log_outcome(const protocol::Peer& client, const protocol::Outcome& outcome) {
    // This runs for every request: an ordinary one is only a trace line, so the
    // peer's text is not built for it unless tracing.
    const bool ordinary = outcome.note.empty() && !operator_command(outcome.command);
    if (ordinary && !spdlog::should_log(spdlog::level::trace)) return;
    const auto peer = client.text();
    if (operator_command(outcome.command) && outcome.action != protocol::Outcome::Action::NeedMore) {
        if (outcome.end_code == protocol::EndCode::Ok && outcome.note.empty())
            spdlog::info("{} {:04X} ({}) done", peer, outcome.command,
                         outcome.command == 0x1630 ? "remote password unlock" :
                         outcome.command == 0x1631 ? "remote password lock" : "remote operation");
        else
            spdlog::warn("{} {:04X} refused: {}", peer, outcome.command, outcome.note);
        return;
    }
    if (outcome.note.empty()) {
        spdlog::trace("{} {:04X}/{:04X} ok, {} byte(s) in, {} byte(s) out", peer, outcome.command, outcome.subcommand,
                      outcome.consumed, outcome.response.size());
        return;
    }
    if (outcome.command == 0 && outcome.subcommand == 0)
        spdlog::debug("{} {}", peer, outcome.note);
    else
        spdlog::debug("{} {:04X}/{:04X} rejected: {}", peer, outcome.command, outcome.subcommand, outcome.note);
}

}  // namespace slmp::station
