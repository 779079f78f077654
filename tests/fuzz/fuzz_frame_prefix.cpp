// scan_frame (protocol/frame.hpp) on a stream fed byte by byte: every proper
// prefix of a whole frame must ask for more, never be skipped as garbage or
// refused as too large, or a TCP session that receives a frame in pieces would
// drop it. Input layout:
//   [0] bit 0 direction (request/response), bits 1-2 policy (binary/ascii/auto),
//       bit 3 frame kind and bit 4 codec for the built frame, bit 5: max 64 bytes
//   [1..] the bytes scanned as they are, and also as the payload of a frame
//       built with encode_frame (so every input tests at least one whole frame)
#include <cstddef>
#include <cstdint>
#include <span>
#include <vector>

#include "protocol/frame.hpp"
#include "protocol/message.hpp"
#include "tests/fuzz/fuzz_check.hpp"

namespace {

using namespace slmp::protocol;

void check_prefixes(std::span<const std::uint8_t> data, Direction direction, DataCodePolicy policy, std::size_t max) {
    auto whole = scan_frame(data, direction, policy, max);
    if (whole.status != FrameScan::Status::Complete) return;
    const std::size_t n = whole.size;
    FUZZ_CHECK(n > 0 && n <= data.size() && n <= max, "a Complete frame of %zu bytes in %zu (max %zu)", n,
               data.size(), max);
    FUZZ_CHECK(n == whole.header.header_size + whole.header.data_length, "size %zu is not header %zu + length %u", n,
               whole.header.header_size, whole.header.data_length);
    // Exactly the frame, in its own block: ASan sees a read past the prefix.
    const std::vector<std::uint8_t> frame(data.begin(), data.begin() + static_cast<std::ptrdiff_t>(n));
    for (std::size_t k = 0; k < n; ++k) {
        auto part = scan_frame(std::span(frame).first(k), direction, policy, max);
        FUZZ_CHECK(part.status == FrameScan::Status::NeedMore, "prefix %zu of a %zu-byte frame gave status %d", k, n,
                   static_cast<int>(part.status));
        FUZZ_CHECK(part.needed > k && part.needed <= n, "prefix %zu of %zu asks for %zu bytes", k, n, part.needed);
    }
    auto again = scan_frame(frame, direction, policy, max);
    FUZZ_CHECK(again.status == FrameScan::Status::Complete && again.size == n,
               "the frame alone scans differently from the frame with bytes after it");
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    if (size < 1) return 0;
    const auto direction = data[0] & 1 ? Direction::Response : Direction::Request;
    const auto policy = static_cast<DataCodePolicy>((data[0] >> 1 & 3) % 3);
    const std::size_t max = data[0] & 0x20 ? 64 : 8192;
    std::span<const std::uint8_t> rest(data + 1, size - 1);
    check_prefixes(rest, direction, policy, max);

    // The same bytes as the payload of a frame this codec builds (encode_frame).
    const auto kind = data[0] & 0x08 ? FrameKind::E4 : FrameKind::E3;
    auto codec = data[0] & 0x10 ? Codec::Ascii : Codec::Binary;
    if (policy != DataCodePolicy::Auto) codec = policy == DataCodePolicy::Binary ? Codec::Binary : Codec::Ascii;
    if (rest.size() > 4096) return 0;
    auto frame = encode_frame(direction, kind, codec, 0x1234, Route{}, rest);
    auto scan = scan_frame(frame, direction, policy, 1u << 16);
    FUZZ_CHECK(scan.status == FrameScan::Status::Complete && scan.size == frame.size(),
               "an encoded %zu-byte frame scans as status %d size %zu", frame.size(), static_cast<int>(scan.status),
               scan.size);
    check_prefixes(frame, direction, policy, 1u << 16);
    return 0;
}
