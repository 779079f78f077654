// Differential mode's report (docs/twin.md, "Compare"): each request a
// station with `--upstream ... --compare` served both from its own memory (the
// twin) and through its upstream, the two answers classified the one way every
// tool classifies them (protocol/differential.hpp), counted, the differences
// logged one warning each and the last of them kept for GET /api/compare.
// On the station's strand, like the rest of the station: no lock.
#pragma once

#include <array>
#include <chrono>
#include <cstdint>
#include <deque>
#include <vector>

#include <spdlog/logger.h>

#include "protocol/differential.hpp"
#include "protocol/peer.hpp"

namespace slmp::station {

// One request both sides served, and how their answers differ.
struct ComparedRequest {
    std::uint64_t number = 0;   // the n-th compared request since the start (or the last clear), from 1
    std::chrono::system_clock::time_point at;
    std::uint64_t connection = 0;   // the client's session id (TCP connection, UDP port session)
    protocol::Peer peer;
    std::uint16_t command = 0;
    std::uint16_t subcommand = 0;
    std::vector<std::uint8_t> request;
    protocol::differential::Observed upstream;   // what the client got
    protocol::differential::Observed twin;       // what this station's own memory and profile answered
    protocol::differential::Difference difference;
};

class Comparison {
public:
    // The differences kept for GET /api/compare (older ones only counted).
    static constexpr std::size_t kKept = 100;

    Comparison(std::chrono::microseconds slack, spdlog::logger& log) : slack_(slack), log_(log) {}

    // Classifies the two answers of `compared` (upstream first: the real
    // PLC is the reference), counts them and, when they differ, logs one
    // warning and keeps them. Returns the classification.
    protocol::differential::Difference add(ComparedRequest compared);
    // Counting starts afresh (DELETE /api/compare).
    void clear();

    std::chrono::microseconds slack() const { return slack_; }
    std::uint64_t compared() const { return compared_; }
    std::uint64_t same() const { return compared_ - different(); }
    std::uint64_t different() const;
    // Differences of one kind (not Same).
    std::uint64_t count(protocol::differential::DifferenceKind kind) const {
        return by_kind_[static_cast<std::size_t>(kind)];
    }
    // The last kKept differences, the oldest first.
    const std::deque<ComparedRequest>& differences() const { return kept_; }

private:
    std::chrono::microseconds slack_;
    spdlog::logger& log_;
    std::uint64_t compared_ = 0;
    std::array<std::uint64_t, 6> by_kind_{};   // indexed by DifferenceKind
    std::deque<ComparedRequest> kept_;
};

}  // namespace slmp::station
