// The special relays (SM) and registers (SD) a running CPU keeps up to date,
// the ones HMI and SCADA clients poll. Numbers are the iQ-R / QnU ones (the two
// agree on all of these; only the calendar layout differs by family).
//
//   SM0/SM1  error flags           SD0     latest error code
//   SM50     error reset (written by the program or a client; read at END)
//   SM400/401 always ON / OFF      SM402/403 ON / OFF during the first scan after RUN
//   SM409 10 ms, SM410 100 ms, SM411 200 ms, SM412 1 s, SM413 2 s clocks,
//   SM414 2n s clock (n = SD414), SM415 2n ms clock (n = SD415)
//   SD203    operating state: b0-b3 0 RUN / 2 STOP / 3 PAUSE, b4-b7 cause
//   SD210-SD216 calendar (iQ-R, iQ-F: binary year..day of week;
//            QnU, L, QJ71E71: SD210-SD213 BCD, two digits a byte)
//   SD412    one-second counter since power-on
//   SD520-SD525 scan time: current, minimum, maximum (ms, then the µs part)
// Full list and sources: docs/cpu-runtime.md.
#pragma once

#include <chrono>
#include <cstdint>
#include <optional>

#include "devicemodel/cpu_profile.hpp"
#include "devicemodel/device_memory.hpp"
#include "devicemodel/operating_state.hpp"

namespace slmp::devicemodel {

// Local calendar time, supplied by whoever owns the real clock (the server).
struct CalendarTime {
    int year = 2000;
    int month = 1;      // 1-12
    int day = 1;        // 1-31
    int hour = 0;
    int minute = 0;
    int second = 0;
    int weekday = 6;    // 0 = Sunday (1 Jan 2000 was a Saturday)
};

namespace special {

void set_sm(DeviceMemory& memory, std::uint32_t number, bool on);
void set_sd(DeviceMemory& memory, std::uint32_t number, std::uint32_t value);
std::uint32_t sd(const DeviceMemory& memory, std::uint32_t number);
bool sm(const DeviceMemory& memory, std::uint32_t number);

// Power-on values: SM400 ON, SM401 OFF, SD414/SD415 = 30 (the CPU's defaults).
void publish_constants(DeviceMemory& memory);
void publish_state(DeviceMemory& memory, RunState state, StopCause cause);
void publish_error(DeviceMemory& memory, const std::optional<CpuError>& error);
void publish_first_scan(DeviceMemory& memory, bool first_scan);
// Clock pulses from the time since power-on: each is ON for the first half of its period.
void publish_clock_pulses(DeviceMemory& memory, std::chrono::microseconds since_power_on);
void publish_calendar(DeviceMemory& memory, const CalendarTime& time, Family family);
void publish_second_counter(DeviceMemory& memory, std::chrono::microseconds since_power_on);
// SD520/521 the current scan; then the family's layout (docs/cpu-runtime.md):
// iQ-R and iQ-F minimum SD522/523, maximum SD524/525; Q and L the initial
// scan SD522/523, minimum SD524/525, maximum SD526/527.
struct ScanTimeValues {
    std::chrono::microseconds current{}, initial{}, min{}, max{};
};
void publish_scan_times(DeviceMemory& memory, Family family, const ScanTimeValues& times);

}  // namespace special
}  // namespace slmp::devicemodel
