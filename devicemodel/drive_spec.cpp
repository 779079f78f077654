#include "devicemodel/drive_spec.hpp"

namespace slmp::devicemodel {

std::string_view drive_kind_name(DriveKind kind) {
    switch (kind) {
        case DriveKind::ProgramMemory: return "program memory";
        case DriveKind::SramCard: return "SRAM card";
        case DriveKind::SdCard: return "SD memory card";
        case DriveKind::StandardRam: return "standard RAM";
        case DriveKind::StandardRom: return "standard ROM";
        case DriveKind::DeviceLabelMemory: return "device/label memory";
        case DriveKind::DataMemory: return "data memory";
    }
    return "drive";
}

std::string_view drive_kind_key(DriveKind kind) {
    switch (kind) {
        case DriveKind::ProgramMemory: return "program_memory";
        case DriveKind::SramCard: return "sram_card";
        case DriveKind::SdCard: return "sd_card";
        case DriveKind::StandardRam: return "standard_ram";
        case DriveKind::StandardRom: return "standard_rom";
        case DriveKind::DeviceLabelMemory: return "device_label_memory";
        case DriveKind::DataMemory: return "data_memory";
    }
    return "?";
}

std::string_view describe(FileFault fault) {
    switch (fault) {
        case FileFault::None: return "ok";
        case FileFault::NoDrive: return "no such drive on this CPU, or no card in the slot";
        case FileFault::BadName: return "not a valid file name or path for this CPU";
        case FileFault::NotFound: return "no such file or folder";
        case FileFault::Exists: return "a file of that name exists";
        case FileFault::NotAFile: return "a folder where a file is meant";
        case FileFault::NoCapacity: return "the drive's capacity would be exceeded";
        case FileFault::WriteProtected: return "the drive is write-protected (SD card LOCK switch)";
        case FileFault::ReadOnly: return "the file is read-only (attribute 01H)";
        case FileFault::Locked: return "the file is locked by an open (1827) of another client or mode";
        case FileFault::Password: return "the file password does not match";
        case FileFault::BadPointer: return "no file is open with that file pointer No.";
        case FileFault::NotWriteMode: return "the file was opened for reading";
        case FileFault::OutOfRange: return "offset or length past the file's size";
        case FileFault::TooManyOpen: return "every file pointer No. is in use";
        case FileFault::HostError: return "the host refused the file operation";
        case FileFault::RunState: return "the CPU is in RUN: this file may not be changed";
        case FileFault::Count: break;
    }
    return "file error";
}

std::string_view file_fault_key(FileFault fault) {
    switch (fault) {
        case FileFault::None: return "ok";
        case FileFault::NoDrive: return "no_drive";
        case FileFault::BadName: return "bad_name";
        case FileFault::NotFound: return "not_found";
        case FileFault::Exists: return "exists";
        case FileFault::NotAFile: return "not_a_file";
        case FileFault::NoCapacity: return "no_capacity";
        case FileFault::WriteProtected: return "write_protected";
        case FileFault::ReadOnly: return "read_only";
        case FileFault::Locked: return "locked";
        case FileFault::Password: return "password";
        case FileFault::BadPointer: return "bad_pointer";
        case FileFault::NotWriteMode: return "not_write_mode";
        case FileFault::OutOfRange: return "out_of_range";
        case FileFault::TooManyOpen: return "too_many_open";
        case FileFault::HostError: return "host_error";
        case FileFault::RunState: return "run_state";
        case FileFault::Count: break;
    }
    return "?";
}

}  // namespace slmp::devicemodel
