// 3E/4E frame headers, binary and ASCII, requests and responses.
// Layout: ../shared/spec/slmp-frames-and-devices.md §3.1–§3.3.
//
// scan_frame() looks at the start of a byte stream and says whether a whole
// frame is there, how long it is, or how many bytes to throw away. It never
// reads past the frame, so a TCP session can feed it one byte at a time.
#pragma once

#include <cstddef>
#include <cstdint>
#include <span>
#include <string_view>

namespace slmp::protocol {

enum class Codec : std::uint8_t { Binary, Ascii };
enum class FrameKind : std::uint8_t { E3, E4 };
enum class Direction : std::uint8_t { Request, Response };
// Which data codes a port accepts: binary, ASCII, or whichever a message uses.
enum class DataCodePolicy : std::uint8_t { Binary, Ascii, Auto };

// The access route. The own station is network 00, station FF, module I/O 03FF
// (03E0 = CPU No.1 of a multi-CPU system), multidrop 00.
struct Route {
    std::uint8_t network = 0x00;
    std::uint8_t station = 0xFF;
    std::uint16_t module_io = 0x03FF;
    std::uint8_t multidrop = 0x00;
    friend bool operator==(const Route&, const Route&) = default;
};

struct FrameHeader {
    FrameKind kind = FrameKind::E3;
    Codec codec = Codec::Binary;
    std::uint16_t serial = 0;    // 4E only
    Route route;
    std::uint16_t data_length = 0;  // request/response data length field
    std::size_t header_size = 0;    // bytes before the field the length counts from
};

struct FrameScan {
    enum class Status : std::uint8_t {
        NeedMore,   // the data is a valid prefix; wait for `needed` bytes in all
        Complete,   // a whole frame of `size` bytes is at the start
        Garbage,    // not a frame: skip `size` bytes (up to the next possible subheader)
        TooLarge,   // the length field announces more than the allowed maximum
    };
    Status status = Status::NeedMore;
    std::size_t size = 0;
    std::size_t needed = 0;
    FrameHeader header;
};

FrameScan scan_frame(std::span<const std::uint8_t> data, Direction direction, DataCodePolicy policy,
                     std::size_t max_frame_bytes);

// Size of the fixed header up to and including the data length field.
std::size_t header_size(FrameKind kind, Codec codec);

std::string_view to_string(Codec codec);
std::string_view to_string(FrameKind kind);

}  // namespace slmp::protocol
