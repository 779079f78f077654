#include "protocol/command_table.hpp"

#include <algorithm>
#include <array>

#include "protocol/commands/handlers.hpp"

namespace slmp::protocol {
namespace {

using namespace commands;
using enum DeviceForm;
using enum Access;
using devicemodel::Family;

// Which port families serve a command (real-CPU measurements): the QnU/L
// built-in ports refuse 0101, 0406/1406, 0619 and 0613/1613; the FX5 built-in
// port refuses 0801/0802 and 0613/1613. Every other command is served by all.
constexpr Families kAll = 0xFF;
constexpr Families kNotQL = kAll & ~(family_bit(Family::QnU) | family_bit(Family::L));
constexpr Families kNotFx5 = kAll & ~family_bit(Family::IQF);
constexpr Families kNotQLFx5 = kNotQL & kNotFx5;
// Label commands need GX Works3 global labels in the CPU: iQ-R only
// (SLMP Reference Manual §5.1; Q/L, QJ71E71 and FX5 ports answer C059).
constexpr Families kIqrOnly = family_bit(Family::IQR);

constexpr std::uint16_t kExt = kExtended;
constexpr std::uint16_t kCtl = kControlCpuOnly;
constexpr std::uint16_t kW = kWrites;
constexpr std::uint16_t kFile = kFileRoute;
constexpr std::uint16_t kOp = kOperator;
constexpr std::uint16_t kDev = kConnectedDevice;
// Remote password rows: exempt from the lock they open.
constexpr std::uint16_t kPw = kPasswordExempt;
// The node commands (JA §3.12-3.14): on "node_commands" ports only; the
// parameter write sequence's rows stay served while it runs.
constexpr std::uint16_t kNd = kNode;
constexpr std::uint16_t kPwr = kNode | kParameterWrite;

// Sorted by (command, subcommand); checked below. Columns: command, subcommand,
// name, handler, decoder (device commands), device form, access, flags, families.
constexpr std::array kCommands = {
    CommandSpec{0x0101, 0x0000, "Read Type Name", read_type_name, nullptr, Q, None, 0, kNotQL},
    CommandSpec{0x0401, 0x0000, "Device Read (word units, Q form)", batch_read, decode_batch, Q, Words},
    CommandSpec{0x0401, 0x0001, "Device Read (bit units, Q form)", batch_read, decode_batch, Q, Bits},
    CommandSpec{0x0401, 0x0002, "Device Read (word units, iQ-R form)", batch_read, decode_batch, IQR, Words},
    CommandSpec{0x0401, 0x0003, "Device Read (bit units, iQ-R form)", batch_read, decode_batch, IQR, Bits},
    CommandSpec{0x0401, 0x0080, "Device Read (word units, Q form, extended)", batch_read, decode_batch, Q, Words, kExt},
    CommandSpec{0x0401, 0x0081, "Device Read (bit units, Q form, extended)", batch_read, decode_batch, Q, Bits, kExt},
    CommandSpec{0x0401, 0x0082, "Device Read (word units, iQ-R form, extended)", batch_read, decode_batch, IQR, Words, kExt},
    CommandSpec{0x0401, 0x0083, "Device Read (bit units, iQ-R form, extended)", batch_read, decode_batch, IQR, Bits, kExt},
    CommandSpec{0x0403, 0x0000, "Read Random (Q form)", random_read, decode_random_read, Q, Words},
    CommandSpec{0x0403, 0x0002, "Read Random (iQ-R form)", random_read, decode_random_read, IQR, Words},
    CommandSpec{0x0403, 0x0080, "Read Random (Q form, extended)", random_read, decode_random_read, Q, Words, kExt},
    CommandSpec{0x0403, 0x0082, "Read Random (iQ-R form, extended)", random_read, decode_random_read, IQR, Words, kExt},
    CommandSpec{0x0406, 0x0000, "Read Block (Q form)", block_read, decode_block_read, Q, Words, 0, kNotQL},
    CommandSpec{0x0406, 0x0002, "Read Block (iQ-R form)", block_read, decode_block_read, IQR, Words, 0, kNotQL},
    CommandSpec{0x0406, 0x0080, "Read Block (Q form, extended)", block_read, decode_block_read, Q, Words, kExt, kNotQL},
    CommandSpec{0x0406, 0x0082, "Read Block (iQ-R form, extended)", block_read, decode_block_read, IQR, Words, kExt, kNotQL},
    CommandSpec{0x041A, 0x0000, "Array Label Read", array_label_read, nullptr, Q, None, 0, kIqrOnly},
    CommandSpec{0x041C, 0x0000, "Label Read Random", label_read_random, nullptr, Q, None, 0, kIqrOnly},
    CommandSpec{0x0601, 0x0000, "Extend Unit Read", extend_unit_read},
    CommandSpec{0x0613, 0x0000, "Memory Read", memory_read, nullptr, Q, None, kCtl, kNotQLFx5},
    CommandSpec{0x0619, 0x0000, "Self Test (loopback)", self_test, nullptr, Q, None, kCtl, kNotQL},
    CommandSpec{0x0801, 0x0000, "Entry Monitor Device (Q form)", monitor_register, decode_monitor, Q, Words, kCtl, kNotFx5},
    CommandSpec{0x0801, 0x0002, "Entry Monitor Device (iQ-R form)", monitor_register, decode_monitor, IQR, Words, kCtl, kNotFx5},
    CommandSpec{0x0801, 0x0080, "Entry Monitor Device (Q form, extended)", monitor_register, decode_monitor, Q, Words,
                kExt | kCtl, kNotFx5},
    CommandSpec{0x0801, 0x0082, "Entry Monitor Device (iQ-R form, extended)", monitor_register, decode_monitor, IQR,
                Words, kExt | kCtl, kNotFx5},
    CommandSpec{0x0802, 0x0000, "Execute Monitor", monitor_execute, nullptr, Q, None, kCtl, kNotFx5},
    CommandSpec{0x0E30, 0x0000, "Node Search", node_search, nullptr, Q, None, kNd},
    CommandSpec{0x0E31, 0x0000, "IP Address Set", ip_address_set, nullptr, Q, None, kNd},
    CommandSpec{0x0E32, 0x0000, "Device Info Compare", device_info_compare, nullptr, Q, None, kNd},
    CommandSpec{0x0E33, 0x0000, "Parameter Get", parameter_get, nullptr, Q, None, kNd},
    CommandSpec{0x0E34, 0x0000, "Parameter Set", parameter_set, nullptr, Q, None, kPwr},
    CommandSpec{0x0E35, 0x0000, "Parameter Set Start", parameter_set_start, nullptr, Q, None, kPwr},
    CommandSpec{0x0E36, 0x0000, "Parameter Set End", parameter_set_end, nullptr, Q, None, kPwr},
    CommandSpec{0x0E3A, 0x0000, "Parameter Set Cancel", parameter_set_cancel, nullptr, Q, None, kPwr},
    CommandSpec{0x0E44, 0x0000, "Status Read", status_read, nullptr, Q, None, kNd},
    CommandSpec{0x0E45, 0x0000, "Communication Setting Get", communication_setting_get, nullptr, Q, None, kNd},
    CommandSpec{0x0E53, 0x0000, "Status Read2", status_read2, nullptr, Q, None, kNd},
    CommandSpec{0x1001, 0x0000, "Remote RUN", remote_run, nullptr, Q, None, kOp | kW},
    CommandSpec{0x1002, 0x0000, "Remote STOP", remote_stop, nullptr, Q, None, kOp},
    CommandSpec{0x1003, 0x0000, "Remote PAUSE", remote_pause, nullptr, Q, None, kOp},
    CommandSpec{0x1005, 0x0000, "Remote Latch Clear", remote_latch_clear, nullptr, Q, None, kOp | kW},
    CommandSpec{0x1006, 0x0000, "Remote RESET", remote_reset, nullptr, Q, None, kOp | kW},
    CommandSpec{0x1401, 0x0000, "Device Write (word units, Q form)", batch_write, decode_batch, Q, Words, kW},
    CommandSpec{0x1401, 0x0001, "Device Write (bit units, Q form)", batch_write, decode_batch, Q, Bits, kW},
    CommandSpec{0x1401, 0x0002, "Device Write (word units, iQ-R form)", batch_write, decode_batch, IQR, Words, kW},
    CommandSpec{0x1401, 0x0003, "Device Write (bit units, iQ-R form)", batch_write, decode_batch, IQR, Bits, kW},
    CommandSpec{0x1401, 0x0080, "Device Write (word units, Q form, extended)", batch_write, decode_batch, Q, Words, kExt | kW},
    CommandSpec{0x1401, 0x0081, "Device Write (bit units, Q form, extended)", batch_write, decode_batch, Q, Bits, kExt | kW},
    CommandSpec{0x1401, 0x0082, "Device Write (word units, iQ-R form, extended)", batch_write, decode_batch, IQR, Words,
                kExt | kW},
    CommandSpec{0x1401, 0x0083, "Device Write (bit units, iQ-R form, extended)", batch_write, decode_batch, IQR, Bits,
                kExt | kW},
    CommandSpec{0x1402, 0x0000, "Write Random (word units, Q form)", random_write_words, decode_random_write_words, Q,
                Words, kW},
    CommandSpec{0x1402, 0x0001, "Write Random (bit units, Q form)", random_write_bits, decode_random_write_bits, Q, Bits, kW},
    CommandSpec{0x1402, 0x0002, "Write Random (word units, iQ-R form)", random_write_words, decode_random_write_words, IQR,
                Words, kW},
    CommandSpec{0x1402, 0x0003, "Write Random (bit units, iQ-R form)", random_write_bits, decode_random_write_bits, IQR,
                Bits, kW},
    CommandSpec{0x1402, 0x0080, "Write Random (word units, Q form, extended)", random_write_words,
                decode_random_write_words, Q, Words, kExt | kW},
    CommandSpec{0x1402, 0x0081, "Write Random (bit units, Q form, extended)", random_write_bits, decode_random_write_bits,
                Q, Bits, kExt | kW},
    CommandSpec{0x1402, 0x0082, "Write Random (word units, iQ-R form, extended)", random_write_words,
                decode_random_write_words, IQR, Words, kExt | kW},
    CommandSpec{0x1402, 0x0083, "Write Random (bit units, iQ-R form, extended)", random_write_bits,
                decode_random_write_bits, IQR, Bits, kExt | kW},
    CommandSpec{0x1406, 0x0000, "Write Block (Q form)", block_write, decode_block_write, Q, Words, kW, kNotQL},
    CommandSpec{0x1406, 0x0002, "Write Block (iQ-R form)", block_write, decode_block_write, IQR, Words, kW, kNotQL},
    CommandSpec{0x1406, 0x0080, "Write Block (Q form, extended)", block_write, decode_block_write, Q, Words, kExt | kW, kNotQL},
    CommandSpec{0x1406, 0x0082, "Write Block (iQ-R form, extended)", block_write, decode_block_write, IQR, Words,
                kExt | kW, kNotQL},
    CommandSpec{0x141A, 0x0000, "Array Label Write", array_label_write, nullptr, Q, None, kW, kIqrOnly},
    CommandSpec{0x141B, 0x0000, "Label Write Random", label_write_random, nullptr, Q, None, kW, kIqrOnly},
    CommandSpec{0x1601, 0x0000, "Extend Unit Write", extend_unit_write, nullptr, Q, None, kW},
    CommandSpec{0x1613, 0x0000, "Memory Write", memory_write, nullptr, Q, None, kCtl | kW, kNotQLFx5},
    CommandSpec{0x1617, 0x0000, "Clear Error", clear_error, nullptr, Q, None, kCtl | kOp | kDev},
    CommandSpec{0x1630, 0x0000, "Remote Password Unlock", password_unlock, nullptr, Q, None, kPw},
    CommandSpec{0x1631, 0x0000, "Remote Password Lock", password_lock, nullptr, Q, None, kPw},
    // File control (SLMP Reference Manual §5.8): 0000 Q/L, 0004 L, 0040 iQ-R; the
    // handler answers a subcommand the CPU's family does not speak (§2.2).
    // kW on the commands system protect blocks (§5). FX5: not served. kFile: the
    // restricted request destinations of §3.1.4.
    CommandSpec{0x1810, 0x0000, "Read Directory/File (Q/L)", file_list, nullptr, Q, None, kFile, kNotFx5},
    CommandSpec{0x1810, 0x0040, "Read Directory/File (iQ-R)", file_list, nullptr, Q, None, kFile, kNotFx5},
    CommandSpec{0x1811, 0x0000, "Search Directory/File (Q/L)", file_search, nullptr, Q, None, kFile, kNotFx5},
    CommandSpec{0x1811, 0x0040, "Search Directory/File (iQ-R)", file_search, nullptr, Q, None, kFile, kNotFx5},
    CommandSpec{0x1820, 0x0000, "New File (Q/L)", file_new, nullptr, Q, None, kFile | kW, kNotFx5},
    CommandSpec{0x1820, 0x0040, "New File (iQ-R)", file_new, nullptr, Q, None, kFile | kW, kNotFx5},
    CommandSpec{0x1822, 0x0000, "Delete File (Q/L)", file_delete, nullptr, Q, None, kFile | kW, kNotFx5},
    CommandSpec{0x1822, 0x0004, "Delete File (L, 32-character password)", file_delete, nullptr, Q, None, kFile | kW, kNotFx5},
    CommandSpec{0x1822, 0x0040, "Delete File (iQ-R)", file_delete, nullptr, Q, None, kFile | kW, kNotFx5},
    CommandSpec{0x1824, 0x0000, "Copy File (Q/L)", file_copy, nullptr, Q, None, kFile | kW, kNotFx5},
    CommandSpec{0x1824, 0x0004, "Copy File (L, 32-character password)", file_copy, nullptr, Q, None, kFile | kW, kNotFx5},
    CommandSpec{0x1824, 0x0040, "Copy File (iQ-R)", file_copy, nullptr, Q, None, kFile | kW, kNotFx5},
    CommandSpec{0x1825, 0x0000, "Change File State (Q/L)", file_state, nullptr, Q, None, kFile | kW, kNotFx5},
    CommandSpec{0x1825, 0x0004, "Change File State (L, 32-character password)", file_state, nullptr, Q, None, kFile | kW,
                kNotFx5},
    CommandSpec{0x1825, 0x0040, "Change File State (iQ-R)", file_state, nullptr, Q, None, kFile | kW, kNotFx5},
    CommandSpec{0x1826, 0x0000, "Change File Date (Q/L)", file_date, nullptr, Q, None, kFile | kW, kNotFx5},
    CommandSpec{0x1826, 0x0040, "Change File Date (iQ-R)", file_date, nullptr, Q, None, kFile | kW, kNotFx5},
    CommandSpec{0x1827, 0x0000, "Open File (Q/L)", file_open, nullptr, Q, None, kFile, kNotFx5},
    CommandSpec{0x1827, 0x0004, "Open File (L, 32-character password)", file_open, nullptr, Q, None, kFile, kNotFx5},
    CommandSpec{0x1827, 0x0040, "Open File (iQ-R)", file_open, nullptr, Q, None, kFile, kNotFx5},
    CommandSpec{0x1828, 0x0000, "Read File", file_read, nullptr, Q, None, kFile, kNotFx5},
    CommandSpec{0x1829, 0x0000, "Write File", file_write, nullptr, Q, None, kFile | kW, kNotFx5},
    CommandSpec{0x182A, 0x0000, "Close File", file_close, nullptr, Q, None, kFile, kNotFx5},
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

// The per-command facts must agree across a command's rows, since the request
// path asks them of any row (find_any_row) before the subcommand is known.
constexpr bool per_command_flags_agree() {
    constexpr std::uint16_t kPerCommand = kPasswordExempt | kOperator | kWrites | kNode | kParameterWrite | kConnectedDevice;
    for (std::size_t i = 1; i < kCommands.size(); ++i) {
        const auto& a = kCommands[i - 1];
        const auto& b = kCommands[i];
        if (a.command != b.command) continue;
        if ((a.flags & kPerCommand) != (b.flags & kPerCommand) || a.families != b.families ||
            (a.decode == nullptr) != (b.decode == nullptr))
            return false;
    }
    return true;
}
static_assert(per_command_flags_agree(), "rows of one command must share flags, families and decoder presence");

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

const CommandSpec* find_any_row(std::uint16_t command) {
    auto it = std::lower_bound(kCommands.begin(), kCommands.end(), command,
                               [](const CommandSpec& row, std::uint16_t key) { return row.command < key; });
    return it != kCommands.end() && it->command == command ? &*it : nullptr;
}

}  // namespace slmp::protocol
