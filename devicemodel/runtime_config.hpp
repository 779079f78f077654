// What the configuration tells a running CPU: the switch, scan time, timer and
// counter presets (a simulator has no ladder program, so the presets that the
// program's OUT T0 K20 would give come from here), latch ranges, the remote
// reset and password parameters. Documented in docs/cpu-runtime.md.
#pragma once

#include <chrono>
#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "devicemodel/device_table.hpp"
#include "devicemodel/operating_state.hpp"

namespace slmp::devicemodel {

// Timers `first`..`first+count-1` of `area` (T, ST, LT or LST) are in the
// "program": they time while their coil is on, in units of `base`.
struct TimerRange {
    Area area = Area::T;
    std::uint32_t first = 0;
    std::uint32_t count = 1;
    std::uint32_t preset = 0;
    std::chrono::microseconds base{100000};
};

// Counters of `area` (C or LC) count rising edges of their coil up to `preset`.
struct CounterRange {
    Area area = Area::C;
    std::uint32_t first = 0;
    std::uint32_t count = 1;
    std::uint32_t preset = 0;
};

// Devices kept over a power cycle / Remote RESET and cleared only by latch clear.
struct LatchRange {
    Area area = Area::D;
    std::uint32_t first = 0;
    std::uint32_t count = 0;
};

struct RuntimeConfig {
    RunSwitch run_switch = RunSwitch::Run;
    std::chrono::milliseconds scan_time{10};
    bool remote_reset_enabled = false;      // iQ-R/Q parameter default: disabled
    bool output_off_at_stop = true;         // Y turned off when the CPU enters STOP
    std::string password;                   // remote password; empty = none
    unsigned lockout_attempts = 10;         // wrong Unlocks in a row before the lock-out
    std::chrono::seconds lockout_period{60};
    std::vector<TimerRange> timers;
    std::vector<CounterRange> counters;
    std::vector<LatchRange> latch;
    std::optional<CpuError> error;          // a CPU error present from the start
    // The CPU's system protect (security key / write protection): writes and
    // remote operations over any port are refused (PortProfile::system_protect_code).
    bool system_protect = false;
};

}  // namespace slmp::devicemodel
