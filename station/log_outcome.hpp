// Logs one handled frame: a debug line saying why for every rejected or
// ignored request (the "connects but times out" puzzle), a trace line otherwise.
#pragma once

#include "protocol/engine.hpp"
#include "protocol/peer.hpp"
#include "station/station_log.hpp"

namespace slmp::station {

void log_outcome(spdlog::logger& log, const protocol::Peer& peer, const protocol::Outcome& outcome);

}  // namespace slmp::station
