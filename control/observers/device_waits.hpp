// The waits of GET /api/devices/{address}/wait (docs/api.md, "Waiting for a
// value"): each pending wait is a condition and a timer. Nothing polls: the
// event hub's write observer says when device memory changed, and once the
// request (or scan, or API call) that changed it is over, every condition is
// checked once and the met ones wake their waiting connection by cancelling
// its timer. The timer running out is the timeout.
#pragma once

#include <functional>
#include <vector>

#include "station/asio.hpp"

#include "control/observers/event_hub.hpp"

namespace slmp::control {

class DeviceWaits {
public:
    struct Waiter {
        explicit Waiter(boost::asio::any_io_executor executor, std::function<bool()> holds)
            : holds(std::move(holds)), timer(std::move(executor)) {}
        std::function<bool()> holds;   // reads the value and checks the condition
        boost::asio::steady_timer timer;
        bool met = false;
    };

    DeviceWaits(const station::Home& home, EventHub& events) : home_(home), events_(events) {}
    ~DeviceWaits();
    DeviceWaits(const DeviceWaits&) = delete;
    DeviceWaits& operator=(const DeviceWaits&) = delete;

    // A waiter joins until remove(); the first one attaches the write observer.
    void add(Waiter* waiter);
    void remove(Waiter* waiter);
    // Shutdown: every wait ends now (unmet).
    void close_all();
    std::size_t pending() const { return waiters_.size(); }   // GET /api/info "waits"

private:
    void changed();   // from the write observer: check once the current work is done
    void check();

    station::Home home_;
    EventHub& events_;
    std::vector<Waiter*> waiters_;
    bool check_posted_ = false;
    bool closed_ = false;
};

}  // namespace slmp::control
