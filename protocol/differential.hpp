// Differential testing of two SLMP servers (docs/twin.md): a generator of
// requests that walk every command and subcommand of the command table, each
// limit of a profile ±1, the edges of every device area, bad devices and bad
// fields — in whichever frame and data code it is given — and the comparison of
// what two servers did with the same request (answer bytes, end code, silence,
// close). Pure: no sockets. `slmp diff` sends the requests to two servers; the
// same pieces serve any tool that must say "does this server answer like that
// one" (slmp probe's served-or-refused test uses sample_request()).
#pragma once

#include <cstdint>
#include <optional>
#include <string>
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
};

std::string describe(const Observed& observed);
// nullopt when both did the same (the same answer bytes, or both silence, or
// both close); else a line saying how they differ.
std::optional<std::string> difference(const Observed& a, const Observed& b);

}  // namespace slmp::protocol::differential
