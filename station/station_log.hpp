// A station's log lines. In a plant every line of a station starts with its
// name ("press-7: tcp:127.0.0.1:40312 connected"), so a warning among 500
// stations says whose it is; a lone unnamed station logs without a prefix.
// All share the process's sinks, level and line format.
#pragma once

#include <memory>
#include <string>

// Declared only: the headers that hold a logger stay free of spdlog's; the
// files that log include <spdlog/spdlog.h>.
namespace spdlog { class logger; }

namespace slmp::station {

// Sets the process's line format (server/main.cpp): time, level, then the
// logger's name and ": " when it has one, then the message.
void use_log_format();

// The process's logger (spdlog's default), unnamed.
std::shared_ptr<spdlog::logger> process_logger();
// The process's logger for an empty name; otherwise a copy of it with that name.
std::shared_ptr<spdlog::logger> station_logger(const std::string& name);

}  // namespace slmp::station
