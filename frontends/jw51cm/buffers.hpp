// The JW-51CM's designated buffers (§8) and ring buffers (§9), as the unit's
// network parameter image defines them (§15: octal 1000–1377, 1400–1577) and
// as data memory holds them: an indirect definition and every ring's write and
// read pointers live in an 8-byte info area in data memory, so the ladder
// program (here: SLMP, the HTTP API, a scenario) and the host see one state.
// Shared by the commands (buffer_handlers.cpp) and the face's HTTP resource.
#pragma once

#include <cstdint>
#include <span>
#include <string>
#include <vector>

#include "frontends/jw51cm/memory_map.hpp"

namespace slmp::jw51cm {

inline constexpr std::size_t kParameterBytes = 04000;       // §15: 0000–3777 (octal)
inline constexpr std::uint32_t kDesignatedParameters = 01000;   // 8 bytes a buffer, 00–1F
inline constexpr std::uint32_t kRingParameters = 01400;         // 8 bytes a ring, 0–F
inline constexpr unsigned kDesignatedBuffers = 32, kRingBuffers = 16;

// A parameter block's +7: how the buffer is defined.
inline constexpr std::uint8_t kUnused = 0x00, kDirect = 0x80, kIndirect = 0xC0;
// A ring's direction (§9): 01 (parameters, info area; 80 in 69/79) PLC -> host, read by 29;
// 81 host -> PLC, written by 39.
inline constexpr std::uint8_t kToHost = 0x01, kToHostAlt = 0x80, kToPlc = 0x81;

// 68/69's DINF: how the buffer is defined, 0x80 added when its contents are invalid.
inline constexpr std::uint8_t kDinfNone = 0x00, kDinfDirect = 0x01, kDinfIndirect = 0x02, kDinfInvalid = 0x80;

// A byte place in data memory: file (DSEG) and file address.
struct Place {
    std::uint8_t file = 0;
    std::uint32_t address = 0;
};

struct DesignatedBuffer {
    std::uint8_t dinf = kDinfNone;
    Place info;                   // indirect: the info area; direct: 0, 0 (as 68 answers)
    Place start;                  // DF, DA
    std::uint16_t length_field = 0;   // DL as stored: 0 means 64 KB
    std::uint32_t bytes() const { return length_field == 0 ? 0x10000u : length_field; }
    bool defined() const { return dinf != kDinfNone; }
    bool valid() const { return defined() && !(dinf & kDinfInvalid); }
};

struct RingBuffer {
    std::uint8_t dinf = kDinfNone;
    Place info;                   // WP at +0, RP at +2 (both definitions)
    std::uint8_t file = 0;        // BF
    std::uint8_t high = 0;        // BAH: the start address's high byte, a multiple of 4 (1 KB aligned)
    std::uint8_t direction = 0;   // DIR as stored
    std::uint8_t length_code = 0; // BL: 00 = 64 KB, else 256·BL (01, 02, 04, … 80)
    std::uint16_t wp = 0, rp = 0;

    std::uint32_t address() const { return static_cast<std::uint32_t>(high) << 8; }
    std::uint32_t size() const { return length_code == 0 ? 0x10000u : 256u * length_code; }
    bool defined() const { return dinf != kDinfNone; }
    bool valid() const { return defined() && !(dinf & kDinfInvalid); }
    bool to_host() const { return direction == kToHost || direction == kToHostAlt; }
    bool pointers_inside() const { return wp < size() && rp < size(); }
    // Bytes between RP and WP (what the reader may take), and what a writer may add:
    // WP must never reach RP, so one byte always stays free (§9).
    std::uint32_t unread() const { return (wp + size() - rp) % size(); }
    std::uint32_t free() const { return size() - 1 - unread(); }
};

// Whether a layout is one the unit accepts, against the simulated files' sizes.
bool valid_ring_layout(const MemoryMap& map, std::uint8_t file, std::uint8_t high, std::uint8_t direction,
                       std::uint8_t length_code);
bool valid_buffer_layout(const MemoryMap& map, Place start, std::uint32_t bytes);

// The definitions, from the parameter image and (indirect, and every ring's pointers) data memory.
DesignatedBuffer designated_buffer(std::span<const std::uint8_t> parameters, const MemoryMap& map,
                                   const ByteAccess& memory, unsigned number);
RingBuffer ring_buffer(std::span<const std::uint8_t> parameters, const MemoryMap& map, const ByteAccess& memory,
                       unsigned number);

// The ring's bytes from offset `from` on, wrapping at its end; callers check valid() first.
std::vector<std::uint8_t> ring_bytes(const RingBuffer& ring, const ByteAccess& memory, std::uint32_t from,
                                     std::uint32_t count);
void put_ring_bytes(const RingBuffer& ring, ByteAccess& memory, std::uint32_t at, std::span<const std::uint8_t> data);
void set_write_pointer(RingBuffer& ring, ByteAccess& memory, std::uint32_t wp);
void set_read_pointer(RingBuffer& ring, ByteAccess& memory, std::uint32_t rp);

// What is wrong with the parameter image's buffer blocks on this map, naming the
// parameter (octal) and the fix; empty when nothing (the unit's check when the
// parameters are written, §8 [4], §9 [5]).
std::string check_parameters(std::span<const std::uint8_t> parameters, const MemoryMap& map);

std::string octal(std::uint32_t value, int digits);

}  // namespace slmp::jw51cm
