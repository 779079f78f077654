// Sharp JW-51CM computer-link frames for the tests: the 40-byte header (zeros
// will do: the unit echoes what it needs of it), then the ID byte and a 00 —
// 47 for a host's request, 45 for the unit's response — then what follows the
// ID (docs/jw51cm.md, the frame's layout).
#pragma once

#include <cstdint>
#include <vector>

namespace slmp::test::jw51cm {

inline std::vector<std::uint8_t> frame(std::uint8_t id, const std::vector<std::uint8_t>& after_id) {
    std::vector<std::uint8_t> bytes(40, 0);
    bytes.push_back(id);
    bytes.push_back(0x00);
    bytes.insert(bytes.end(), after_id.begin(), after_id.end());
    return bytes;
}
inline std::vector<std::uint8_t> request(const std::vector<std::uint8_t>& after_id) { return frame(0x47, after_id); }
inline std::vector<std::uint8_t> response(const std::vector<std::uint8_t>& after_id) { return frame(0x45, after_id); }

}  // namespace slmp::test::jw51cm
