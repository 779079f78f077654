// A request as protocol::decode leaves it: the frame header, the command
// table's row, the route's target CPU, and — for device commands — the decoded
// operands (devices, counts and write data) as data. The scenario hook, the
// recorder, metrics and the call monitor read this; execute() serves it. It
// never touches device memory, so deciding about a request changes nothing.
#pragma once

#include <cstdint>
#include <span>
#include <string>
#include <string_view>
#include <vector>

#include "protocol/end_code.hpp"
#include "protocol/fields.hpp"
#include "protocol/frame.hpp"

namespace slmp::protocol {

struct CommandSpec;

// One device (or run of devices) a command names, as it arrived.
struct DeviceOperand {
    enum class Unit : std::uint8_t { Bit, Word, DoubleWord };   // what one point is
    DeviceField field;
    Unit unit = Unit::Word;
    std::uint32_t points = 0;
    bool bit_block = false;               // 0406/1406: a block of a bit device, in words
    std::vector<std::uint16_t> words;     // write data: words (a double word is two, low first)
    std::vector<std::uint8_t> bits;       // write data: one 0/1 a point (bit units)
};

// The operands of a device command, in request order: every device whose
// fields decoded. `error` is the first problem met while reading — a field
// that does not decode, or a limit the port enforces while it reads — and the
// handler answers it before its device checks, or after them when
// `error_after_checks` (a batch write's data: the device and the count are
// checked before the data is read).
struct Operands {
    std::vector<DeviceOperand> devices;
    EndCode error = EndCode::Ok;
    std::string_view error_field;
    bool error_after_checks = false;

    bool failed_before_checks() const { return error != EndCode::Ok && !error_after_checks; }
};

struct Request {
    enum class Frame : std::uint8_t {
        NeedMore,   // no whole frame yet; nothing consumed
        Garbage,    // `size` bytes that start no request frame
        TooLarge,   // the length field announces more than the maximum
        Complete,   // a whole frame of `size` bytes
    };
    Frame frame = Frame::NeedMore;
    std::size_t size = 0;
    FrameHeader header;

    // Monitoring timer, command and subcommand; when they do not decode,
    // `header_error` says why.
    bool has_command = false;
    EndCode header_error = EndCode::Ok;
    std::string_view header_error_field;
    std::uint16_t command = 0;
    std::uint16_t subcommand = 0;

    const CommandSpec* spec = nullptr;     // the table's row; null when the table has none
    EndCode route_error = EndCode::Ok;     // the access route names no CPU of this station
    // The route names another network/station and the port relays (a module's
    // port): only the header is decoded here; the station the plant's router
    // finds decodes the rest (station/network_map.hpp). `route_error` is what it
    // gets when nothing routes it.
    bool elsewhere = false;
    bool routed = false;                   // a route brought it here from another station (Engine::decode)
    std::size_t target = 0;                // CPU No. - 1 the module I/O number selects
    std::span<const std::uint8_t> data;    // request data after the subcommand (valid while the input is)
    Operands operands;

    bool complete() const { return frame == Frame::Complete; }
    // Device reads or writes (device commands only; the scenario filters).
    bool reads_devices() const;
    bool writes_devices() const;
};

}  // namespace slmp::protocol
