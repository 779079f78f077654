#include "devicemodel/runtime.hpp"

#include <algorithm>

namespace slmp::devicemodel {

using std::chrono::duration_cast;
using std::chrono::microseconds;

void Runtime::configure(RuntimeConfig config, DeviceMemory& memory) {
    config_ = std::move(config);
    state_ = OperatingState(config_.run_switch);
    latch_ = LatchMap(config_.latch);
    timers_.configure(config_.timers, config_.counters);
    password_.configure(config_.password, config_.lockout_attempts, config_.lockout_period);
    power_on(memory);
}

void Runtime::power_on(DeviceMemory& memory) {
    state_.restart();
    if (config_.error) state_.raise(*config_.error);
    timers_.reset_tracking();
    if (observer_) observer_->powered_on();
    clock_started_ = false;   // SD412 and the clock pulses count from the next scan
    scan_min_.reset();
    scan_max_.reset();
    special::publish_constants(memory);
    special::publish_scan_times(memory, family_, {});
    first_scan_ = state_.state() == RunState::Run;
    special::publish_first_scan(memory, first_scan_);
    special::publish_state(memory, state_.state(), state_.cause());
    special::publish_error(memory, state_.error());
}

void Runtime::scan(DeviceMemory& memory, TimePoint now, const CalendarTime& calendar) {
    if (!clock_started_) {
        clock_started_ = true;
        power_on_ = now;
        last_scan_ = now;
    }
    auto elapsed = duration_cast<microseconds>(std::max(now - last_scan_, TimePoint::duration::zero()));
    publish_clocks(memory, now, calendar);
    error_reset(memory);
    if (state_.state() != RunState::Run) return;   // STOP/PAUSE: nothing times

    timers_.run(memory, elapsed);
    if (first_scan_) {
        // The scan that follows STOP->RUN is the first scan; its measured time
        // includes the time spent stopped, so it is left out of the statistics.
        first_scan_ = false;
        special::publish_first_scan(memory, false);
        return;
    }
    record_scan_time(memory, elapsed);
}

void Runtime::scan_repeated(DeviceMemory& memory, TimePoint now, const CalendarTime& calendar, microseconds per_scan,
                            std::uint64_t count) {
    if (count == 0 || !clock_started_) return;
    publish_clocks(memory, now, calendar);
    if (state_.state() != RunState::Run) return;
    timers_.run(memory, per_scan * static_cast<std::int64_t>(count));
    record_scan_time(memory, per_scan);   // min and max of equal times: once is all of them
}

std::optional<std::uint64_t> Runtime::scans_until_due(const DeviceMemory& memory, microseconds per_scan) const {
    if (state_.state() != RunState::Run) return std::nullopt;   // nothing times
    if (first_scan_) return 1;
    return timers_.scans_until_due(memory, per_scan);
}

void Runtime::publish_clocks(DeviceMemory& memory, TimePoint now, const CalendarTime& calendar) {
    last_scan_ = now;
    auto since = duration_cast<microseconds>(now - power_on_);
    special::publish_clock_pulses(memory, since);
    special::publish_second_counter(memory, since);
    special::publish_calendar(memory, calendar, family_);
}

// SM50 Error reset, the CPU's own way to clear a continuation error (Clear
// Error 1617 belongs to a module port; a CPU's built-in port refuses it,
// docs/cpu-runtime.md). An OFF->ON change seen at END clears SM0/SM1/SD0; a
// stop error stays until a reset. iQ-R and iQ-F turn SM50 off again when done
// ("error reset completed"); on Q and L it stays as the program left it.
void Runtime::error_reset(DeviceMemory& memory) {
    const bool on = special::sm(memory, 50);
    const bool rising = on && !error_reset_was_on_;
    error_reset_was_on_ = on;
    if (!rising) return;
    change(memory, [&] { return state_.clear_error(); });
    if (family_ == Family::IQR || family_ == Family::IQF) {
        special::set_sm(memory, 50, false);
        error_reset_was_on_ = false;
    }
}

void Runtime::record_scan_time(DeviceMemory& memory, microseconds elapsed) {
    scan_current_ = elapsed;
    if (!scan_min_) scan_initial_ = elapsed;
    scan_min_ = scan_min_ ? std::min(*scan_min_, elapsed) : elapsed;
    scan_max_ = scan_max_ ? std::max(*scan_max_, elapsed) : elapsed;
    special::publish_scan_times(memory, family_, {elapsed, scan_initial_, *scan_min_, *scan_max_});
}

template <typename Change>
RemoteRefusal Runtime::change(DeviceMemory& memory, Change&& operation) {
    auto before = state_.state();
    auto refusal = operation();
    if (refusal == RemoteRefusal::None) settle(memory, before);
    return refusal;
}

// Publishes the new state and does what a state change does on the CPU.
void Runtime::settle(DeviceMemory& memory, RunState before) {
    auto after = state_.state();
    special::publish_state(memory, after, state_.cause());
    special::publish_error(memory, state_.error());
    if (after == before) return;
    if (observer_) observer_->state_changing(memory, before, after);
    timers_.reset_tracking();   // time spent outside RUN does not count
    if (after == RunState::Stop && config_.output_off_at_stop) {
        const auto* y = find_by_symbol("Y");
        for (std::uint32_t n = 0; n < memory.size(Area::Y); ++n) memory.set_bit(*y, n, false);
    }
    if (after == RunState::Run) {
        first_scan_ = true;
        scan_min_.reset();
        scan_max_.reset();
        special::publish_first_scan(memory, true);
    }
}

void Runtime::clear(DeviceMemory& memory, ClearScope scope) {
    clear_devices(memory, latch_, scope);
    timers_.reset_tracking();
    if (observer_) observer_->devices_cleared();
    if (initial_values_) initial_values_(memory);
}

RemoteRefusal Runtime::remote_run(DeviceMemory& memory, ClientId client, bool forced, ClearMode mode) {
    auto before = state_.state();
    auto refusal = state_.remote_run(client, forced);
    if (refusal != RemoteRefusal::None) return refusal;
    // Devices are cleared only when the CPU really goes to RUN, then it runs.
    if (before != RunState::Run && state_.state() == RunState::Run && mode != ClearMode::None)
        clear(memory, mode == ClearMode::All ? ClearScope::All : ClearScope::NonLatched);
    settle(memory, before);
    return RemoteRefusal::None;
}

RemoteRefusal Runtime::remote_stop(DeviceMemory& memory, ClientId client) {
    return change(memory, [&] { return state_.remote_stop(client); });
}

RemoteRefusal Runtime::remote_pause(DeviceMemory& memory, ClientId client, bool forced) {
    return change(memory, [&] { return state_.remote_pause(client, forced); });
}

RemoteRefusal Runtime::latch_clear(DeviceMemory& memory, ClientId client) {
    auto refusal = state_.can_latch_clear(client);
    if (refusal == RemoteRefusal::None) clear(memory, ClearScope::All);
    return refusal;
}

RemoteRefusal Runtime::reset(DeviceMemory& memory) {
    auto refusal = state_.can_reset(config_.remote_reset_enabled);
    if (refusal == RemoteRefusal::None) restart(memory);
    return refusal;
}

void Runtime::restart(DeviceMemory& memory) {
    clear(memory, ClearScope::NonLatched);
    // Every special relay and register starts afresh, except the device-size
    // registers, which the CPU republishes from its parameters at once.
    const auto* sm = find_by_symbol("SM");
    for (std::uint32_t n = 0; n < memory.size(Area::SM); ++n) memory.set_bit(*sm, n, false);
    password_.forget_failures();
    power_on(memory);
}

RemoteRefusal Runtime::clear_error(DeviceMemory& memory) {
    return change(memory, [&] { return state_.clear_error(); });
}

void Runtime::set_switch(DeviceMemory& memory, RunSwitch position) {
    change(memory, [&] {
        state_.set_switch(position);
        return RemoteRefusal::None;
    });
}

void Runtime::stop_by_program(DeviceMemory& memory) {
    change(memory, [&] {
        state_.stop_by_program();
        return RemoteRefusal::None;
    });
}

void Runtime::raise_error(DeviceMemory& memory, CpuError error) {
    change(memory, [&] {
        state_.raise(error);
        return RemoteRefusal::None;
    });
}

}  // namespace slmp::devicemodel
