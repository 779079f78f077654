// The bytes a TCP connection has received and not served yet, with the CPU
// time each read arrived (the end_of_scan and model timing modes,
// docs/timing.md). While the session waits on the virtual clock the socket is
// still read (wait()), so a request that arrives during the wait gets its own
// arrival time: end_of_scan serves it at the next END after it, not one scan
// late, and its monitoring timer counts from then.
#pragma once

#include <chrono>
#include <cstdint>
#include <deque>
#include <memory>
#include <optional>
#include <vector>

#include "station/asio.hpp"

#include "station/scan_loop.hpp"

namespace slmp::server {

class TimedInput {
public:
    using TimePoint = station::VirtualClock::TimePoint;

    TimedInput(station::StrandSocket& socket, station::ScanLoop& clock);

    std::vector<std::uint8_t>& bytes() { return state_->bytes; }
    // `n` bytes were appended to bytes() by a read that just returned.
    void received(std::size_t n);
    // The first `n` bytes were served (or skipped): they leave bytes().
    void consumed(std::size_t n);
    // When the byte before bytes()[end] arrived: a request ending there arrived then.
    TimePoint arrival(std::size_t end) const;

    // One wait on the clock (ScanLoop::until_end_or), reading what arrives
    // meanwhile into bytes(). Returns at the END after `seen`, at `at`, or when
    // bytes arrived; the caller re-checks.
    station::StrandTask<> wait(std::optional<std::uint64_t> seen, std::optional<TimePoint> at);

private:
    struct Stamp {
        std::uint64_t end;   // stream offset after the read's last byte
        TimePoint at;
    };
    // Shared with a readiness handler still queued after the wait ended.
    struct State {
        std::vector<std::uint8_t> bytes;
        std::deque<Stamp> stamps;
        std::uint64_t front = 0;   // stream offset of bytes()[0]
        bool watching = false;
        std::uint64_t generation = 0;   // of the wait a readiness handler belongs to
    };
    static void watch(const std::shared_ptr<State>& state, station::StrandSocket& socket,
                      station::ScanLoop& clock);
    static bool read_available(State& state, station::StrandSocket& socket, TimePoint now);

    station::StrandSocket& socket_;
    station::ScanLoop& clock_;
    std::shared_ptr<State> state_ = std::make_shared<State>();
};

}  // namespace slmp::server
