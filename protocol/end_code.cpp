#include "protocol/end_code.hpp"

namespace slmp::protocol {

std::string_view describe(EndCode code) {
    switch (code) {
        case EndCode::Ok: return "normal completion";
        case EndCode::LatchClearNotInStop: return "remote latch clear needs the CPU in STOP";
        case EndCode::DeviceNotAccessible: return "the device cannot be accessed by this command or path";
        case EndCode::DeviceOutOfRange: return "device number or span outside the configured device size";
        case EndCode::RouteNetworkNotFound: return "the requested network number cannot be reached from this port";
        case EndCode::RouteStationNotFound: return "the requested station cannot be reached from this port";
        case EndCode::RouteNotCpu: return "the requested module I/O number is not a CPU of this station";
        case EndCode::AsciiConversion: return "ASCII data that cannot be converted to binary";
        case EndCode::WordPointsOverLimit: return "word point count out of range";
        case EndCode::BitPointsOverLimit: return "bit point count out of range";
        case EndCode::AddressOutOfRange: return "request beyond the device range";
        case EndCode::UnsupportedCommand: return "command or subcommand not supported";
        case EndCode::DeviceNotSpecifiable: return "the device cannot be specified (unknown code or not a plain device)";
        case EndCode::BadRequestContent: return "request content is wrong (e.g. bit units on a word device)";
        case EndCode::LengthMismatch: return "request data length does not match the data";
        case EndCode::RemotePasswordLocked: return "remote password is locked";
    }
    return "end code not described";
}

}  // namespace slmp::protocol
