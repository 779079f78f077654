#include "server/timed_input.hpp"

namespace slmp::server {

namespace asio = boost::asio;

TimedInput::TimedInput(station::StrandSocket& socket, station::ScanLoop& clock) : socket_(socket), clock_(clock) {}

void TimedInput::received(std::size_t n) {
    if (n == 0) return;
    auto& s = *state_;
    s.stamps.push_back({s.front + s.bytes.size(), clock_.clock().now()});
}

void TimedInput::consumed(std::size_t n) {
    auto& s = *state_;
    s.bytes.erase(s.bytes.begin(), s.bytes.begin() + static_cast<std::ptrdiff_t>(n));
    s.front += n;
    while (!s.stamps.empty() && s.stamps.front().end <= s.front) s.stamps.pop_front();
}

TimedInput::TimePoint TimedInput::arrival(std::size_t end) const {
    const auto& s = *state_;
    const auto last = s.front + end;   // the stream offset one past the request's last byte
    for (const auto& stamp : s.stamps)
        if (stamp.end >= last) return stamp.at;
    return clock_.clock().now();
}

bool TimedInput::read_available(State& state, station::StrandSocket& socket, TimePoint now) {
    boost::system::error_code ec;
    const auto n = socket.available(ec);
    if (ec || n == 0) return false;   // closed, or readable at its end (EOF): the session's next read sees it
    const auto old = state.bytes.size();
    state.bytes.resize(old + n);
    const auto got = socket.read_some(asio::buffer(state.bytes.data() + old, n), ec);   // ready: does not block
    state.bytes.resize(old + got);
    if (got > 0) state.stamps.push_back({state.front + state.bytes.size(), now});
    return !ec && got > 0;
}

void TimedInput::watch(const std::shared_ptr<State>& state, station::StrandSocket& socket, station::ScanLoop& clock) {
    const auto generation = state->generation;
    socket.async_wait(station::StrandSocket::wait_read, [state, &socket, &clock, generation](const boost::system::error_code& ec) {
        // After its wait ended the session (and the socket) may be gone: touch nothing.
        if (!state->watching || state->generation != generation) return;
        if (!socket.is_open()) {
            state->watching = false;
            clock.nudge();   // the waiting session sees the closed socket
            return;
        }
        // Cancelled by an Ondemand push waking the session's read: keep watching.
        if (ec == asio::error::operation_aborted) return watch(state, socket, clock);
        if (ec || !read_available(*state, socket, clock.clock().now())) {
            state->watching = false;   // EOF or an error: the session's next read reports it
            return;
        }
        clock.nudge();   // a new request may have a shorter deadline
        watch(state, socket, clock);
    });
}

station::StrandTask<> TimedInput::wait(std::optional<std::uint64_t> seen, std::optional<TimePoint> at) {
    state_->watching = true;
    ++state_->generation;
    watch(state_, socket_, clock_);
    co_await clock_.until_end_or(seen, at);
    state_->watching = false;
    boost::system::error_code ec;
    socket_.cancel(ec);   // the readiness wait; its handler returns at once
    // What arrived up to now belongs to this wake (an END serves it).
    if (socket_.is_open()) read_available(*state_, socket_, clock_.clock().now());
}

}  // namespace slmp::server
