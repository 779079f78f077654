// --targets: the servers a run spreads its connections over, written as
// "host:20000-20999" (a range of ports, a plant of stations) or a comma list
// "host:p1,host:p2", or both mixed ("127.0.0.1:5000,127.0.0.1:20001-20004").
//
// Parsing is pure text (no name lookup), so it can be tested alone; run.cpp
// resolves each host and applies the loopback rule afterwards.
#pragma once

#include <cstdint>
#include <string>
#include <string_view>
#include <vector>

namespace slmp::bench {

struct Target {
    std::string host;   // as written, without the brackets of "[::1]"
    std::uint16_t port = 0;
    friend bool operator==(const Target&, const Target&) = default;
};

// More targets than this in one run is a typo (a range written backwards is
// refused, but 1-65535 is not): one port per connection is the useful maximum.
inline constexpr std::size_t kMaxTargets = 4096;

// The targets in the order written (a range low to high). Throws
// std::invalid_argument with a message naming the bad entry and the fix.
std::vector<Target> parse_targets(std::string_view text);

}  // namespace slmp::bench
