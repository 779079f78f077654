// The special relays (SM) and registers (SD) of a CPU in a redundant pair
// (docs/cpu-runtime.md, "Redundant pairs"; docs/plants.md): which system it
// is (A/B), its role (control/standby), why the systems last switched and why
// a switch failed. One table per family; a CPU publishes its own row from the
// pair's state at every END and whenever the pair changes, so SLMP reads and
// the PLC program see them like any SM/SD.
//
// Sources: Q12PRH/Q25PRH (QnPRH) manuals: SM1511 system A, SM1512 system B,
// SM1515 control system, SM1516 standby system, SD1588 the cause of a switch
// that occurred in the own system, SD1601 the switch's cause on both systems
// (0 never, 1 power off / reset / hardware / WDT, 2 stop error, 3 network
// module request, 16 instruction, 17 engineering tool request). MELSEC iQ-R
// redundant function: SD1643 system switching cause (own system), SD1644
// cause of a switch failure, SD1649 cause of the last successful switch, same
// codes. The iQ-R relays' numbers (SM1632-SM1635 here) are inferred: the
// public lists we could reach did not show them (docs/cpu-runtime.md).
#pragma once

#include <cstdint>

#include "devicemodel/cpu_profile.hpp"
#include "devicemodel/device_memory.hpp"

namespace slmp::devicemodel {

// SD1588/SD1601 (Q), SD1643/SD1649 (iQ-R).
enum class SwitchCause : std::uint16_t {
    None = 0,              // the systems never switched (since power-on)
    PowerOffOrReset = 1,   // the control system's power cut or RESET
    StopError = 2,         // a stop error of the control system
    NetworkModule = 3,     // a network module's request (not simulated)
    Instruction = 16,      // SP.CONTSW (not simulated)
    Request = 17,          // the engineering tool's request: the HTTP API and the scenario action here
};

// SD1644 (iQ-R): why the last switch the control system tried failed.
enum class SwitchFailure : std::uint16_t {
    None = 0,
    StandbyUnavailable = 1,   // the standby is powered off or resetting
    StandbyStopError = 3,     // a stop error on the standby
    Switching = 8,            // a switch is under way
};

struct RedundantStatus {
    bool system_b = false;   // system A otherwise
    bool control = false;    // the standby otherwise
    SwitchCause own_cause = SwitchCause::None;        // a cause that occurred in this CPU
    SwitchCause switch_cause = SwitchCause::None;     // the cause of the last switch (both CPUs)
    SwitchFailure failure = SwitchFailure::None;      // the last switch this CPU could not make
};

// Writes the family's row (iQ-F has no redundant CPU: nothing).
void publish_redundant(DeviceMemory& memory, Family family, const RedundantStatus& status);

}  // namespace slmp::devicemodel
