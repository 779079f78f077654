#include "protocol/frame_1e.hpp"

#include <algorithm>
#include <array>

#include "devicemodel/hex.hpp"
#include "protocol/commands/handlers.hpp"
#include "protocol/fields.hpp"

namespace slmp::protocol {
namespace {

using namespace commands;
using enum Layout1E;

// The subset of 1E commands QnU/L/QJ71E71 ports serve and FX3U-era clients
// send (docs/frames.md lists the sources). Sorted by code. Bit-unit monitor
// (06/08) and the extension file register and special function module
// commands are not here: their bytes are not a frame this port knows.
constexpr std::array kCommands1E = {
    Command1E{0x00, "Batch Read (bit units)", 0x0401, 0x0001, Read, decode_batch_1e, nullptr, true},
    Command1E{0x01, "Batch Read (word units)", 0x0401, 0x0000, Read, decode_batch_1e},
    Command1E{0x02, "Batch Write (bit units)", 0x1401, 0x0001, WriteBits, decode_batch_1e},
    Command1E{0x03, "Batch Write (word units)", 0x1401, 0x0000, WriteWords, decode_batch_1e},
    Command1E{0x04, "Test (random write, bit units)", 0x1402, 0x0001, TestBits, decode_test_bits_1e},
    // Points and a fixed 00 read as 3E's word and double-word counts (00), so
    // the 3E decoders serve 05 and 07 with the A-compatible device layout.
    Command1E{0x05, "Test (random write, word units)", 0x1402, 0x0000, TestWords, decode_random_write_words},
    Command1E{0x07, "Monitor Device Registration (word units)", 0x0801, 0x0000, DeviceList, decode_monitor},
    Command1E{0x09, "Monitor (word units)", 0x0802, 0x0000, Header},
    Command1E{0x13, "Remote RUN", 0x1001, 0x0000, Header, nullptr, remote_run_1e},
    Command1E{0x14, "Remote STOP", 0x1002, 0x0000, Header, nullptr, remote_stop_1e},
    Command1E{0x15, "PC Type Read", 0x0101, 0x0000, Header, nullptr, read_pc_type_1e},
    Command1E{0x16, "Loopback Test", 0x0619, 0x0000, Loopback, nullptr, self_test_1e},
};

constexpr bool sorted() {
    for (std::size_t i = 1; i < kCommands1E.size(); ++i)
        if (kCommands1E[i - 1].code >= kCommands1E[i].code) return false;
    return true;
}
static_assert(sorted(), "kCommands1E must be sorted by code without duplicates");

bool allows(DataCodePolicy policy, Codec codec) {
    return policy == DataCodePolicy::Auto || (policy == DataCodePolicy::Binary) == (codec == Codec::Binary);
}

// The command a 1E request starts with, and its codec; null when none.
const Command1E* leading_command(std::span<const std::uint8_t> data, DataCodePolicy policy, Codec& codec,
                                 bool& prefix) {
    prefix = false;
    if (data.empty()) return nullptr;
    if (allows(policy, Codec::Binary))
        if (const auto* row = find_command_1e(data[0])) {
            codec = Codec::Binary;
            return row;
        }
    if (!allows(policy, Codec::Ascii) || (data[0] != '0' && data[0] != '1')) return nullptr;
    if (data.size() < 2) {
        prefix = true;   // every ASCII subheader starts with 0 or 1
        return nullptr;
    }
    auto code = devicemodel::parse_hex(data.first(2));
    codec = Codec::Ascii;
    return code ? find_command_1e(static_cast<std::uint8_t>(*code)) : nullptr;
}

// Fields before the variable part, in bytes (binary) after the subheader.
std::size_t fixed_bytes(Layout1E layout) {
    switch (layout) {
        case Header: return 4;
        case Read:
        case WriteBits:
        case WriteWords: return 12;
        case TestBits:
        case TestWords:
        case DeviceList: return 6;
        case Loopback: return 5;
    }
    return 4;
}

}  // namespace

std::span<const Command1E> all_commands_1e() { return kCommands1E; }

const Command1E* find_command_1e(std::uint8_t code) {
    auto it = std::find_if(kCommands1E.begin(), kCommands1E.end(), [&](const Command1E& c) { return c.code == code; });
    return it == kCommands1E.end() ? nullptr : &*it;
}

bool starts_1e(std::span<const std::uint8_t> data, DataCodePolicy policy) {
    Codec codec{};
    bool prefix = false;
    return leading_command(data, policy, codec, prefix) || prefix;
}

std::optional<FrameScan> scan_1e(std::span<const std::uint8_t> data, DataCodePolicy policy,
                                 std::size_t max_frame_bytes) {
    Codec codec = Codec::Binary;
    bool prefix = false;
    const auto* row = leading_command(data, policy, codec, prefix);
    FrameScan scan;
    if (prefix) {
        scan.needed = data.size() + 1;
        return scan;
    }
    if (!row) return std::nullopt;
    const std::size_t unit = codec == Codec::Binary ? 1 : 2;   // characters per byte
    auto& h = scan.header;
    h.kind = FrameKind::E1;
    h.codec = codec;
    h.command_1e = row->code;
    h.header_size = header_size(FrameKind::E1, codec);
    const auto fixed = fixed_bytes(row->layout) * unit;
    if (data.size() < fixed) {
        scan.needed = fixed;
        return scan;
    }
    // A one-byte field at byte `offset` (ASCII: two hex characters).
    auto byte_at = [&](std::size_t offset) -> std::optional<std::uint32_t> {
        if (codec == Codec::Binary) return data[offset];
        return devicemodel::parse_hex(data.subspan(offset * 2, 2));
    };
    auto pc = byte_at(1);
    std::optional<std::uint32_t> count = 0;
    if (row->layout == Read || row->layout == WriteBits || row->layout == WriteWords) count = byte_at(10);  // points
    else if (row->layout != Header) count = byte_at(4);
    if (!pc || !count) {
        // Non-hex ASCII where a count is: the length is unknowable.
        scan.status = FrameScan::Status::Garbage;
        scan.size = 2;
        return scan;
    }
    std::size_t n = *count;
    const bool batch = row->layout == Read || row->layout == WriteBits || row->layout == WriteWords;
    if (n == 0 && batch) n = 256;   // a batch's 00 points = 256
    std::size_t extra = 0;   // bytes after the fixed part
    switch (row->layout) {
        case WriteBits: extra = (n + 1) / 2; break;
        case WriteWords: extra = 2 * n; break;
        case TestBits: extra = 7 * n; break;
        case TestWords: extra = 8 * n; break;
        case DeviceList: extra = 6 * n; break;
        default: break;
    }
    // Loopback data are characters as they are: n bytes in both codecs.
    scan.size = fixed + extra * unit + (row->layout == Loopback ? *count : 0);
    h.route = Route{0x00, static_cast<std::uint8_t>(*pc), 0x03FF, 0x00};
    h.data_length = static_cast<std::uint16_t>(std::min<std::size_t>(scan.size - h.header_size, 0xFFFF));
    return settle(scan, data.size(), max_frame_bytes);
}

// 1E end codes (QJ71E71 A-compatible 1E frame; docs/frames.md says which are
// inferred). 5B is followed by the CPU's abnormal code.
EndCode1E end_code_1e(EndCode code) {
    switch (code) {
        case EndCode::Ok: return {0x00, std::nullopt};
        case EndCode::UnsupportedCommand:
        case EndCode::LengthMismatch: return {0x50, std::nullopt};   // command or request content
        case EndCode::AsciiConversion: return {0x54, std::nullopt};
        case EndCode::RunWriteProhibited: return {0x55, std::nullopt};
        case EndCode::DeviceNotSpecifiable:
        case EndCode::DeviceNotAccessible:
        case EndCode::BadRequestContent: return {0x56, std::nullopt};   // device specification
        case EndCode::WordPointsOverLimit:
        case EndCode::BitPointsOverLimit:
        case EndCode::RandomBitPointsOverLimit:
        case EndCode::RandomWordPointsOverLimit:
        case EndCode::AddressOutOfRange:
        case EndCode::DeviceOutOfRange: return {0x57, std::nullopt};   // points or range
        case EndCode::RelayTimeout: return {0x60, std::nullopt};
        case EndCode::RouteNetworkNotFound:
        case EndCode::RouteStationNotFound:
        case EndCode::RouteNotCpu: return {0x5B, 0x10};   // PC No. error
        case EndCode::RemotePasswordLocked:
        case EndCode::RemotePasswordLockedOut:
        case EndCode::RemoteHeldByOther:
        case EndCode::RemoteResetDisabled:
        case EndCode::LatchClearNotInStop: return {0x5B, 0x18};   // remote error
        default: break;
    }
    return {0x5B, 0x11};   // mode error: the CPU cannot do it now (Busy CEE0 and the rest)
}

// The meanings of the codes end_code_1e() gives (docs/frames.md).
constexpr std::array kEndCodeTexts1E = {
    EndCodeText1E{0x00, std::nullopt, "normal completion"},
    EndCodeText1E{0x50, std::nullopt, "command or request content not as specified"},
    EndCodeText1E{0x54, std::nullopt, "ASCII data that does not convert to binary"},
    EndCodeText1E{0x55, std::nullopt, "write during RUN not allowed"},
    EndCodeText1E{0x56, std::nullopt, "device specification wrong"},
    EndCodeText1E{0x57, std::nullopt, "points or device range exceeded"},
    EndCodeText1E{0x5B, 0x10, "PC No. error: not the own station"},
    EndCodeText1E{0x5B, 0x11, "mode error: the CPU cannot do it now"},
    EndCodeText1E{0x5B, 0x18, "remote error: remote operation refused"},
    EndCodeText1E{0x60, std::nullopt, "monitoring timer expired"},
};

std::span<const EndCodeText1E> all_end_codes_1e() { return kEndCodeTexts1E; }

std::vector<std::uint8_t> encode_response_1e(const FrameHeader& request, std::span<const std::uint8_t> data) {
    FieldWriter w(request.codec);
    w.u8(static_cast<std::uint8_t>(request.command_1e | 0x80));
    w.u8(0x00);
    w.raw(data);
    return std::move(w.bytes());
}

std::vector<std::uint8_t> encode_error_1e(const FrameHeader& request, EndCode code) {
    FieldWriter w(request.codec);
    auto c = end_code_1e(code);
    w.u8(static_cast<std::uint8_t>(request.command_1e | 0x80));
    w.u8(c.code);
    if (c.abnormal) w.u8(*c.abnormal);
    return std::move(w.bytes());
}

}  // namespace slmp::protocol
