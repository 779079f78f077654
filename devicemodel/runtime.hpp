// A CPU that runs: the operating state, the scan cycle, timers and counters,
// the special relays/registers, the remote password and the latch rules, over
// one DeviceMemory. Time comes from outside (scan(now)): the server passes the
// steady clock, tests pass a fake one, so everything here is deterministic.
//
// Requests are served between scans (the real CPU serves them at END
// processing), so a remote RUN/STOP/PAUSE takes effect at a scan boundary and
// SD203 shows it at once. Behaviour and the simulated SM/SD list:
// docs/cpu-runtime.md.
#pragma once

#include <chrono>
#include <cstdint>
#include <functional>
#include <optional>

#include "devicemodel/cpu_profile.hpp"
#include "devicemodel/device_clear.hpp"
#include "devicemodel/device_memory.hpp"
#include "devicemodel/operating_state.hpp"
#include "devicemodel/remote_password.hpp"
#include "devicemodel/runtime_config.hpp"
#include "devicemodel/special_registers.hpp"
#include "devicemodel/timers.hpp"

namespace slmp::devicemodel {

// Remote RUN clear modes (§5.2): 00 none, 01 outside the latch range, 02 all.
enum class ClearMode : std::uint8_t { None = 0, NonLatched = 1, All = 2 };

// Told what the operating state does, for the user's program running on this
// CPU (station/cpu_program.hpp): it keeps the Y image of STOP->RUN and restarts
// its edges and timers. Calls come on the station's strand.
class RuntimeObserver {
public:
    // The state is changing from `before` to `after`; Y are still as they were.
    virtual void state_changing(DeviceMemory& memory, RunState before, RunState after) = 0;
    // Devices were cleared (Remote RUN clear modes, latch clear, a power cycle).
    virtual void devices_cleared() = 0;
    // Power-on and Remote RESET: the CPU starts afresh (from the switch).
    virtual void powered_on() = 0;

protected:
    ~RuntimeObserver() = default;
};

class Runtime {
public:
    using TimePoint = std::chrono::steady_clock::time_point;

    explicit Runtime(Family family = Family::IQR) : family_(family) {}

    // Applies a configuration and powers the CPU on (state from the switch).
    void configure(RuntimeConfig config, DeviceMemory& memory);
    const RuntimeConfig& config() const { return config_; }
    // Re-applied after every device clear and restart, as the CPU's "device
    // initial values" parameter is (§5.2).
    void set_initial_values(std::function<void(DeviceMemory&)> apply) { initial_values_ = std::move(apply); }
    void set_observer(RuntimeObserver* observer) { observer_ = observer; }

    // One scan at time `now` (steady) with the wall-clock calendar.
    void scan(DeviceMemory& memory, TimePoint now, const CalendarTime& calendar);
    // `count` more scans of `per_scan` each, the last at `now`, with nothing
    // but the scans in between (no request, no program, no scenario): the
    // same values as `count` calls of scan() — clocks and the calendar from
    // the last one, timers moved by the sum (TimerBank::scans_until_due), the
    // scan-time statistics as `count` scans of `per_scan`. Only after a
    // scan(), so edges and the first scan are behind. How an idle station
    // catches up (station/scan_loop.hpp).
    void scan_repeated(DeviceMemory& memory, TimePoint now, const CalendarTime& calendar,
                       std::chrono::microseconds per_scan, std::uint64_t count);
    // Right after a scan: how many more scans of `per_scan` each until one
    // that is not a repetition of the last (TimerBank::scans_until_due, or the
    // first scan after a change of state); nullopt: none ever.
    std::optional<std::uint64_t> scans_until_due(const DeviceMemory& memory, std::chrono::microseconds per_scan) const;
    TimePoint now() const { return last_scan_; }
    // The scan time statistics SD520-SD525 publish (none before the second scan in RUN).
    struct ScanTimes {
        std::chrono::microseconds current, min, max;
    };
    std::optional<ScanTimes> scan_times() const {
        if (!scan_min_) return std::nullopt;
        return ScanTimes{scan_current_, *scan_min_, *scan_max_};
    }

    RunState state() const { return state_.state(); }
    const OperatingState& operating_state() const { return state_; }
    const LatchMap& latch() const { return latch_; }
    RemotePassword& password() { return password_; }
    const RemotePassword& password() const { return password_; }

    RemoteRefusal remote_run(DeviceMemory& memory, ClientId client, bool forced, ClearMode clear);
    RemoteRefusal remote_stop(DeviceMemory& memory, ClientId client);
    RemoteRefusal remote_pause(DeviceMemory& memory, ClientId client, bool forced);
    RemoteRefusal latch_clear(DeviceMemory& memory, ClientId client);
    // Remote RESET: on success the CPU has restarted (non-latched devices
    // cleared, hold and error erased, state from the switch).
    RemoteRefusal reset(DeviceMemory& memory);
    RemoteRefusal clear_error(DeviceMemory& memory);
    void set_switch(DeviceMemory& memory, RunSwitch position);
    void raise_error(DeviceMemory& memory, CpuError error);
    // The program executed STOP: the CPU stops at the end of this scan.
    void stop_by_program(DeviceMemory& memory);

    // A power cycle (also the end of a Remote RESET): clears what a power cycle
    // clears and starts from the switch.
    void restart(DeviceMemory& memory);

private:
    template <typename Change>
    RemoteRefusal change(DeviceMemory& memory, Change&& operation);
    void settle(DeviceMemory& memory, RunState before);
    void publish_clocks(DeviceMemory& memory, TimePoint now, const CalendarTime& calendar);
    void record_scan_time(DeviceMemory& memory, std::chrono::microseconds elapsed);
    void error_reset(DeviceMemory& memory);
    void power_on(DeviceMemory& memory);
    void clear(DeviceMemory& memory, ClearScope scope);

    Family family_;
    RuntimeConfig config_;
    OperatingState state_;
    LatchMap latch_;
    TimerBank timers_;
    RemotePassword password_;
    std::function<void(DeviceMemory&)> initial_values_;
    RuntimeObserver* observer_ = nullptr;

    bool clock_started_ = false;
    TimePoint power_on_{};
    TimePoint last_scan_{};
    bool first_scan_ = false;
    bool error_reset_was_on_ = false;   // SM50 at the last END: its OFF->ON change resets the error
    std::optional<std::chrono::microseconds> scan_min_, scan_max_;
    std::chrono::microseconds scan_current_{}, scan_initial_{};
};

}  // namespace slmp::devicemodel
