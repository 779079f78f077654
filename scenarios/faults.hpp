// Fault rules at run time: which faults a request matches, whether each
// fires (skip, count, seeded probability, time window, enabled), and the
// combined decision the server carries out at its one hook.
//
// Every matching fault that fires contributes; when two want the same thing
// (two end codes, two delays, two ways to drop) the first in file order wins.
#pragma once

#include <chrono>
#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "scenarios/events.hpp"
#include "scenarios/incoming.hpp"
#include "scenarios/rng.hpp"
#include "scenarios/scenario.hpp"

namespace slmp::scenarios {

// How the server sends one response (after the engine, or a forced answer).
struct Delivery {
    std::chrono::microseconds delay{0};           // wait before the first byte
    std::vector<std::size_t> pieces;              // sizes of separate writes; empty: one write
    std::chrono::microseconds pause{0};           // between pieces
    std::size_t coalesce = 0;                     // hold until this many responses are ready...
    std::chrono::microseconds hold{0};            // ...or this long has passed
    bool plain() const { return delay.count() == 0 && pieces.empty() && coalesce == 0; }
};

struct FaultDecision {
    enum class Drop : std::uint8_t { None, NoResponse, Close, Reset };
    std::optional<protocol::EndCode> end_code;    // answer with this instead of the CPU
    std::optional<std::uint8_t> frontend_code;    // a front end's: answer with this response code / RSLT
    Drop drop = Drop::None;
    double delay_ms = 0;
    std::optional<FaultAction> split, coalesce;
    std::vector<FaultAction> corruptions;
    std::optional<double> power_cycle_ms, refuse_ms;
    std::vector<std::string> fired;               // names of the faults that fired
    bool any() const { return !fired.empty(); }
};

struct FaultStats {
    std::string name;        // the fault's id, or "<file>#/faults/2"
    std::string kind;        // "delay", "end_code", ...
    std::string scenario;    // the name of the scenario it belongs to
    bool enabled = true;
    std::uint64_t matched = 0;
    std::uint64_t fired = 0;
};

class FaultSet {
public:
    // `seed` per fault: each has its own random stream (Rng::stream).
    void add(const Fault& fault, const std::string& source, std::uint64_t seed, const std::string& scenario = {});

    FaultDecision decide(const Incoming& incoming, double now_ms, const EventSink& log);
    // Turns a fault on or off by id (trigger actions) or by its stats name
    // (the HTTP API: "<file>#/faults/2" for one without an id); false when there is none.
    bool enable(const std::string& id, bool on);
    std::vector<FaultStats> stats() const;

private:
    struct Entry {
        const Fault* fault;
        std::string name;
        std::string scenario;
        Rng rng;
        bool enabled;
        std::uint64_t matched = 0;
        std::uint64_t fired = 0;
    };
    static bool matches(const Fault& fault, const Incoming& incoming);

    std::vector<Entry> entries_;
};

std::string_view to_string(FaultKind kind);

// The response bytes after the decision's corruptions (in order).
void corrupt(std::vector<std::uint8_t>& response, const protocol::FrameHeader& request, const FaultAction& action, Rng& rng);
// Sizes of the pieces a split sends `size` bytes in.
std::vector<std::size_t> split_sizes(std::size_t size, const FaultAction& split);

}  // namespace slmp::scenarios
