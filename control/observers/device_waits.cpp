#include "control/observers/device_waits.hpp"

#include <algorithm>

namespace slmp::control {

DeviceWaits::~DeviceWaits() {
    if (!waiters_.empty()) events_.set_change_listener(nullptr);
}

void DeviceWaits::add(Waiter* waiter) {
    if (closed_) {
        waiter->timer.cancel();
        return;
    }
    if (waiters_.empty()) events_.set_change_listener([this] { changed(); });
    waiters_.push_back(waiter);
}

void DeviceWaits::remove(Waiter* waiter) {
    std::erase(waiters_, waiter);
    if (waiters_.empty()) events_.set_change_listener(nullptr);
}

void DeviceWaits::close_all() {
    closed_ = true;
    for (auto* w : waiters_) w->timer.cancel();
}

// A request writes device by device; its condition is judged on the whole
// request, as any client would see it, so the check runs after it.
void DeviceWaits::changed() {
    if (check_posted_) return;
    check_posted_ = true;
    boost::asio::post(home_, [this] {
        check_posted_ = false;
        check();
    });
}

void DeviceWaits::check() {
    for (auto* w : waiters_) {
        if (w->met || !w->holds()) continue;
        w->met = true;
        w->timer.cancel();
    }
}

}  // namespace slmp::control
