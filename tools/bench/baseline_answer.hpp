// The baseline server's whole protocol: find where a request ends and append
// an answer of the right size (docs/bench.md, "The baseline server").
//
// It exists to measure what this machine's sockets cost without a PLC behind
// them, so it decodes only what the answer's size needs:
//   - the subheader (3E/4E, binary "50 00"/"54 00" or ASCII "5000"/"5400") and
//     the request data length: where the frame ends;
//   - the command and the subcommand's last bit: 0401 word or bit units, 1401;
//   - the point count of 0401, which is the last field of every 0401 form.
// Everything else is copied: the response header is the request's header up to
// its length field (access route and 4E serial echoed) with the subheader
// turned into a response's. A 0401 answers zeros; a 1401 the short OK; any other
// command C059 with the error information block, as a CPU without it would.
// Nothing is stored: a write changes nothing a later read sees.
#pragma once

#include <cstddef>
#include <cstdint>
#include <span>
#include <vector>

namespace slmp::bench::baseline {

// The largest request taken (the simulator's default --max-request-bytes); a
// length field announcing more means the stream is not SLMP.
inline constexpr std::size_t kMaxRequestBytes = 8192;

struct Answered {
    enum class Status : std::uint8_t {
        NeedMore,   // the bytes so far are the start of a request
        Done,       // one request of `size` bytes was answered into `out`
        Invalid,    // not an SLMP request: a TCP connection is closed, a datagram dropped
    };
    Status status = Status::NeedMore;
    std::size_t size = 0;
};

// Looks at the request at the start of `in`; when it is whole, appends its
// answer to `out` (out is never shrunk or cleared here).
Answered answer_request(std::span<const std::uint8_t> in, std::vector<std::uint8_t>& out);

}  // namespace slmp::bench::baseline
