// Timers and counters as the scan drives them (in RUN only).
//
// Timer (T, LT): while its coil is on, the current value grows by the time
// elapsed since the previous scan, in units of the range's base (the remainder
// is carried, so a 100 ms timer on a 30 ms scan still counts true time). The
// scan that first sees the coil on starts timing from 0, as the OUT instruction
// does; the contact turns on when the value reaches the preset. Coil off: value
// and contact reset.
// Retentive timer (ST, LST): the same, but coil off keeps value and contact.
// Counter (C, LC): each rising edge of the coil (off at the previous scan, on
// now) adds 1 up to the preset; the contact turns on at the preset.
// A client resets a timer or counter by writing its value/contact, as RST does.
#pragma once

#include <chrono>
#include <cstdint>
#include <optional>
#include <span>
#include <vector>

#include "devicemodel/device_memory.hpp"
#include "devicemodel/runtime_config.hpp"

namespace slmp::devicemodel {

class TimerBank {
public:
    void configure(std::span<const TimerRange> timers, std::span<const CounterRange> counters);
    // One scan in RUN: `elapsed` since the previous scan.
    void run(DeviceMemory& memory, std::chrono::microseconds elapsed);
    // STOP/PAUSE or a device clear: edges and carried remainders start afresh.
    void reset_tracking();
    // Right after run(): how many more scans of `per_scan` each until one
    // that changes more than a running timer's current value (a contact that
    // turns on, a counter's edge, a coil turned on or off since, a value a
    // client wrote past the preset); nullopt when no such scan ever comes.
    // Until then a scan only adds to timing values, and run() with the sum of
    // those scans' times gives exactly what they would give one by one (the
    // remainder is carried, the preset and maximum only clamp), which is how
    // an idle station skips them (station/scan_loop.hpp).
    std::optional<std::uint64_t> scans_until_due(const DeviceMemory& memory, std::chrono::microseconds per_scan) const;

private:
    struct Timer {
        TimerRange range;
        std::vector<std::uint8_t> timing;          // coil was on at the previous scan
        std::vector<std::int64_t> remainder_us;    // time not yet worth one base unit
    };
    struct Counter {
        CounterRange range;
        std::vector<std::uint8_t> coil_before;
    };
    static void run_timer(DeviceMemory& memory, Timer& t, std::chrono::microseconds elapsed);
    static void run_counter(DeviceMemory& memory, Counter& c);

    std::vector<Timer> timers_;
    std::vector<Counter> counters_;
};

}  // namespace slmp::devicemodel
