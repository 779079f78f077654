// Scenarios may name global labels wherever they name one device value
// (timeline steps, "set", trigger conditions and increments). The loader does
// not know the CPU, so it keeps the names; this binds them to the CPU's label
// table when the scenario starts (docs/scenarios.md, "Labels").
#pragma once

#include "devicemodel/labels.hpp"
#include "scenarios/scenario.hpp"

namespace slmp::scenarios {

// Resolves every label the scenario names. Throws config::ConfigError naming
// the file, the JSON pointer, the name and the fix when one does not resolve
// or has a type a scenario cannot write numbers to.
void bind_labels(Scenario& scenario, const devicemodel::LabelTable& labels);

}  // namespace slmp::scenarios
