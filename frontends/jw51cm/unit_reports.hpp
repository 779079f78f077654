// What the JW-51CM writes into the PLC's data memory on its own, as its
// network parameter image (§15) asks: the command execution completion record
// after each computer-link command (§11, parameters 3660–3667) and the
// connection status monitor flags, one bit a connection (§12, 3764–3767).
// The ladder program reads them (here: SLMP, /api/devices, a scenario).
#pragma once

#include <array>
#include <cstdint>
#include <span>
#include <string>
#include <vector>

#include "frontends/jw51cm/buffers.hpp"
#include "frontends/jw51cm/memory_map.hpp"

namespace slmp::jw51cm {

inline constexpr std::uint32_t kCompletionParameters = 03660;   // 3660–3667
inline constexpr std::uint32_t kStatusFlagParameters = 03764;   // 3764–3767
inline constexpr std::uint8_t kOutputOn = 0x80;                 // +7 (3667, 3767): 80 on, 00 off
inline constexpr std::uint32_t kCompletionMinBytes = 16, kCompletionMaxBytes = 64;
inline constexpr std::uint32_t kCompletionCommandAt = 014;      // the command's copy, from c-ID on
inline constexpr unsigned kConnections = 8;
inline constexpr std::uint8_t kNoConnection = 0xFF;             // a TCP client beyond the unit's 8 numbers

// An area the unit writes: where, how many bytes, whether it writes at all.
struct OutputArea {
    bool on = false;
    Place place;
    std::uint32_t bytes = 0;
};
// 3660/3661 address (L, H), 3662 file (§19.13: 3661 by one chapter, 3662 read
// here, as 3766 and 3772 sit), 3664/3665 size, 3667 80 on.
OutputArea completion_area(std::span<const std::uint8_t> parameters);
// 3764/3765 address (L, H), 3766 file, 3767 80 on; one byte.
OutputArea status_flag_area(std::span<const std::uint8_t> parameters);

// What is wrong with 3660–3667 and 3764–3767, naming the parameter and the fix; empty when nothing.
std::string check_report_parameters(std::span<const std::uint8_t> parameters, const MemoryMap& map);

// Who sent a command: the record's peer IP, port and the unit's own connection number.
struct Caller {
    std::array<std::uint8_t, 4> ip{};
    std::uint16_t port = 0;
    std::uint8_t connection = kNoConnection;
};

// The record of one command (§11, best reading of its blurred table): +00–+03
// the peer's IP (first octet first), +04/+05 its port (L, H), +06 the own
// connection number, +07 00, +10 the RSLT answered, +11–+13 00, +14 on the
// received command from c-ID (47) on; cut to `bytes`, zeros after a shorter command.
std::vector<std::uint8_t> completion_record(const Caller& caller, std::uint8_t rslt,
                                            std::span<const std::uint8_t> command_from_id, std::uint32_t bytes);

// The unit's connection numbers 0–7 as its status flags show them: a UDP
// connection's bit is on from power-on, a TCP connection's while it is established.
class Connections {
public:
    // Numbers that are not handed to TCP clients: `udp` (on from power-on) and `reserved` (their owner sets them).
    void assign(std::uint8_t udp, std::uint8_t reserved);
    // A TCP client connected: the lowest free number, its bit on; kNoConnection when none is free.
    std::uint8_t open();
    void close(std::uint8_t number);
    void set(std::uint8_t number, bool on);   // a reserved number's bit (SEND/RECEIVE's active connection)
    std::uint8_t flags() const { return static_cast<std::uint8_t>(udp_ | established_); }
    std::uint8_t udp() const { return udp_; }

private:
    std::uint8_t udp_ = 0, reserved_ = 0, established_ = 0;
};

}  // namespace slmp::jw51cm
