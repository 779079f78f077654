// Differential testing of two SLMP servers (docs/twin.md): a generator of
// requests that walk every command and subcommand of the command table, each
// limit of a profile ±1, the edges of every device area, bad devices and bad
// fields — in whichever frame and data code it is given — and the comparison of
// what two servers did with the same request (answer bytes, end code, silence,
// close). Pure: no sockets. `slmp diff` sends the requests to two servers; the
// same pieces serve any tool that must say "does this server answer like that
// one" (slmp probe's served-or-refused test uses sample_request()).
#pragma once

#include <chrono>
#include <cstdint>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "devicemodel/cpu_profile.hpp"
#include "protocol/client.hpp"
#include "protocol/command_table.hpp"
#include "protocol/port_profile.hpp"

namespace slmp::protocol::differential {

struct Sample {
    std::string label;                 // what the request tests: "0401/0000 D10239 x2 (span past the end)"
    std::vector<std::uint8_t> bytes;   // the whole request frame
};

// The requests, in the order to send them, for one frame kind and data code
// (`frame`; the 4E serial counts up from frame.serial). The profile gives the
// limits and sizes to probe at ±1 — the original's, so that a twin which got
// one wrong shows it. Device reads avoid what changes by itself (SM/SD besides
// the size registers), so two identical servers answer identically. Remote
// RESET is left out (its answer is a restart, not a comparison).
std::vector<Sample> generate(const PortProfile& port, const devicemodel::CpuProfile& cpu,
                             const client::FrameOptions& frame);

// One harmless request for a command-table row: a read of D0 / M0 or the
// command's smallest well-formed body (a label or file that does not exist,
// loopback of one byte). Writing rows write `scratch` (a word device; bit rows
// write the bits of `scratch_bits`); nullopt for rows the probe must never send
// unasked (remote operations, password lock).
std::optional<std::vector<std::uint8_t>> sample_request(const CommandSpec& row, const client::FrameOptions& frame,
                                                        const devicemodel::DeviceAddress& scratch,
                                                        const devicemodel::DeviceAddress& scratch_bits);

// What a server did with a request.
struct Observed {
    enum class Kind : std::uint8_t { Answer, Silence, Close };
    Kind kind = Kind::Answer;
    std::vector<std::uint8_t> bytes;   // the answer frame (Answer)
    std::uint16_t end_code = 0;        // the answer's end code (Answer)
    // How long the answer took, where the caller measured it (slmp-sim
    // --compare); nullopt: not compared.
    std::optional<std::chrono::microseconds> time = std::nullopt;
};

// The kinds of difference, the same in every report (slmp-sim --compare's log,
// GET /api/compare and its metric, slmp-replay, slmp diff; docs/twin.md,
// "Compare"). The first that applies names it:
//   close    one side closed the connection and the other did not;
//   silence  one side answered and the other stayed silent;
//   end_code both answered, with different end codes;
//   bytes    both answered with the same end code, and the bytes differ;
//   time     the same answer, at answer times far apart (times_far_apart).
// Both silent, or both closed, is the same.
enum class DifferenceKind : std::uint8_t { Same, Close, Silence, EndCode, Bytes, Time };
inline constexpr DifferenceKind kDifferenceKinds[] = {DifferenceKind::Close, DifferenceKind::Silence,
                                                      DifferenceKind::EndCode, DifferenceKind::Bytes,
                                                      DifferenceKind::Time};
// "same", "close", "silence", "end_code", "bytes", "time".
std::string_view kind_name(DifferenceKind kind);
// "answer", "silence", "close".
std::string_view kind_name(Observed::Kind kind);

struct Difference {
    DifferenceKind kind = DifferenceKind::Same;
    // end_code and bytes: the offset of the first byte that differs (a shorter
    // answer that is the start of the longer one: the shorter one's length).
    std::optional<std::size_t> first_byte;
    std::string text;   // one line saying how (empty: the same)

    bool same() const { return kind == DifferenceKind::Same; }
};

// Answer times far apart: the longer is more than twice the shorter plus
// `slack`. Twice absorbs the spread of one server's own answers; the slack,
// the network and the scheduling of a fast one (a twin that answers in 50 µs
// and a PLC in 4 ms are not far apart with a few ms of slack).
bool times_far_apart(std::chrono::microseconds a, std::chrono::microseconds b, std::chrono::microseconds slack);

// How `b` differs from `a`. Times are compared only when both carry one and
// `slack` is given (the answers being the same).
Difference classify(const Observed& a, const Observed& b, std::optional<std::chrono::microseconds> slack = std::nullopt);

std::string describe(const Observed& observed);
// nullopt when both did the same (the same answer bytes, or both silence, or
// both close); else a line saying how they differ (classify's text).
std::optional<std::string> difference(const Observed& a, const Observed& b);

}  // namespace slmp::protocol::differential
