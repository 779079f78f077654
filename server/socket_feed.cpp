#include "server/socket_feed.hpp"

namespace slmp::server {

namespace asio = boost::asio;

bool SocketFeed::read_now(std::vector<std::uint8_t>& into) {
    boost::system::error_code ec;
    const auto n = socket_.available(ec);
    if (ec || n == 0) return false;   // closed, or readable at its end (EOF): the session's next read sees it
    const auto old = into.size();
    into.resize(old + n);
    const auto got = socket_.read_some(asio::buffer(into.data() + old, n), ec);   // ready: does not block
    into.resize(old + got);
    return !ec && got > 0;
}

void SocketFeed::watch(std::function<bool(bool open)> ready) {
    state_->watching = true;
    ++state_->generation;
    state_->ready = std::move(ready);
    arm(state_, socket_);
}

void SocketFeed::arm(const std::shared_ptr<State>& state, station::StrandSocket& socket) {
    const auto generation = state->generation;
    socket.async_wait(station::StrandSocket::wait_read, [state, &socket, generation](const boost::system::error_code& ec) {
        // After its watch ended the session (and the socket) may be gone: touch nothing.
        if (!state->watching || state->generation != generation) return;
        if (!socket.is_open()) {
            state->watching = false;
            state->ready(false);
            return;
        }
        // Cancelled by an Ondemand push waking the session's read: keep watching.
        if (ec == asio::error::operation_aborted) return arm(state, socket);
        if (ec || !state->ready(true)) {
            state->watching = false;
            return;
        }
        arm(state, socket);
    });
}

void SocketFeed::stop_watching() {
    if (!state_->watching) return;
    state_->watching = false;
    state_->ready = nullptr;
    boost::system::error_code ec;
    socket_.cancel(ec);   // the readiness wait; its handler returns at once
}

}  // namespace slmp::server
