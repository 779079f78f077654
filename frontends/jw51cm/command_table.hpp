// The JW-51CM command table (JW-51CM manual, docs/jw51cm.md): every fact
// about each COM in one row — its request length, the write-permission mode
// and PLC state it needs, and its handler.
#pragma once

#include <cstdint>
#include <optional>
#include <span>
#include <string_view>
#include <vector>

#include "frontends/jw51cm/computer_link.hpp"

namespace slmp::jw51cm {

// How the request's length continues after the fixed bytes: with L (text bytes
// `length_at`, `length_at`+1, little-endian) bytes, or 2·L (program steps).
enum class Tail : std::uint8_t { None, L, TwoL };
enum class Needs : std::uint8_t { Any, Stopped };

struct Context {
    ComputerLink& link;
    std::span<const std::uint8_t> text;   // after COM
    std::vector<std::uint8_t>& out;       // response text after RSLT
};

using Handler = Rslt (*)(Context&);

struct CommandRow {
    std::uint8_t com;
    std::string_view name;
    std::size_t fixed;        // bytes after COM before the tail
    Tail tail;
    std::uint8_t min_mode;    // write-permission mode needed (§6.1): 0 reads, 1 data writes, 2 program/system
    Needs needs;              // 14 and 54 need the PLC stopped (RSLT 06)
    Handler handler;
    std::size_t length_at = 3;   // where L sits in the text: 3 (34, 54, 14, 39), 4 (38: DB TAG IP L)
};

std::span<const CommandRow> command_table();
const CommandRow* find_command(std::uint8_t com);
// The request's whole length (header included) once its fixed part is in `request`, or nullopt before.
std::optional<std::size_t> request_length(const CommandRow& row, std::span<const std::uint8_t> request);

Rslt mode_read(Context&);
Rslt mode_set(Context&);
Rslt relay_monitor(Context&);
Rslt relay_set(Context&);
Rslt timer_monitor(Context&);
Rslt timer_set(Context&);
Rslt register_read(Context&);
Rslt register_write(Context&);
Rslt register_fill(Context&);
Rslt system_read(Context&);
Rslt system_write(Context&);
Rslt program_read(Context&);
Rslt program_write(Context&);
Rslt date_read(Context&);
Rslt time_read(Context&);
Rslt date_set(Context&);
Rslt time_set(Context&);
Rslt run_monitor(Context&);
Rslt run_stop(Context&);
// buffer_handlers.cpp
Rslt buffer_read(Context&);
Rslt buffer_write(Context&);
Rslt buffer_info_read(Context&);
Rslt buffer_info_write(Context&);
Rslt ring_read(Context&);
Rslt ring_write(Context&);
Rslt ring_info_read(Context&);
Rslt ring_info_write(Context&);

}  // namespace slmp::jw51cm
