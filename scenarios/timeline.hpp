// Runs a Timeline on the scenario clock. Every step has an interval [start,
// end) in each pass; an instant step (set, increment, copy) happens once per
// pass when the clock passes its start; a lasting step (ramp, sine, square,
// random walk) writes its value for the current time at every advance. The
// values depend only on the time, never on how often advance() is called
// (random walks move at exact multiples of every_ms), so a run on a fake clock
// gives the same values as the server's scan cycle.
#pragma once

#include <cstdint>
#include <vector>

#include "devicemodel/device_memory.hpp"
#include "scenarios/events.hpp"
#include "scenarios/rng.hpp"
#include "scenarios/scenario.hpp"

namespace slmp::scenarios {

// Writes values in the configuration's "devices" form (also used by "set" actions).
void apply_values(devicemodel::DeviceMemory& memory, const std::vector<config::InitialValue>& values,
                  const std::vector<LabelValue>& labels = {});

class Station;   // runner.hpp

class TimelineRunner {
public:
    // `station` serves Ondemand steps (null: they do nothing).
    TimelineRunner(const Timeline& timeline, std::uint64_t seed, Station* station = nullptr);

    // Moves the clock to `now_ms` since the scenario started (never backwards).
    void advance(devicemodel::DeviceMemory& memory, double now_ms, const EventSink& log);
    bool finished() const { return finished_; }

private:
    struct Walk {
        Rng rng;
        std::int64_t pass = -1;       // the pass the walk's state belongs to
        std::uint64_t moves = 0;      // moves made in that pass
        double value = 0;
    };
    void window(devicemodel::DeviceMemory& memory, std::int64_t pass, double from, double to, bool current,
                const EventSink& log);
    void instant(devicemodel::DeviceMemory& memory, const Step& step, const EventSink& log);
    void lasting(devicemodel::DeviceMemory& memory, std::size_t index, std::int64_t pass, double t);
    void walk_to(std::size_t index, std::int64_t pass, double t);

    const Timeline& timeline_;
    Station* station_;
    std::vector<Walk> walks_;         // one per step (used by random walks only)
    double last_ms_ = -1;             // -1: nothing run yet, so steps at 0 ms fire
    bool finished_ = false;
};

}  // namespace slmp::scenarios
