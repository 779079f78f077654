#include "protocol/command_table.hpp"

#include <algorithm>
#include <array>

#include "protocol/commands/handlers.hpp"

namespace slmp::protocol {
namespace {

using namespace commands;
using enum DeviceForm;
using enum Access;

// Sorted by (command, subcommand); checked below. `true` after the access
// marks the extended (008x) layout; the last flag marks commands that cannot
// reach CPU No.2–4 of a multi-CPU system (Appendix 3).
constexpr bool kExt = true;
constexpr bool kControlCpuOnly = true;
constexpr std::array kCommands = {
    CommandSpec{0x0101, 0x0000, "Read Type Name", read_type_name},
    CommandSpec{0x0401, 0x0000, "Device Read (word units, Q form)", batch_read, Q, Words},
    CommandSpec{0x0401, 0x0001, "Device Read (bit units, Q form)", batch_read, Q, Bits},
    CommandSpec{0x0401, 0x0002, "Device Read (word units, iQ-R form)", batch_read, IQR, Words},
    CommandSpec{0x0401, 0x0003, "Device Read (bit units, iQ-R form)", batch_read, IQR, Bits},
    CommandSpec{0x0401, 0x0080, "Device Read (word units, Q form, extended)", batch_read, Q, Words, kExt},
    CommandSpec{0x0401, 0x0081, "Device Read (bit units, Q form, extended)", batch_read, Q, Bits, kExt},
    CommandSpec{0x0401, 0x0082, "Device Read (word units, iQ-R form, extended)", batch_read, IQR, Words, kExt},
    CommandSpec{0x0401, 0x0083, "Device Read (bit units, iQ-R form, extended)", batch_read, IQR, Bits, kExt},
    CommandSpec{0x0403, 0x0000, "Read Random (Q form)", random_read, Q, Words},
    CommandSpec{0x0403, 0x0002, "Read Random (iQ-R form)", random_read, IQR, Words},
    CommandSpec{0x0403, 0x0080, "Read Random (Q form, extended)", random_read, Q, Words, kExt},
    CommandSpec{0x0403, 0x0082, "Read Random (iQ-R form, extended)", random_read, IQR, Words, kExt},
    CommandSpec{0x0406, 0x0000, "Read Block (Q form)", block_read, Q, Words},
    CommandSpec{0x0406, 0x0002, "Read Block (iQ-R form)", block_read, IQR, Words},
    CommandSpec{0x0406, 0x0080, "Read Block (Q form, extended)", block_read, Q, Words, kExt},
    CommandSpec{0x0406, 0x0082, "Read Block (iQ-R form, extended)", block_read, IQR, Words, kExt},
    CommandSpec{0x0601, 0x0000, "Extend Unit Read", extend_unit_read},
    CommandSpec{0x0613, 0x0000, "Memory Read", memory_read, Q, None, false, kControlCpuOnly},
    CommandSpec{0x0619, 0x0000, "Self Test (loopback)", self_test, Q, None, false, kControlCpuOnly},
    CommandSpec{0x0801, 0x0000, "Entry Monitor Device (Q form)", monitor_register, Q, Words, false, kControlCpuOnly},
    CommandSpec{0x0801, 0x0002, "Entry Monitor Device (iQ-R form)", monitor_register, IQR, Words, false, kControlCpuOnly},
    CommandSpec{0x0801, 0x0080, "Entry Monitor Device (Q form, extended)", monitor_register, Q, Words, kExt, kControlCpuOnly},
    CommandSpec{0x0801, 0x0082, "Entry Monitor Device (iQ-R form, extended)", monitor_register, IQR, Words, kExt,
                kControlCpuOnly},
    CommandSpec{0x0802, 0x0000, "Execute Monitor", monitor_execute, Q, None, false, kControlCpuOnly},
    CommandSpec{0x1001, 0x0000, "Remote RUN", remote_run},
    CommandSpec{0x1002, 0x0000, "Remote STOP", remote_stop},
    CommandSpec{0x1003, 0x0000, "Remote PAUSE", remote_pause},
    CommandSpec{0x1005, 0x0000, "Remote Latch Clear", remote_latch_clear},
    CommandSpec{0x1006, 0x0000, "Remote RESET", remote_reset},
    CommandSpec{0x1401, 0x0000, "Device Write (word units, Q form)", batch_write, Q, Words},
    CommandSpec{0x1401, 0x0001, "Device Write (bit units, Q form)", batch_write, Q, Bits},
    CommandSpec{0x1401, 0x0002, "Device Write (word units, iQ-R form)", batch_write, IQR, Words},
    CommandSpec{0x1401, 0x0003, "Device Write (bit units, iQ-R form)", batch_write, IQR, Bits},
    CommandSpec{0x1401, 0x0080, "Device Write (word units, Q form, extended)", batch_write, Q, Words, kExt},
    CommandSpec{0x1401, 0x0081, "Device Write (bit units, Q form, extended)", batch_write, Q, Bits, kExt},
    CommandSpec{0x1401, 0x0082, "Device Write (word units, iQ-R form, extended)", batch_write, IQR, Words, kExt},
    CommandSpec{0x1401, 0x0083, "Device Write (bit units, iQ-R form, extended)", batch_write, IQR, Bits, kExt},
    CommandSpec{0x1402, 0x0000, "Write Random (word units, Q form)", random_write_words, Q, Words},
    CommandSpec{0x1402, 0x0001, "Write Random (bit units, Q form)", random_write_bits, Q, Bits},
    CommandSpec{0x1402, 0x0002, "Write Random (word units, iQ-R form)", random_write_words, IQR, Words},
    CommandSpec{0x1402, 0x0003, "Write Random (bit units, iQ-R form)", random_write_bits, IQR, Bits},
    CommandSpec{0x1402, 0x0080, "Write Random (word units, Q form, extended)", random_write_words, Q, Words, kExt},
    CommandSpec{0x1402, 0x0081, "Write Random (bit units, Q form, extended)", random_write_bits, Q, Bits, kExt},
    CommandSpec{0x1402, 0x0082, "Write Random (word units, iQ-R form, extended)", random_write_words, IQR, Words, kExt},
    CommandSpec{0x1402, 0x0083, "Write Random (bit units, iQ-R form, extended)", random_write_bits, IQR, Bits, kExt},
    CommandSpec{0x1406, 0x0000, "Write Block (Q form)", block_write, Q, Words},
    CommandSpec{0x1406, 0x0002, "Write Block (iQ-R form)", block_write, IQR, Words},
    CommandSpec{0x1406, 0x0080, "Write Block (Q form, extended)", block_write, Q, Words, kExt},
    CommandSpec{0x1406, 0x0082, "Write Block (iQ-R form, extended)", block_write, IQR, Words, kExt},
    CommandSpec{0x1601, 0x0000, "Extend Unit Write", extend_unit_write},
    CommandSpec{0x1613, 0x0000, "Memory Write", memory_write, Q, None, false, kControlCpuOnly},
    CommandSpec{0x1617, 0x0000, "Clear Error", clear_error, Q, None, false, kControlCpuOnly},
    CommandSpec{0x1630, 0x0000, "Remote Password Unlock", password_unlock},
    CommandSpec{0x1631, 0x0000, "Remote Password Lock", password_lock},
};

constexpr bool sorted_and_unique() {
    for (std::size_t i = 1; i < kCommands.size(); ++i) {
        const auto& a = kCommands[i - 1];
        const auto& b = kCommands[i];
        if (a.command > b.command || (a.command == b.command && a.subcommand >= b.subcommand)) return false;
    }
    return true;
}
static_assert(sorted_and_unique(), "kCommands must be sorted by (command, subcommand) without duplicates");

}  // namespace

std::span<const CommandSpec> all_commands() { return kCommands; }

const CommandSpec* find_command(std::uint16_t command, std::uint16_t subcommand) {
    auto it = std::lower_bound(kCommands.begin(), kCommands.end(), std::pair{command, subcommand},
                               [](const CommandSpec& row, const std::pair<std::uint16_t, std::uint16_t>& key) {
                                   return std::pair{row.command, row.subcommand} < key;
                               });
    if (it == kCommands.end() || it->command != command || it->subcommand != subcommand) return nullptr;
    return &*it;
}

bool is_known_command(std::uint16_t command) {
    return std::any_of(kCommands.begin(), kCommands.end(), [&](const CommandSpec& row) { return row.command == command; });
}

bool is_iqr_device_subcommand(std::uint16_t command, std::uint16_t subcommand) {
    constexpr std::array kDeviceCommands = {std::uint16_t{0x0401}, std::uint16_t{0x1401}, std::uint16_t{0x0403},
                                            std::uint16_t{0x1402}, std::uint16_t{0x0406}, std::uint16_t{0x1406},
                                            std::uint16_t{0x0801}};
    bool device_command = std::find(kDeviceCommands.begin(), kDeviceCommands.end(), command) != kDeviceCommands.end();
    auto form = subcommand & 0xFF7F;   // 008x: the same forms with the extension specification
    return device_command && (form == 0x0002 || form == 0x0003);
}

}  // namespace slmp::protocol
