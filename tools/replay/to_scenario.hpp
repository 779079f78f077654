// slmp-replay --to-scenario (docs/twin.md, "Recording → scenario"): what the
// clients of a recorded session read, per device over time, as a scenario
// slmp-sim --scenario loads as it is — every device's first value read as its
// initial value, and a `set` step at each later time a read showed another
// value (whole ms from the first exchange, rounded down, so a step is in
// place by the time its read was made) — or, where three or more distinct
// values read one after another lie on one line in time, a `ramp` through
// them that shows each of those reads exactly as it was read. The reads used: batch reads 0401
// (word and bit units, Q and iQ-R form, 3E and 4E, binary and ASCII) and
// random reads 0403 (words and double words) answered 0000. Pure: no I/O.
#pragma once

#include <cstddef>
#include <map>
#include <string>

#include <nlohmann/json.hpp>

#include "config/config.hpp"
#include "scenarios/recording.hpp"

namespace slmp::replay {

struct ScenarioFromRecording {
    nlohmann::json scenario;
    std::size_t reads = 0;     // read exchanges whose values were taken
    std::size_t devices = 0;   // devices the scenario gives values
    std::size_t steps = 0;     // timeline steps
    std::size_t ramps = 0;     // ... of them ramps
    // Exchanges that read devices but gave no values, by why ("answered C051").
    std::map<std::string, std::size_t> skipped;
};

// `profile` decodes the requests (its port's forms, its X/Y numbering) and
// names the devices; `name` is the scenario's.
ScenarioFromRecording to_scenario(const scenarios::Recording& recording, const config::Profile& profile,
                                  const std::string& name);

}  // namespace slmp::replay
