#include "protocol/frame.hpp"

#include <algorithm>
#include <array>
#include <optional>

#include "devicemodel/hex.hpp"
#include "protocol/frame_1e.hpp"

namespace slmp::protocol {
namespace {

struct Subheader {
    FrameKind kind;
    Codec codec;
    Direction direction;
    std::string_view bytes;
};

bool codec_allowed(Codec codec, DataCodePolicy policy) {
    return policy == DataCodePolicy::Auto || (policy == DataCodePolicy::Binary) == (codec == Codec::Binary);
}

// Every subheader this server recognises; 4E and station-number-extended
// subheaders are followed by the serial number and two zero bytes (§3.1.2).
// The station-number-extended frame exists in binary only (§1.1).
constexpr std::array<Subheader, 10> kSubheaders = {{
    {FrameKind::E3, Codec::Binary, Direction::Request, std::string_view("\x50\x00", 2)},
    {FrameKind::E4, Codec::Binary, Direction::Request, std::string_view("\x54\x00", 2)},
    {FrameKind::E3, Codec::Ascii, Direction::Request, "5000"},
    {FrameKind::E4, Codec::Ascii, Direction::Request, "5400"},
    {FrameKind::E3, Codec::Binary, Direction::Response, std::string_view("\xD0\x00", 2)},
    {FrameKind::E4, Codec::Binary, Direction::Response, std::string_view("\xD4\x00", 2)},
    {FrameKind::E3, Codec::Ascii, Direction::Response, "D000"},
    {FrameKind::E4, Codec::Ascii, Direction::Response, "D400"},
    {FrameKind::Ext, Codec::Binary, Direction::Request, std::string_view("\x68\x00", 2)},
    {FrameKind::Ext, Codec::Binary, Direction::Response, std::string_view("\xE8\x00", 2)},
}};

// A port without the station-number-extended frame does not know its subheader.
bool recognised(const Subheader& sub, Direction direction, DataCodePolicy policy, FrameSet frames) {
    if (sub.direction != direction || !codec_allowed(sub.codec, policy)) return false;
    return sub.kind != FrameKind::Ext || direction == Direction::Response || frames.station_extended;
}


// How the data matches a subheader: fully, as a prefix (more bytes needed), or not.
enum class Match { Full, Prefix, None };

Match match(std::span<const std::uint8_t> data, std::string_view subheader) {
    auto n = std::min(data.size(), subheader.size());
    for (std::size_t i = 0; i < n; ++i)
        if (data[i] != static_cast<std::uint8_t>(subheader[i])) return Match::None;
    return n == subheader.size() ? Match::Full : Match::Prefix;
}

// Reads an unsigned field of `bytes` binary bytes (little-endian) or 2·bytes
// ASCII hex characters at `offset`.
std::optional<std::uint32_t> field(std::span<const std::uint8_t> data, std::size_t offset, std::size_t bytes,
                                   Codec codec) {
    if (codec == Codec::Binary) {
        std::uint32_t value = 0;
        for (std::size_t i = 0; i < bytes; ++i) value |= std::uint32_t{data[offset + i]} << (8 * i);
        return value;
    }
    return devicemodel::parse_hex(data.subspan(offset, bytes * 2));
}

}  // namespace

std::size_t header_size(FrameKind kind, Codec codec) {
    // subheader(2) [serial(2) zero(2)] network(1) station(1) module I/O(2) multidrop(1)
    // [fixed 00(1) extended station(2)] length(2); 1E: subheader(1) PC No.(1) timer(2)
    if (kind == FrameKind::E1) return codec == Codec::Binary ? 4 : 8;
    std::size_t bytes = (kind == FrameKind::E3 ? 2 : 6) + 7 + (kind == FrameKind::Ext ? 3 : 0);
    return codec == Codec::Binary ? bytes : bytes * 2;
}

FrameScan scan_frame(std::span<const std::uint8_t> data, Direction direction, DataCodePolicy policy,
                     std::size_t max_frame_bytes, FrameSet frames) {
    if (frames.e1 && direction == Direction::Request)
        if (auto scan = scan_1e(data, policy, max_frame_bytes)) return *scan;
    FrameScan scan;
    const Subheader* found = nullptr;
    bool prefix = false;
    for (const auto& sub : kSubheaders) {
        if (!recognised(sub, direction, policy, frames)) continue;
        auto m = match(data, sub.bytes);
        if (m == Match::Full) found = &sub;
        if (m == Match::Prefix) prefix = true;
    }
    if (!found) {
        if (prefix || data.empty()) {
            scan.needed = data.size() + 1;
            return scan;
        }
        // Resynchronise: drop bytes up to the next place a subheader could start.
        std::size_t skip = 1;
        for (; skip < data.size(); ++skip) {
            auto rest = data.subspan(skip);
            bool possible = std::any_of(kSubheaders.begin(), kSubheaders.end(), [&](const Subheader& sub) {
                return recognised(sub, direction, policy, frames) && match(rest, sub.bytes) != Match::None;
            });
            if (frames.e1 && direction == Direction::Request && starts_1e(rest, policy)) possible = true;
            if (possible) break;
        }
        scan.status = FrameScan::Status::Garbage;
        scan.size = skip;
        return scan;
    }

    auto& h = scan.header;
    h.kind = found->kind;
    h.codec = found->codec;
    h.header_size = header_size(h.kind, h.codec);
    if (data.size() < h.header_size) {
        scan.needed = h.header_size;
        return scan;
    }
    const std::size_t unit = h.codec == Codec::Binary ? 1 : 2;  // characters per byte
    std::size_t pos = found->bytes.size();
    std::optional<std::uint32_t> serial = 0, reserved = 0, fixed = 0, extended = 0;
    if (h.kind != FrameKind::E3) {
        serial = field(data, pos, 2, h.codec);
        reserved = field(data, pos + 2 * unit, 2, h.codec);
        pos += 4 * unit;
    }
    auto network = field(data, pos, 1, h.codec);
    auto station = field(data, pos + unit, 1, h.codec);
    auto module_io = field(data, pos + 2 * unit, 2, h.codec);
    auto multidrop = field(data, pos + 4 * unit, 1, h.codec);
    pos += 5 * unit;
    if (h.kind == FrameKind::Ext) {   // fixed 00, then the extended station No. (§3.1.6)
        fixed = field(data, pos, 1, h.codec);
        extended = field(data, pos + 1, 2, h.codec);
        pos += 3;
    }
    auto length = field(data, pos, 2, h.codec);
    if (!serial || !reserved || !fixed || !extended || !network || !station || !module_io || !multidrop || !length) {
        // An ASCII header with non-hex characters: its length is unknowable.
        scan.status = FrameScan::Status::Garbage;
        scan.size = found->bytes.size();
        return scan;
    }
    h.serial = static_cast<std::uint16_t>(*serial);
    h.extended_station = static_cast<std::uint16_t>(*extended);
    h.route = Route{static_cast<std::uint8_t>(*network), static_cast<std::uint8_t>(*station),
                    static_cast<std::uint16_t>(*module_io), static_cast<std::uint8_t>(*multidrop)};
    h.data_length = static_cast<std::uint16_t>(*length);
    scan.size = h.header_size + h.data_length;
    return settle(scan, data.size(), max_frame_bytes);
}

std::string_view to_string(Codec codec) { return codec == Codec::Binary ? "binary" : "ASCII"; }
std::string_view to_string(FrameKind kind) {
    switch (kind) {
        case FrameKind::E3: return "3E";
        case FrameKind::E4: return "4E";
        case FrameKind::E1: return "1E";
        case FrameKind::Ext: break;
    }
    return "station-number-extended";
}

FrameScan settle(FrameScan scan, std::size_t available, std::size_t max_frame_bytes) {
    if (scan.size > max_frame_bytes) {
        scan.status = FrameScan::Status::TooLarge;
        return scan;
    }
    if (available < scan.size) {
        scan.needed = scan.size;
        return scan;
    }
    scan.status = FrameScan::Status::Complete;
    return scan;
}

}  // namespace slmp::protocol
