#include "protocol/command_table.hpp"

#include <algorithm>
#include <array>

#include "protocol/commands/handlers.hpp"

namespace slmp::protocol {
namespace {

using namespace commands;
using enum DeviceForm;
using enum Access;

// Sorted by (command, subcommand); checked below.
constexpr std::array kCommands = {
    CommandSpec{0x0101, 0x0000, "Read Type Name", read_type_name},
    CommandSpec{0x0401, 0x0000, "Device Read (word units, Q form)", batch_read, Q, Words},
    CommandSpec{0x0401, 0x0001, "Device Read (bit units, Q form)", batch_read, Q, Bits},
    CommandSpec{0x0401, 0x0002, "Device Read (word units, iQ-R form)", batch_read, IQR, Words},
    CommandSpec{0x0401, 0x0003, "Device Read (bit units, iQ-R form)", batch_read, IQR, Bits},
    CommandSpec{0x0619, 0x0000, "Self Test (loopback)", self_test},
    CommandSpec{0x1401, 0x0000, "Device Write (word units, Q form)", batch_write, Q, Words},
    CommandSpec{0x1401, 0x0001, "Device Write (bit units, Q form)", batch_write, Q, Bits},
    CommandSpec{0x1401, 0x0002, "Device Write (word units, iQ-R form)", batch_write, IQR, Words},
    CommandSpec{0x1401, 0x0003, "Device Write (bit units, iQ-R form)", batch_write, IQR, Bits},
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
