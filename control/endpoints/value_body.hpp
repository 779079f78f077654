// What /api/devices and /api/buffer share in a request: the count=N query
// parameter and the {"values": [...]} / {"string": "..."} body. Both throw
// ApiError (400) with a message that names the fix.
#pragma once

#include <cstdint>
#include <string>

#include <nlohmann/json.hpp>

#include "control/http/router.hpp"

namespace slmp::control {

// count=N, 1 when not given (its range is checked with the run: make_run).
std::uint64_t count_param(const ApiRequest& request);

// A JSON object with exactly one of "values" and "string".
nlohmann::json parse_value_body(const std::string& body);

}  // namespace slmp::control
