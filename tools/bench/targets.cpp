#include "tools/bench/targets.hpp"

#include <charconv>
#include <stdexcept>

namespace slmp::bench {

namespace {

[[noreturn]] void refuse(std::string_view entry, const std::string& why) {
    throw std::invalid_argument("--targets entry '" + std::string(entry) + "': " + why +
                                " (write host:port, host:first-last or a comma list of them)");
}

std::uint16_t port_number(std::string_view entry, std::string_view digits) {
    unsigned value = 0;
    auto [end, error] = std::from_chars(digits.data(), digits.data() + digits.size(), value);
    if (digits.empty() || error != std::errc{} || end != digits.data() + digits.size())
        refuse(entry, "'" + std::string(digits) + "' is not a port number");
    if (value < 1 || value > 65535) refuse(entry, "port " + std::string(digits) + " is outside 1-65535");
    return static_cast<std::uint16_t>(value);
}

// "host:port" or "host:first-last" (IPv6 hosts in brackets: "[::1]:5000").
void add_entry(std::string_view entry, std::vector<Target>& targets) {
    std::string_view host, ports;
    if (entry.starts_with('[')) {
        auto close = entry.find("]:");
        if (close == std::string_view::npos) refuse(entry, "an IPv6 address needs ']:' and a port after it");
        host = entry.substr(1, close - 1);
        ports = entry.substr(close + 2);
    } else {
        auto colon = entry.rfind(':');
        if (colon == std::string_view::npos) refuse(entry, "no port");
        host = entry.substr(0, colon);
        ports = entry.substr(colon + 1);
        if (host.find(':') != std::string_view::npos) refuse(entry, "write an IPv6 address in brackets: [::1]:5000");
    }
    if (host.empty()) refuse(entry, "no host");

    auto dash = ports.find('-');
    std::uint16_t first = port_number(entry, ports.substr(0, dash));
    std::uint16_t last = dash == std::string_view::npos ? first : port_number(entry, ports.substr(dash + 1));
    if (last < first) refuse(entry, "the range runs backwards");
    if (targets.size() + (last - first + 1u) > kMaxTargets)
        refuse(entry, "more than " + std::to_string(kMaxTargets) + " targets in all");
    for (unsigned port = first; port <= last; ++port) targets.push_back({std::string(host), static_cast<std::uint16_t>(port)});
}

}  // namespace

std::vector<Target> parse_targets(std::string_view text) {
    if (text.empty()) throw std::invalid_argument("--targets is empty (write host:port, host:first-last or a comma list)");
    std::vector<Target> targets;
    std::size_t start = 0;
    for (;;) {
        auto comma = text.find(',', start);
        auto entry = text.substr(start, comma == std::string_view::npos ? std::string_view::npos : comma - start);
        if (entry.empty()) throw std::invalid_argument("--targets '" + std::string(text) + "' has an empty entry (a stray comma)");
        add_entry(entry, targets);
        if (comma == std::string_view::npos) break;
        start = comma + 1;
    }
    return targets;
}

}  // namespace slmp::bench
