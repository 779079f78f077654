// A Sharp JW CPU's JW-51CM computer link (JW-51CM manual, docs/jw51cm.md): a 40-byte header,
// ID 47/45, ATTR, COM, RSLT; no length field, so a request's length comes from
// its COM row (§3.2). One object per station: the write-permission mode, the
// clock, system memory and the program are the unit's and the CPU's, shared
// by every connection; the RUN/STOP hold is the station's operating state.
// Knows no sockets and no SLMP.
#pragma once

#include <array>
#include <chrono>
#include <cstdint>
#include <functional>
#include <map>
#include <optional>
#include <span>
#include <vector>

#include "devicemodel/cpu.hpp"
#include "frontends/gate.hpp"
#include "frontends/jw51cm/memory_map.hpp"
#include "frontends/jw51cm/unit_reports.hpp"

namespace slmp::jw51cm {

inline constexpr std::size_t kHeaderBytes = 40;
inline constexpr std::uint8_t kCommandId = 0x47, kResponseId = 0x45;
inline constexpr std::size_t kMaxData = 1024;   // §4.1: bytes per read/write
inline constexpr std::uint8_t kUdpConnection = 7;   // the UDP port's connection number (inferred, docs/jw51cm.md)
// The station's operating state knows its STOP holder by client id: this one is the JW-51CM unit.
inline constexpr devicemodel::ClientId kUnitClient = 0x4A57'3531'434D'0000ULL;

struct Options {
    std::uint32_t file_bytes = 16384;          // files 1–7 (inferred default)
    std::uint32_t timers = 1024;               // T/C 0000–1777 octal
    std::map<std::uint32_t, std::uint8_t> timer_attributes;   // TADR -> ATTR (§7.2 table); others 00 "unused"
    std::uint32_t system_bytes = 02200;        // #0000–#2177
    std::uint32_t program_steps = 0x7E00;      // per PSEG (08, 09)
    // The unit's network parameter image (§15, octal 0000–3777): the designated
    // buffers at 1000–1377 and the ring buffers at 1400–1577 are read from it
    // (frontends/jw51cm/buffers.hpp); the rest is 00.
    std::vector<std::uint8_t> parameters = std::vector<std::uint8_t>(04000, 0);
};

enum class Rslt : std::uint8_t {
    Ok = 0x00, Format = 0x01, NotStopped = 0x06, WriteMode = 0x10, TimerWhileStopped = 0x13,
    // §9, §10: the ring buffers.
    RingUndefined = 0x40, RingInvalid = 0x41, RingPointers = 0x42, RingFull = 0x43, RingTooLarge = 0x44,
    // §8, §10: the designated buffers.
    BufferUndefined = 0x48, BufferInvalid = 0x49, BufferLength = 0x4A,
};

// A ring buffer's read or write that waits for the host's confirm (29/39 FUN 81):
// the pointer it started from and the bytes it moved. The unit's RAM, not data memory.
struct PendingConfirm {
    bool open = false;
    std::uint16_t from = 0;
    std::uint16_t length = 0;
};

class ComputerLink {
public:
    using Clock = std::function<std::chrono::system_clock::time_point()>;
    ComputerLink(devicemodel::Cpu& cpu, Options options, Clock clock = {});

    struct Result {
        enum class Kind { NeedMore, Respond, Drop } kind = Kind::NeedMore;
        std::size_t consumed = 0;
        std::vector<std::uint8_t> response;
        std::uint8_t command = 0;
    };
    // One request from the front of a TCP stream. `whole_segment`: the stream
    // is exactly what has arrived (E8 swallows one more byte only when it came
    // in the same segment, §7.2).
    // `gate` (a scenario fault, frontends/gate.hpp) is asked once a whole,
    // well-formed request's COM is known, before the gates of §19.
    // `caller`: who sent it, for the completion record (§11) written after
    // every request answered when 3667 is 80.
    Result handle_stream(std::span<const std::uint8_t> stream, const frontends::Gate& gate = {}, const Caller& caller = {});
    // One UDP datagram: one request, its length must be exactly the COM's.
    Result handle_datagram(std::span<const std::uint8_t> datagram, const frontends::Gate& gate = {},
                           const Caller& caller = {});

    // The connection numbers (§12): `udp_port` when the unit serves a UDP port
    // (its number is 7, inferred); `udp` more UDP connections' bits (SEND/RECEIVE's
    // over UDP), `reserved` bits TCP clients are not given (its TCP_Active one).
    void assign_connections(bool udp_port, std::uint8_t udp = 0, std::uint8_t reserved = 0);
    void set_connection(std::uint8_t number, bool established);   // a reserved number's bit
    std::uint8_t udp_connection() const;   // 7, or kNoConnection without a UDP port
    // A TCP client connected (its number, kNoConnection when none is free) or
    // left; the status flag byte follows when 3767 is 80.
    std::uint8_t open_connection();
    void close_connection(std::uint8_t number);
    // Power-on (start, Remote RESET, a power cut's end): the flag byte written again.
    void power_on();
    const Connections& connections() const { return connections_; }

    std::uint8_t write_mode() const { return write_mode_; }
    const MemoryMap& map() const { return map_; }
    devicemodel::Cpu& cpu() { return cpu_; }
    const Options& options() const { return options_; }

    // The unit's state, for the handlers.
    std::uint8_t write_mode_ = 0;   // §6.1: 0 at power-on, unit-wide
    std::vector<std::uint8_t> system_memory;
    std::vector<std::uint8_t> program;   // PSEG 08 then 09, 2 bytes a step
    std::chrono::seconds clock_offset{0};   // the PLC calendar = host UTC + offset
    std::optional<std::chrono::system_clock::time_point> clock_stopped;   // B3 CTRL 01
    // Per ring buffer 0–F: the read or write awaiting the host's confirm (FUN 82/83), unit-wide
    // (whichever connection or transport confirms; inferred, §19.4).
    std::array<PendingConfirm, 16> ring_confirms{};
    std::chrono::system_clock::time_point now() const { return clock_(); }

private:
    Result cut_stream(std::span<const std::uint8_t> stream, const frontends::Gate& gate);
    Result cut_datagram(std::span<const std::uint8_t> datagram, const frontends::Gate& gate);
    Result answer(std::span<const std::uint8_t> request, std::size_t length, const frontends::Gate& gate);
    // §11: the record of an answered request, when the parameters ask for it.
    void record_completion(std::span<const std::uint8_t> request, const Result& result, const Caller& caller);
    void write_flags();
    void write_area(Place place, std::span<const std::uint8_t> bytes);

    devicemodel::Cpu& cpu_;
    Options options_;
    MemoryMap map_;
    Clock clock_;
    Connections connections_;
    bool udp_port_ = false;
};

// The response frame for `request`'s header and COM: RSLT, then `text` when RSLT is 00.
std::vector<std::uint8_t> response_frame(std::span<const std::uint8_t> request, Rslt rslt,
                                         std::span<const std::uint8_t> text = {});

}  // namespace slmp::jw51cm
