#include "frontends/jw51cm/command_table.hpp"

#include <array>

namespace slmp::jw51cm {

namespace {

// §7.1 with §3.2's lengths. Modes: reads 0; data writes 1 (30/34 inferred;
// 38 by its error 10, §19.10); program and system memory writes 2 (§5.3).
constexpr std::array kCommands{
    CommandRow{0xE9, "write-permission mode read", 0, Tail::None, 0, Needs::Any, mode_read},
    CommandRow{0xF9, "write-permission mode set", 1, Tail::None, 0, Needs::Any, mode_set},
    CommandRow{0x20, "relay monitor", 4, Tail::None, 0, Needs::Any, relay_monitor},
    CommandRow{0x30, "relay set/reset", 5, Tail::None, 1, Needs::Any, relay_set},
    CommandRow{0x23, "T/C current value monitor", 4, Tail::None, 0, Needs::Any, timer_monitor},
    CommandRow{0x32, "T/C set/reset", 3, Tail::None, 1, Needs::Any, timer_set},
    CommandRow{0x24, "register read", 5, Tail::None, 0, Needs::Any, register_read},
    CommandRow{0x34, "register write", 5, Tail::L, 1, Needs::Any, register_write},
    CommandRow{0x35, "register fill", 6, Tail::None, 1, Needs::Any, register_fill},
    CommandRow{0x44, "system memory read", 5, Tail::None, 0, Needs::Any, system_read},
    CommandRow{0x54, "system memory write", 5, Tail::L, 2, Needs::Stopped, system_write},
    CommandRow{0x04, "program read", 5, Tail::None, 0, Needs::Any, program_read},
    CommandRow{0x14, "program write", 5, Tail::TwoL, 2, Needs::Stopped, program_write},
    CommandRow{0xA2, "date read", 0, Tail::None, 0, Needs::Any, date_read},
    CommandRow{0xA3, "time read", 0, Tail::None, 0, Needs::Any, time_read},
    CommandRow{0xB2, "date set", 4, Tail::None, 1, Needs::Any, date_set},
    CommandRow{0xB3, "time set", 4, Tail::None, 1, Needs::Any, time_set},
    CommandRow{0xE8, "PLC run-state monitor", 0, Tail::None, 0, Needs::Any, run_monitor},
    CommandRow{0xF8, "PLC stop / release stop", 1, Tail::None, 0, Needs::Any, run_stop},
    CommandRow{0x28, "designated buffer read", 6, Tail::None, 0, Needs::Any, buffer_read},
    CommandRow{0x38, "designated buffer write", 6, Tail::L, 1, Needs::Any, buffer_write, 4},
    CommandRow{0x68, "designated buffer info read", 1, Tail::None, 0, Needs::Any, buffer_info_read},
    CommandRow{0x78, "designated buffer info write", 8, Tail::None, 1, Needs::Any, buffer_info_write},
    CommandRow{0x29, "ring buffer read", 5, Tail::None, 0, Needs::Any, ring_read},
    CommandRow{0x39, "ring buffer write", 5, Tail::L, 1, Needs::Any, ring_write},
    CommandRow{0x69, "ring buffer info read", 1, Tail::None, 0, Needs::Any, ring_info_read},
    CommandRow{0x79, "ring buffer info write", 13, Tail::None, 1, Needs::Any, ring_info_write},
};

}  // namespace

std::span<const CommandRow> command_table() { return kCommands; }

const CommandRow* find_command(std::uint8_t com) {
    for (const auto& row : kCommands)
        if (row.com == com) return &row;
    return nullptr;
}

std::optional<std::size_t> request_length(const CommandRow& row, std::span<const std::uint8_t> request) {
    constexpr std::size_t kText = kHeaderBytes + 3;
    std::size_t length = kText + row.fixed;
    if (row.tail == Tail::None) return length;
    if (request.size() < kText + row.length_at + 2) return std::nullopt;
    std::size_t l = request[kText + row.length_at] | static_cast<std::size_t>(request[kText + row.length_at + 1]) << 8;
    return length + (row.tail == Tail::TwoL ? 2 * l : l);
}

}  // namespace slmp::jw51cm
