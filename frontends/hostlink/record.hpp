// Host-link records on a byte stream (Ladder Motion host-link manual, docs/hostlink.md): the
// FCS, and cutting `@` … FCS `*` CR records — bare (touch-panel style) or
// wrapped in STX … ETX (PC style) — out of what a transport received.
#pragma once

#include <cstddef>
#include <cstdint>
#include <span>
#include <string>
#include <string_view>

namespace slmp::hostlink {

inline constexpr std::size_t kMaxRecordBytes = 132;   // §3.3: "132 bytes per record"
// Data characters a response may carry: a record less `@00`, command, code, FCS, `*` CR.
inline constexpr std::size_t kMaxResponseData = kMaxRecordBytes - 11;
inline constexpr char kStx = 0x02, kEtx = 0x03;

// XOR of every byte of `text`, as two uppercase hex characters (§2.1).
std::string fcs(std::string_view text);
// The LAN wrapper's checksum: (−Σ bytes) mod 256, two uppercase hex characters (§2.2).
std::string csm(std::string_view text);
// `body` ("@00" + command + text) closed with its FCS, `*` and CR.
std::string close_record(std::string_view body);

// What the stream holds at its front.
struct Cut {
    enum class Kind {
        NeedMore,   // a record has begun but is not whole yet (or nothing at all)
        Garbage,    // `consumed` bytes that start no record: dropped
        Record,     // one record: `record` is `@` … CR, without the wrapper
    };
    Kind kind = Kind::NeedMore;
    std::size_t consumed = 0;   // bytes to drop from the front of the stream, wrapper included
    std::string_view record;
    bool wrapped = false;       // it came between STX and ETX; the answer goes back the same way
};

// Cuts the first record. A record ends at the first CR after its `@`; bytes
// before an `@` or STX are garbage. A stream that holds `limit` bytes with
// no CR is garbage too, so a client that never ends a record cannot make the
// buffer grow without bound.
Cut cut_record(std::span<const std::uint8_t> stream, std::size_t limit = 1024);

}  // namespace slmp::hostlink
