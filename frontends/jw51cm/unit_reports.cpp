#include "frontends/jw51cm/unit_reports.hpp"

#include <algorithm>
#include <initializer_list>
#include <string_view>

namespace slmp::jw51cm {

namespace {

std::uint16_t u16(std::span<const std::uint8_t> p, std::uint32_t at) {
    return static_cast<std::uint16_t>(p[at] | (p[at + 1] << 8));
}

std::string parameter(std::uint32_t address) { return "parameter " + octal(address, 4); }

// Reserved bytes of a block must stay 00 (§15).
std::string reserved_not_zero(std::span<const std::uint8_t> p, std::uint32_t first, std::initializer_list<unsigned> offsets,
                              std::string_view what) {
    for (auto offset : offsets)
        if (p[first + offset] != 0)
            return parameter(first + offset) + " (" + std::string(what) + ") is unused and must be 00";
    return {};
}

}  // namespace

OutputArea completion_area(std::span<const std::uint8_t> p) {
    const auto at = kCompletionParameters;
    return {p[at + 7] == kOutputOn, {p[at + 2], u16(p, at)}, u16(p, at + 4)};
}

OutputArea status_flag_area(std::span<const std::uint8_t> p) {
    const auto at = kStatusFlagParameters;
    return {p[at + 3] == kOutputOn, {p[at + 2], u16(p, at)}, 1};
}

std::string check_report_parameters(std::span<const std::uint8_t> p, const MemoryMap& map) {
    auto c = kCompletionParameters;
    if (p[c + 7] != 0 && p[c + 7] != kOutputOn)
        return parameter(c + 7) + " (command completion information) is not 00 (off) or 80 (on)";
    if (auto problem = reserved_not_zero(p, c, {3, 6}, "command completion information"); !problem.empty()) return problem;
    if (p[c + 7] == kOutputOn) {
        auto area = completion_area(p);
        if (area.bytes < kCompletionMinBytes || area.bytes > kCompletionMaxBytes)
            return parameter(c + 4) + " (the completion information's size, 3664 L, 3665 H) is " + std::to_string(area.bytes) +
                   " bytes; give 16-64 (10 00 to 40 00)";
        if (!map.contains(area.place.file, area.place.address, area.bytes))
            return parameter(c) + ": the completion information area (file " + std::to_string(area.place.file) + ", " +
                   std::to_string(area.bytes) + " bytes from " + octal(area.place.address, 6) +
                   ") is not inside a file; 3660/3661 is the address (L, H), 3662 the file 0-7; files 1-7 have "
                   "\"file_bytes\" bytes, file 0 8192";
    }
    auto f = kStatusFlagParameters;
    if (p[f + 3] != 0 && p[f + 3] != kOutputOn)
        return parameter(f + 3) + " (connection status flags) is not 00 (off) or 80 (on)";
    if (p[f + 3] == kOutputOn) {
        auto area = status_flag_area(p);
        if (!map.contains(area.place.file, area.place.address, 1))
            return parameter(f) + ": the connection status flag byte (file " + std::to_string(area.place.file) + ", " +
                   octal(area.place.address, 6) + ") is not inside a file; 3764/3765 is the address (L, H), 3766 the file 0-7";
    }
    return {};
}

std::vector<std::uint8_t> completion_record(const Caller& caller, std::uint8_t rslt,
                                            std::span<const std::uint8_t> command_from_id, std::uint32_t bytes) {
    std::vector<std::uint8_t> record(std::max<std::uint32_t>(bytes, kCompletionCommandAt), 0);
    std::copy(caller.ip.begin(), caller.ip.end(), record.begin());
    record[4] = static_cast<std::uint8_t>(caller.port & 0xFF);
    record[5] = static_cast<std::uint8_t>(caller.port >> 8);
    record[6] = caller.connection;
    record[010] = rslt;
    auto room = record.size() - kCompletionCommandAt;
    auto copied = std::min<std::size_t>(room, command_from_id.size());
    std::copy_n(command_from_id.begin(), copied, record.begin() + kCompletionCommandAt);
    record.resize(bytes);
    return record;
}

void Connections::assign(std::uint8_t udp, std::uint8_t reserved) {
    udp_ = udp;
    reserved_ = reserved;
    established_ &= static_cast<std::uint8_t>(~udp);
}

std::uint8_t Connections::open() {
    for (unsigned n = 0; n < kConnections; ++n) {
        const auto bit = static_cast<std::uint8_t>(1u << n);
        if ((udp_ | reserved_ | established_) & bit) continue;
        established_ |= bit;
        return static_cast<std::uint8_t>(n);
    }
    return kNoConnection;
}

void Connections::close(std::uint8_t number) {
    if (number < kConnections) established_ &= static_cast<std::uint8_t>(~(1u << number));
}

void Connections::set(std::uint8_t number, bool on) {
    if (number >= kConnections) return;
    const auto bit = static_cast<std::uint8_t>(1u << number);
    established_ = static_cast<std::uint8_t>(on ? established_ | bit : established_ & ~bit);
}

}  // namespace slmp::jw51cm
