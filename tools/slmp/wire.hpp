// Raw exchanges for the tools that must see what a port does with any request
// — an answer, silence or a closed connection — rather than fail on it: slmp
// probe and slmp diff (docs/twin.md). One connection (TCP or UDP) that opens on
// demand, sends request bytes as they are, waits up to the silence time for the
// answer, and reopens after a close or a silence (a late answer must not be
// taken for the next one's). Every exchange can be written to a recording in
// slmp-sim's --record format (docs/scenarios.md), so slmp-replay replays it.
#pragma once

#include <chrono>
#include <cstdint>
#include <fstream>
#include <memory>
#include <span>
#include <string>
#include <vector>

#include "protocol/differential.hpp"
#include "tools/slmp/client.hpp"
#include "tools/slmp/link.hpp"

namespace slmp::cli {

using protocol::differential::Observed;

// JSON lines: a header, then an "exchange" line per request, "open"/"close" per connection.
class WireRecorder {
public:
    WireRecorder(const std::string& path, const std::string& note);
    void opened(std::uint64_t connection, const std::string& peer, bool udp);
    void exchange(std::uint64_t connection, const std::string& peer, bool udp, std::span<const std::uint8_t> request,
                  const Observed& observed);
    void closed(std::uint64_t connection, const std::string& peer, bool udp, const std::string& why);

private:
    double now_ms() const;
    std::ofstream out_;
    Clock::time_point start_ = Clock::now();
};

class Wire {
public:
    Wire(const Target& target, std::chrono::milliseconds silence_after, WireRecorder* recorder = nullptr);

    // One request, one outcome. An answer that is no SLMP 3E/4E response (a 1E
    // answer) comes back whole as it arrived, end code 0xFFFF.
    Observed exchange(std::span<const std::uint8_t> request);
    // `requests` written in one send (a pipelined burst); the outcomes in order.
    // After a silence or a close the rest are marked the same, and the
    // connection is closed; when every request was answered it stays open.
    std::vector<Observed> burst(const std::vector<std::vector<std::uint8_t>>& requests);
    // Opens a connection of its own and keeps it (for counting connections);
    // false when the port refuses or closes it at once.
    bool open();
    void close(const std::string& why);
    bool is_open() const { return link_ != nullptr; }
    std::chrono::microseconds last_elapsed() const { return elapsed_; }
    // Requests sent (not those a connection that could not be opened never carried).
    std::size_t sent() const { return sent_; }
    const Target& target() const { return target_; }

private:
    Observed receive_one(Clock::time_point deadline);
    void record(std::span<const std::uint8_t> request, const Observed& observed);

    Target target_;
    std::chrono::milliseconds silence_after_;
    WireRecorder* recorder_;
    std::unique_ptr<Link> link_;
    std::uint64_t connection_ = 0;
    std::vector<std::uint8_t> pending_;
    std::chrono::microseconds elapsed_{0};
    std::size_t sent_ = 0;
};

}  // namespace slmp::cli
