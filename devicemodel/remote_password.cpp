#include "devicemodel/remote_password.hpp"

#include <algorithm>

namespace slmp::devicemodel {

void RemotePassword::configure(std::string password, unsigned lockout_attempts, std::chrono::seconds lockout_period) {
    password_ = std::move(password);
    lockout_attempts_ = lockout_attempts;
    lockout_period_ = lockout_period;
    forget_failures();
}

RemotePassword::Check RemotePassword::check(std::span<const std::uint8_t> given, TimePoint now) {
    if (locked_until_ != TimePoint{}) {
        if (now < locked_until_) return Check::LockedOut;
        forget_failures();   // the lock-out is over: a fresh count
    }
    bool match = configured() && given.size() == password_.size() &&
                 std::equal(given.begin(), given.end(), password_.begin(),
                            [](std::uint8_t a, char b) { return a == static_cast<std::uint8_t>(b); });
    if (match) {
        failures_ = 0;
        return Check::Match;
    }
    if (lockout_attempts_ > 0 && ++failures_ >= lockout_attempts_) locked_until_ = now + lockout_period_;
    return Check::Mismatch;
}

}  // namespace slmp::devicemodel
