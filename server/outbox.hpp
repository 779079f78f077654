// The responses of one TCP connection on their way out. Without scenario
// faults every response found in one read is written in one write, as
// before. A scenario's Delivery can ask for more (docs/scenarios.md "Faults"):
//  - delay: wait before the response (and so before every later one: the
//    connection answers in order, like the CPU);
//  - split: separate writes with pauses between them;
//  - coalesce: hold responses until N are ready, then write them at once; if
//    the client stops sending (it waits for an answer), the hold ends after
//    hold_ms. The session arms watch_hold() before each read so an expiring
//    hold interrupts the read.
// The timing modes (docs/timing.md) do not come here: the session waits on
// the virtual clock before a request is served.
#pragma once

#include <chrono>
#include <cstdint>
#include <deque>
#include <optional>
#include <vector>

#include "station/asio.hpp"

#include "scenarios/faults.hpp"

namespace slmp::server {

class Outbox {
public:
    explicit Outbox(station::StrandSocket& socket);

    void add(std::vector<std::uint8_t> response, const scenarios::Delivery& delivery);
    // Without scenario faults, writes what is queued at once, without an
    // asynchronous operation (the usual case: the answers fit the socket's send
    // buffer). True when nothing is left for send(). Sets `ec` on a failed write.
    bool send_now(boost::system::error_code& ec);
    // Writes everything that is not held, in order. Sets `ec` on a failed write.
    station::StrandTask<> send(boost::system::error_code& ec);

    // Before a read: when responses are held, cancels the read at the hold's end.
    void watch_hold();
    // After a read: stops the watch; true when the read was cut short by it
    // (the held responses are then released for the next send()).
    bool hold_expired();

private:
    struct Item {
        std::vector<std::uint8_t> bytes;
        scenarios::Delivery delivery;
    };
    station::StrandTask<> write(const std::vector<std::uint8_t>& bytes, boost::system::error_code& ec);
    station::StrandTask<> wait(std::chrono::microseconds duration);

    station::StrandSocket& socket_;
    station::StrandTimer timer_;        // delays and pauses
    station::StrandTimer hold_timer_;   // the coalescing hold's end
    std::deque<Item> items_;
    std::vector<std::uint8_t> batch_;        // send_now()'s, reused (keeps its capacity)
    std::size_t group_size_ = 0;             // queued responses the coalescing group waits for (0: no group)
    std::chrono::steady_clock::time_point hold_until_{};
    bool released_ = false;
    bool watching_ = false;
    bool expired_ = false;
};

}  // namespace slmp::server
