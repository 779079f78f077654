// Wall-clock times as the API shows them: ISO 8601, UTC, milliseconds.
#pragma once

#include <chrono>
#include <string>

namespace slmp::control {

std::string iso_time(std::chrono::system_clock::time_point time);   // "2024-05-01T12:00:00.123Z"

}  // namespace slmp::control
