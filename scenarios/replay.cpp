#include "scenarios/replay.hpp"

#include "devicemodel/hex.hpp"

namespace slmp::scenarios {
namespace {

using protocol::Codec;
using protocol::FrameKind;

// Where a 4E frame keeps its serial number: bytes 2-3 (binary) or
// characters 4-7 (ASCII), in requests and responses alike (§3.1).
std::pair<std::size_t, std::size_t> serial_field(std::span<const std::uint8_t> frame) {
    if (frame.size() >= 4 && (frame[0] == 0x54 || frame[0] == 0xD4) && frame[1] == 0x00) return {2, 2};
    if (frame.size() >= 8 && (frame[0] == '5' || frame[0] == 'D') && frame[1] == '4' && frame[2] == '0' && frame[3] == '0')
        return {4, 4};
    return {0, 0};
}

std::vector<std::uint8_t> key_of(std::span<const std::uint8_t> request) {
    std::vector<std::uint8_t> key(request.begin(), request.end());
    auto [at, size] = serial_field(key);
    for (std::size_t i = 0; i < size; ++i) key[at + i] = 0;
    return key;
}

}  // namespace

ReplayBook::ReplayBook(const Recording& recording) {
    for (const auto& e : recording.exchanges) book_[key_of(e.request)].responses.push_back(e.response);
}

ReplayBook::Answer ReplayBook::answer(std::span<const std::uint8_t> request, const protocol::FrameHeader& header) {
    auto it = book_.find(key_of(request));
    if (it == book_.end()) return {};
    auto& entry = it->second;
    auto response = entry.responses[std::min(entry.next, entry.responses.size() - 1)];
    if (entry.next < entry.responses.size()) ++entry.next;
    if (response && header.kind == FrameKind::E4) {
        // Echo the live request's serial number, as the PLC would have.
        auto [at, size] = serial_field(*response);
        if (size == 2) {
            (*response)[at] = static_cast<std::uint8_t>(header.serial & 0xFF);
            (*response)[at + 1] = static_cast<std::uint8_t>(header.serial >> 8);
        } else if (size == 4) {
            std::vector<std::uint8_t> digits;
            devicemodel::append_hex(digits, header.serial, 4);
            std::copy(digits.begin(), digits.end(), response->begin() + static_cast<long>(at));
        }
    }
    return {true, response};
}

}  // namespace slmp::scenarios
