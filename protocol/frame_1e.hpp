// The A-compatible 1E frame (MC protocol, QJ71E71/LJ71E71, QnU/L ports, FX3U
// Ethernet modules): a one-byte subheader that is the command, the PC No.,
// the monitoring timer, then the command's data; no length field, so the
// frame's length follows from the command and its point count. Layout,
// sources and what is inferred: docs/frames.md.
//
// A 1E request decodes into the same Request the 3E path builds: its row in
// kCommands1E names the 3E (command, subcommand) whose table row serves it,
// and a device command's 1E decoder fills the same Operands, so handlers,
// scenarios, recordings and metrics see one request shape.
#pragma once

#include <cstdint>
#include <optional>
#include <span>
#include <string_view>
#include <vector>

#include "protocol/end_code.hpp"
#include "protocol/frame.hpp"

namespace slmp::protocol {

struct DecodeContext;
struct CommandContext;

// How the length of a 1E request follows from its fields.
enum class Layout1E : std::uint8_t {
    Header,        // subheader, PC No., timer only (monitor, RUN, STOP, PC type)
    Read,          // + head device(6) points(1) 00(1)
    WriteBits,     // + head device, points, 00, one nibble a point (whole bytes)
    WriteWords,    // + head device, points, 00, one word a point
    TestBits,      // + points(1) 00(1), per point device(6) + set/reset(1)
    TestWords,     // + points, 00, per point device(6) + word(2)
    DeviceList,    // + points, 00, per point device(6) (monitor registration)
    Loopback,      // + count(1), count raw characters
};

struct Command1E {
    std::uint8_t code;               // the subheader; the response's is code | 80
    std::string_view name;
    std::uint16_t command;           // the command table row that serves it
    std::uint16_t subcommand;
    Layout1E layout;
    void (*decode)(DecodeContext&) = nullptr;          // device commands: the 1E fields -> Operands
    EndCode (*handler)(CommandContext&) = nullptr;     // null: the command table row's handler
    bool bit_data = false;           // the response carries bit data (padded to whole bytes)
};

std::span<const Command1E> all_commands_1e();
const Command1E* find_command_1e(std::uint8_t code);

// A 1E request at the start of `data`: whole, a prefix, or too large; nullopt
// when the data does not start like a 1E request of a known command.
std::optional<FrameScan> scan_1e(std::span<const std::uint8_t> data, DataCodePolicy policy, std::size_t max_frame_bytes);
// Whether a 1E request could start at the beginning of `data` (for resynchronising).
bool starts_1e(std::span<const std::uint8_t> data, DataCodePolicy policy);

// The 1E end code (and abnormal code after 5B) for an SLMP end code; docs/frames.md.
struct EndCode1E {
    std::uint8_t code;
    std::optional<std::uint8_t> abnormal;
};
EndCode1E end_code_1e(EndCode code);
// What each 1E end code (and abnormal code after 5B) that end_code_1e()
// gives means: the Wireshark dissector's table (test_wireshark_tables.cpp).
struct EndCodeText1E {
    std::uint8_t code;
    std::optional<std::uint8_t> abnormal;
    std::string_view meaning;
};
std::span<const EndCodeText1E> all_end_codes_1e();

// Responses: subheader | 80, end code, data — or the error end code (and the
// abnormal code after 5B).
std::vector<std::uint8_t> encode_response_1e(const FrameHeader& request, std::span<const std::uint8_t> data);
std::vector<std::uint8_t> encode_error_1e(const FrameHeader& request, EndCode code);

}  // namespace slmp::protocol
