#include "server/core.hpp"

#include <spdlog/spdlog.h>

namespace slmp::server {

void log_outcome(const std::string& peer, const protocol::Outcome& outcome) {
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

}  // namespace slmp::server
