// A station's log lines. In a plant every line of a station starts with its
// name ("press-7: 127.0.0.1:40312 (TCP) connected"), so a warning among 500
// stations says whose it is; a lone unnamed station logs without a prefix.
// All share the process's sinks, level and time format.
#pragma once

#include <memory>
#include <string>

#include <spdlog/spdlog.h>

namespace slmp::station {

// The format of every log line up to the message (server/main.cpp sets it).
inline constexpr const char* kLogLineHead = "%Y-%m-%d %H:%M:%S.%e %^%-5l%$ ";

// The default logger for an empty name; otherwise one that prefixes `name: `.
std::shared_ptr<spdlog::logger> station_logger(const std::string& name);

}  // namespace slmp::station
