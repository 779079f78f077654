// The CPU's remote password (SLMP Reference Manual §5.7): the configured
// text, and the count of wrong Unlock/Lock attempts that triggers a lock-out
// for a period. Per CPU, not per connection, so reconnecting does not reset the
// count (§15.8 leaves count and period open: both are configuration).
// The lock state itself belongs to each connection (protocol Session).
#pragma once

#include <chrono>
#include <cstdint>
#include <span>
#include <string>

namespace slmp::devicemodel {

class RemotePassword {
public:
    using TimePoint = std::chrono::steady_clock::time_point;

    void configure(std::string password, unsigned lockout_attempts, std::chrono::seconds lockout_period);
    bool configured() const { return !password_.empty(); }

    enum class Check : std::uint8_t { Match, Mismatch, LockedOut };
    // Compares byte for byte (case-sensitive). During a lock-out every attempt,
    // even the right password, is refused and not counted.
    Check check(std::span<const std::uint8_t> given, TimePoint now);

    unsigned failures() const { return failures_; }
    void forget_failures() { failures_ = 0; locked_until_ = {}; }

private:
    std::string password_;
    unsigned lockout_attempts_ = 10;
    std::chrono::seconds lockout_period_{60};
    unsigned failures_ = 0;
    TimePoint locked_until_{};
};

}  // namespace slmp::devicemodel
