#include "protocol/end_code.hpp"

namespace slmp::protocol {

std::string_view describe(EndCode code) {
    switch (code) {
        case EndCode::Ok: return "normal completion";
        case EndCode::LatchClearNotInStop: return "the CPU is not in STOP (remote latch clear and remote reset need STOP)";
        case EndCode::RemoteResetDisabled: return "remote reset is disabled by the CPU parameters (cpu.remote_reset)";
        case EndCode::RemoteHeldByOther: return "another client holds a remote STOP/PAUSE (use forced mode 0003, or release it)";
        case EndCode::RemotePasswordLockedOut: return "remote password locked out after repeated mismatches; wait and retry";
        case EndCode::DeviceNotAccessible: return "the device cannot be accessed by this command or path";
        case EndCode::DeviceOutOfRange: return "device number or span outside the configured device size";
        case EndCode::RouteNetworkNotFound: return "the requested network number cannot be reached from this port";
        case EndCode::RouteStationNotFound: return "the requested station cannot be reached from this port";
        case EndCode::RouteTooManyRelays: return "the route to the requested station passes more than 7 relay stations";
        case EndCode::RouteNotCpu: return "the requested module I/O number is not a CPU of this station";
        case EndCode::OtherSystemError: return "the other system's CPU of the redundant pair cannot be accessed";
        case EndCode::SystemSwitching: return "the redundant pair is switching systems";
        case EndCode::AsciiConversion: return "ASCII data that cannot be converted to binary";
        case EndCode::WordPointsOverLimit: return "word point count out of range";
        case EndCode::BitPointsOverLimit: return "bit point count out of range";
        case EndCode::AddressOutOfRange: return "request beyond the device range";
        case EndCode::UnsupportedCommand: return "command or subcommand not supported";
        case EndCode::DeviceNotSpecifiable: return "the device cannot be specified (unknown code or not a plain device)";
        case EndCode::BadRequestContent: return "request content is wrong (e.g. bit units on a word device)";
        case EndCode::LengthMismatch: return "request data length does not match the data";
        case EndCode::RemotePasswordLocked: return "remote password is locked";
        case EndCode::RunWriteProhibited: return "write during RUN is not allowed (enable online change / writing during RUN)";
        case EndCode::ModuleNotPresent: return "the specified module number does not exist";
        case EndCode::ModuleNotAccessible: return "the specified module cannot be accessed (module number or extended access over the limit)";
        case EndCode::LabelNotFound: return "label not found, or not enabled for access from external devices";
        case EndCode::ExtendedTargetRefused: return "the extended-specification target is protected or not supported";
        case EndCode::RandomBitPointsOverLimit: return "random-write bit point count out of range";
        case EndCode::RandomWordPointsOverLimit: return "random/monitor word point count out of range";
        case EndCode::AsciiLengthMismatch: return "request data length after ASCII-to-binary conversion does not match the data";
        case EndCode::MonitorNotRegistered: return "no monitor registration (send 0801 before 0802)";
        case EndCode::NotExecutableOnCpu: return "the request cannot be executed on this CPU module";
        case EndCode::BadRequestData: return "request data is wrong (e.g. bad bit-device data)";
        case EndCode::DataCodeMismatch: return "ASCII request on a binary port or binary on an ASCII port";
        case EndCode::RemotePasswordMismatchCount: return "remote password mismatches exceeded the notification count";
        case EndCode::RemotePasswordMismatch: return "remote password does not match";
        case EndCode::Busy: return "another request is being processed; wait and resend";
        case EndCode::RequestTooLarge: return "request message size exceeds the processable range";
        case EndCode::ResponseTooLarge: return "response message size would exceed the processable range";
        case EndCode::ServerInfoNotFound: return "the specified server information number does not exist";
        case EndCode::SettingNotAllowed: return "the request contains an item that cannot be set";
        case EndCode::ParameterIdNotFound: return "the specified parameter ID does not exist";
        case EndCode::ExclusiveStartMissing: return "write-exclusive start (parameter set start) was not performed";
        case EndCode::RelayRouteError: return "error on the route to the relay station";
        case EndCode::RelayTimeout: return "processing aborted by a timeout (routed target did not answer)";
    }
    // Families whose members the sources do not tell apart.
    auto value = raw(code);
    if (value >= 0xC811 && value <= 0xC815) return "remote password error (retry/lock-out family C810-C815)";
    if (value >= 0x4000 && value <= 0x4FFF) return "error detected by the CPU module (4xxx: see the CPU's manual)";
    return "end code not described; see the CPU's or module's manual";
}

}  // namespace slmp::protocol
