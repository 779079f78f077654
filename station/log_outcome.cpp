#include "station/log_outcome.hpp"

#include <spdlog/spdlog.h>

#include "protocol/command_table.hpp"

namespace slmp::station {

namespace {

// Remote operations and the remote password are logged at info (warn when
// refused): an operator wants to see who stopped or unlocked the CPU without
// debug logs. The table says which commands those are.
const protocol::CommandSpec* operator_row(std::uint16_t command) {
    const auto* row = protocol::find_any_row(command);
    return row && (row->operator_command() || row->password_exempt()) ? row : nullptr;
}

}  // namespace

void log_outcome(spdlog::logger& log, const protocol::Peer& client, const protocol::Outcome& outcome) {
    // This runs for every request: an ordinary one is only a trace line, so the
    // peer's text is not built for it unless tracing.
    const auto* operation = operator_row(outcome.command);
    const bool ordinary = outcome.note.empty() && !operation;
    if (ordinary && !log.should_log(spdlog::level::trace)) return;
    const auto peer = client.text();
    if (operation && outcome.action != protocol::Outcome::Action::NeedMore) {
        if (outcome.end_code == protocol::EndCode::Ok && outcome.note.empty())
            log.info("{} {:04X} ({}) done", peer, outcome.command, operation->name);
        else
            log.warn("{} {:04X} refused: {}", peer, outcome.command, outcome.note);
        return;
    }
    if (outcome.note.empty()) {
        log.trace("{} {:04X}/{:04X} ok, {} byte(s) in, {} byte(s) out", peer, outcome.command, outcome.subcommand,
                  outcome.consumed, outcome.response.size());
        return;
    }
    if (outcome.command == 0 && outcome.subcommand == 0)
        log.debug("{} {}", peer, outcome.note);
    else
        log.debug("{} {:04X}/{:04X} rejected: {}", peer, outcome.command, outcome.subcommand, outcome.note);
}

}  // namespace slmp::station
