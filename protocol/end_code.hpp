// SLMP end codes: one enum, one description table. Which code a situation gets
// on which CPU is decided by the profile (devicemodel/cpu_profile.hpp); these
// are the names the code base uses for them.
// Sources: real-CPU measurements, SLMP Reference Manual ch. 4.
#pragma once

#include <cstdint>
#include <string_view>

namespace slmp::protocol {

enum class EndCode : std::uint16_t {
    Ok = 0x0000,
    LatchClearNotInStop = 0x4013,
    DeviceNotAccessible = 0x4030,       // device this command/path may not touch
    DeviceOutOfRange = 0x4031,          // iQ-R: start or span past the configured size
    RouteNetworkNotFound = 0x4A01,      // request for another network (chosen, see docs/end-codes.md)
    RouteStationNotFound = 0x4A02,      // request for another station on network 0 (chosen)
    RouteTooManyRelays = 0x4A03,        // a route through more than 7 relay stations (chosen)
    RouteNotCpu = 0x4B02,               // module I/O that is not this CPU (chosen)
    // A redundant pair (docs/plants.md, "Redundant pairs"): the codes the MELSEC
    // redundant system manuals name for a request during a system switch and
    // for the other system's CPU that cannot answer.
    OtherSystemError = 0x4245,          // the other system's CPU (over the tracking cable) is down
    SystemSwitching = 0x4248,           // a system switch is under way
    AsciiConversion = 0xC050,           // ASCII data that is not hexadecimal
    WordPointsOverLimit = 0xC051,
    BitPointsOverLimit = 0xC052,
    AddressOutOfRange = 0xC056,         // Q/L: request beyond the device range
    UnsupportedCommand = 0xC059,
    DeviceNotSpecifiable = 0xC05B,      // unknown device code / device not usable as plain device
    BadRequestContent = 0xC05C,
    LengthMismatch = 0xC061,
    RemotePasswordLocked = 0xC201,
    RemoteResetDisabled = 0x4014,       // 1006 with the remote reset parameter off (chosen, docs/cpu-runtime.md)
    RemoteHeldByOther = 0x4015,         // 1001/1003 mode 0001, 1005: another client holds remote STOP/PAUSE (chosen)
    RemotePasswordLockedOut = 0xC815,   // 1630/1631 during the lock-out after repeated mismatches (chosen in C810-C815)
    // Codes real CPUs and modules answer, named so that describe() explains them
    // to CLI users and in logs (the simulator sends some of them: docs/end-codes.md).
    // Sources: real-CPU measurements, SLMP Reference Manual ch. 4,
    // SLMP Reference Manual ch. 6 (L-series manual, marked [ext]).
    RunWriteProhibited = 0x0055,        // [ext] write to a CPU in RUN while online change is disabled
    ModuleNotPresent = 0x4043,          // 0601/1601 with module number 0000
    ModuleNotAccessible = 0x4080,       // 0601/1601 with module number 03FF; QJ71E71 extended random over limit
    LabelNotFound = 0x40C0,             // label missing or without "access from external device"
    ExtendedTargetRefused = 0x414A,     // 1401 sub 0082 to a protected/unsupported extended target
    RandomBitPointsOverLimit = 0xC053,
    RandomWordPointsOverLimit = 0xC054,
    AsciiLengthMismatch = 0xC058,       // [ext]
    MonitorNotRegistered = 0xC05D,      // [ext] 0802 without a 0801 registration
    NotExecutableOnCpu = 0xC05F,        // [ext]
    BadRequestData = 0xC060,            // [ext]
    DataCodeMismatch = 0xC06F,          // [ext] ASCII to a binary port or the reverse
    RemotePasswordMismatchCount = 0xC200,   // [ext] E71: unlock/lock failures over the notification count
    RemotePasswordMismatch = 0xC810,    // wrong password on Unlock; C811–C815 are the same family
    Busy = 0xCEE0,
    RequestTooLarge = 0xCEE1,
    ResponseTooLarge = 0xCEE2,
    ServerInfoNotFound = 0xCF10,
    SettingNotAllowed = 0xCF20,
    ParameterIdNotFound = 0xCF30,
    ExclusiveStartMissing = 0xCF31,
    RelayRouteError = 0xCF70,
    RelayTimeout = 0xCF71,
};

constexpr EndCode end_code(std::uint16_t raw) { return static_cast<EndCode>(raw); }
constexpr std::uint16_t raw(EndCode code) { return static_cast<std::uint16_t>(code); }

// One line saying what the code means, for logs, the CLI and docs.
std::string_view describe(EndCode code);

}  // namespace slmp::protocol
