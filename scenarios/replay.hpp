// Answering from a recording ("replay" in a scenario): each request is looked
// up by its bytes (a 4E serial number is ignored and echoed from the live
// request), and gets the recorded responses to the same bytes in the order
// they were recorded; once they are used up the last one is repeated (a
// polling HMI keeps reading the final values). Requests the recording does
// not hold get what ReplaySpec::on_miss says.
#pragma once

#include <cstdint>
#include <map>
#include <optional>
#include <span>
#include <vector>

#include "protocol/frame.hpp"
#include "scenarios/recording.hpp"

namespace slmp::scenarios {

class ReplayBook {
public:
    explicit ReplayBook(const Recording& recording);

    struct Answer {
        bool found = false;
        std::optional<std::vector<std::uint8_t>> response;   // nullopt: the PLC did not answer
    };
    Answer answer(std::span<const std::uint8_t> request, const protocol::FrameHeader& header);
    std::size_t size() const { return book_.size(); }

private:
    struct Entry {
        std::vector<std::optional<std::vector<std::uint8_t>>> responses;
        std::size_t next = 0;
    };
    std::map<std::vector<std::uint8_t>, Entry> book_;
};

}  // namespace slmp::scenarios
