// Logs one handled frame: a debug line saying why for every rejected or
// ignored request (the "connects but times out" puzzle), a trace line otherwise.
#pragma once

#include "protocol/engine.hpp"
#include "protocol/peer.hpp"

namespace slmp::station {

void log_outcome(const protocol::Peer& peer, const protocol::Outcome& outcome);

}  // namespace slmp::station
