// Codes as the API and the metrics show them: four upper-case hex digits
// ("0401", "C059"), as the manuals and GX Works write them — the protocol's one
// hex helper.
#pragma once

#include "protocol/hex.hpp"

namespace slmp::control {

using protocol::hex4;

}  // namespace slmp::control
