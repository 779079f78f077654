// Frame headers: 3E/4E (binary and ASCII, requests and responses), the
// station-number-extended frame (binary requests; SLMP Reference Manual ch. 4) and the
// A-compatible 1E frame (requests; protocol/frame_1e.hpp, docs/frames.md).
// Layout: SLMP Reference Manual ch. 4.
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
// E1: A-compatible 1E; Ext: the station-number-extended frame (68 00 / E8 00).
enum class FrameKind : std::uint8_t { E3, E4, E1, Ext };
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

// The network No. (1–239) and station No. (1–120) a port's station is set to
// on the real module (§3.1.3); 0 = not set. A request addressed to them is the
// own station as much as one addressed to 00/FF.
struct StationNumbers {
    std::uint8_t network = 0;
    std::uint8_t station = 0;
    bool configured() const { return network != 0 && station != 0; }
    friend bool operator==(const StationNumbers&, const StationNumbers&) = default;
};

// The frames a port recognises beyond 3E/4E (from its profile); bytes of a
// frame it does not have are not a frame there, as on the real port.
struct FrameSet {
    bool e1 = false;                 // A-compatible 1E requests
    bool station_extended = false;   // 68 00 requests (CC-Link IE TSN modules)
};

struct FrameHeader {
    FrameKind kind = FrameKind::E3;
    Codec codec = Codec::Binary;
    std::uint16_t serial = 0;    // 4E and the station-number-extended frame
    std::uint8_t command_1e = 0;        // 1E: the subheader, which is the command
    std::uint16_t extended_station = 0; // station-number-extended frame (§3.1.6)
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
                     std::size_t max_frame_bytes, FrameSet frames = {});
// The end of every frame shape's scan, once `scan.size` is known: TooLarge
// past the maximum, NeedMore until `available` bytes hold it, else Complete.
FrameScan settle(FrameScan scan, std::size_t available, std::size_t max_frame_bytes);

// Size of the fixed header up to and including the data length field.
std::size_t header_size(FrameKind kind, Codec codec);

std::string_view to_string(Codec codec);
std::string_view to_string(FrameKind kind);

}  // namespace slmp::protocol
