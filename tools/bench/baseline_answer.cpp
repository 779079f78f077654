#include "tools/bench/baseline_answer.hpp"

#include <algorithm>

#include "devicemodel/hex.hpp"

namespace slmp::bench::baseline {

namespace {

// Where a frame's request data length field sits and what follows it
// (SLMP Reference Manual ch. 4).
struct Layout {
    bool ascii;
    std::size_t length_at;   // the request data length field
    std::size_t data_at;     // the first byte the length counts: the monitoring timer
};
constexpr Layout k3EBinary{false, 7, 9};
constexpr Layout k4EBinary{false, 11, 13};   // serial and two reserved bytes after the subheader
constexpr Layout k3EAscii{true, 14, 18};
constexpr Layout k4EAscii{true, 22, 26};

constexpr std::uint16_t kDeviceRead = 0x0401;
constexpr std::uint16_t kDeviceWrite = 0x1401;
constexpr std::uint16_t kNotSupported = 0xC059;
constexpr std::uint16_t kLengthMismatch = 0xC061;
constexpr std::uint16_t kWordPointsOutOfRange = 0xC051;
constexpr std::uint16_t kBitPointsOutOfRange = 0xC052;
// R08CPU's 0401 limits, so the answer is never larger than a real one.
constexpr unsigned kMaxWords = 960;
constexpr unsigned kMaxBitsBinary = 7168;
constexpr unsigned kMaxBitsAscii = 3584;

// A frame's start: which layout, NeedMore while too few bytes tell, or Invalid.
// Only the bytes present are compared, so a request arriving a byte at a time works.
Answered::Status detect(std::span<const std::uint8_t> in, const Layout*& layout) {
    static constexpr char k3E[] = "5000", k4E[] = "5400";
    auto starts = [&](const char* text, std::size_t n) {
        return std::equal(in.begin(), in.begin() + static_cast<std::ptrdiff_t>(std::min(n, in.size())), text);
    };
    if (in.empty()) return Answered::Status::NeedMore;
    if (in[0] == 0x50 || in[0] == 0x54) {
        if (in.size() < 2) return Answered::Status::NeedMore;
        if (in[1] != 0x00) return Answered::Status::Invalid;
        layout = in[0] == 0x50 ? &k3EBinary : &k4EBinary;
        return Answered::Status::Done;
    }
    bool e3 = starts(k3E, 4), e4 = starts(k4E, 4);
    if (!e3 && !e4) return Answered::Status::Invalid;
    if (in.size() < 4) return Answered::Status::NeedMore;
    layout = e3 ? &k3EAscii : &k4EAscii;
    return Answered::Status::Done;
}

// A 16-bit field: two bytes little-endian, or four hex characters. -1 when not hex.
long field16(const std::uint8_t* p, bool ascii) {
    if (!ascii) return p[0] | (p[1] << 8);
    long value = 0;
    for (int i = 0; i < 4; ++i) {
        int d = devicemodel::hex_digit(p[i]);
        if (d < 0) return -1;
        value = value * 16 + d;
    }
    return value;
}

void put16(std::vector<std::uint8_t>& out, unsigned value, bool ascii) {
    if (!ascii) {
        out.push_back(static_cast<std::uint8_t>(value & 0xFF));
        out.push_back(static_cast<std::uint8_t>(value >> 8));
        return;
    }
    devicemodel::append_hex(out, value, 4);
}

// What a request asks for, decided from its command alone.
struct Reply {
    std::uint16_t end_code = 0;
    std::size_t zero_bytes = 0;     // data after the end code: zeros (binary) or '0's (ASCII)
    bool error_information = false; // the route, command and subcommand echoed after a non-zero end code
};

Reply reply_to(std::span<const std::uint8_t> frame, const Layout& layout) {
    const bool ascii = layout.ascii;
    const std::size_t field = ascii ? 4 : 2;
    const std::uint8_t* command_at = frame.data() + layout.data_at + field;   // after the monitoring timer
    long command = field16(command_at, ascii);
    long subcommand = field16(command_at + field, ascii);
    if (command == kDeviceWrite) return {};
    if (command != kDeviceRead || subcommand < 0) return {kNotSupported, 0, true};
    // The point count is the last field of every 0401 form (Q, iQ-R, extended).
    if (frame.size() < layout.data_at + 4 * field) return {kLengthMismatch, 0, true};
    long points = field16(frame.data() + frame.size() - field, ascii);
    bool bits = (subcommand & 1) != 0;   // 0001, 0003, 0081, 0083
    if (bits) {
        unsigned max = ascii ? kMaxBitsAscii : kMaxBitsBinary;
        if (points < 1 || points > static_cast<long>(max)) return {kBitPointsOutOfRange, 0, true};
        // A bit a nibble in binary, a character in ASCII.
        return {0, ascii ? static_cast<std::size_t>(points) : static_cast<std::size_t>(points + 1) / 2, false};
    }
    if (points < 1 || points > static_cast<long>(kMaxWords)) return {kWordPointsOutOfRange, 0, true};
    return {0, static_cast<std::size_t>(points) * field, false};
}

}  // namespace

Answered answer_request(std::span<const std::uint8_t> in, std::vector<std::uint8_t>& out) {
    const Layout* layout = nullptr;
    if (auto status = detect(in, layout); status != Answered::Status::Done) return {status, 0};
    const bool ascii = layout->ascii;
    const std::size_t field = ascii ? 4 : 2;
    if (in.size() < layout->data_at) return {Answered::Status::NeedMore, 0};
    long length = field16(in.data() + layout->length_at, ascii);
    // Too short for monitoring timer, command and subcommand, or too long to be ours.
    if (length < static_cast<long>(3 * field) || layout->data_at + length > kMaxRequestBytes)
        return {Answered::Status::Invalid, 0};
    const std::size_t size = layout->data_at + static_cast<std::size_t>(length);
    if (in.size() < size) return {Answered::Status::NeedMore, 0};

    auto frame = in.first(size);
    Reply reply = reply_to(frame, *layout);
    const std::size_t start = out.size();
    // The response header is the request's up to its length field: the route
    // (and the 4E serial) come back as sent. D0/D4 instead of 50/54.
    out.insert(out.end(), frame.begin(), frame.begin() + static_cast<std::ptrdiff_t>(layout->length_at));
    out[start] = ascii ? 'D' : static_cast<std::uint8_t>(frame[0] | 0x80);
    const std::size_t route_bytes = ascii ? 10 : 5;   // network, station, module I/O, multidrop
    const std::size_t information = reply.error_information ? route_bytes + 2 * field : 0;
    put16(out, static_cast<unsigned>(field + reply.zero_bytes + information), ascii);
    put16(out, reply.end_code, ascii);
    if (reply.error_information) {
        auto route = frame.begin() + static_cast<std::ptrdiff_t>(layout->length_at - route_bytes);
        out.insert(out.end(), route, route + static_cast<std::ptrdiff_t>(route_bytes));
        auto command = frame.begin() + static_cast<std::ptrdiff_t>(layout->data_at + field);
        out.insert(out.end(), command, command + static_cast<std::ptrdiff_t>(2 * field));
    }
    out.resize(out.size() + reply.zero_bytes, ascii ? '0' : 0);
    return {Answered::Status::Done, size};
}

}  // namespace slmp::bench::baseline
