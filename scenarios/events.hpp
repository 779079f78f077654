// Where the scenario engine reports what it did (fired faults, trigger
// actions, timeline steps). The server sends these to spdlog; tests collect them.
#pragma once

#include <functional>
#include <string>

namespace slmp::scenarios {

enum class EventLevel : std::uint8_t { Debug, Info, Warn };
using EventSink = std::function<void(EventLevel, const std::string&)>;

}  // namespace slmp::scenarios
