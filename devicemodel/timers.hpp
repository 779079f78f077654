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
