// Reading scenario files. Every mistake is a config::ConfigError whose message
// names the file, the JSON pointer inside it and the fix, e.g.
//   plant.json: /faults/2/match/command: '04O1' is not a 4-digit hexadecimal code; write it like "C059"
// The published JSON Schema (scenarios/schema.json) describes the same format
// for editors; this loader is the authority and also checks what a schema
// cannot (device addresses, rung syntax, fault ids that triggers name).
#pragma once

#include <filesystem>
#include <string>
#include <vector>

#include "scenarios/scenario.hpp"

namespace slmp::scenarios {

Scenario load_scenario(const std::filesystem::path& file);
Scenario parse_scenario(const std::string& json_text, const std::string& source);

// Checks a set of scenarios loaded together: fault and trigger ids unique
// across files, every fault a trigger names exists. Throws ConfigError.
void check_together(const std::vector<Scenario>& scenarios);

}  // namespace slmp::scenarios
