// The facts of one file drive and the reasons a file operation fails, as plain
// data. They sit apart from devicemodel/drives.hpp because the profiles carry
// them (config/profiles/*.json, "file_drives" and "file_end_codes"), and the
// widely included profile headers should not pull in the file model.
#pragma once

#include <cstddef>
#include <cstdint>
#include <optional>
#include <string_view>

namespace slmp::devicemodel {

enum class DriveKind : std::uint8_t {
    ProgramMemory, SramCard, SdCard, StandardRam, StandardRom, DeviceLabelMemory, DataMemory
};
std::string_view drive_kind_name(DriveKind kind);   // "SD memory card"
std::string_view drive_kind_key(DriveKind kind);    // "sd_card", as the profile JSON spells it

struct DriveSpec {
    std::uint16_t number = 0;
    DriveKind kind = DriveKind::SdCard;
    std::uint64_t capacity = 0;       // bytes of file data the drive holds
    bool present = true;              // false: a card slot with no card
    bool write_protect = false;       // the SD card's LOCK switch
    std::optional<std::uint16_t> alias_of;   // iQ-R drive 1 -> drive 3
};

// Why a file operation was refused; the profile's "file_end_codes" turn each
// into an end code (docs/end-codes.md).
enum class FileFault : std::uint8_t {
    None,
    NoDrive,          // no such drive on this CPU, or the card is not inserted
    BadName,          // not a valid name for the dialect: "..", "\", device names, too long
    NotFound,         // no such file or directory
    Exists,           // 1820/1824: the name is taken
    NotAFile,         // a directory where a file is meant
    NoCapacity,       // the drive's capacity would be exceeded
    WriteProtected,   // the LOCK switch
    ReadOnly,         // attribute 01H: no write, no delete
    Locked,           // another open holds the file (delete, write-open, close type 0 of another's pointer)
    Password,         // the file's password does not match
    BadPointer,       // 1828/1829/182A: no file open with that pointer No.
    NotWriteMode,     // 1829 on a pointer opened for reading
    OutOfRange,       // offset/length past the file's size
    TooManyOpen,      // every pointer No. is in use
    HostError,        // the host refused a read or write (disk full, permissions)
    RunState,         // Q/L in RUN: the file may not be changed (§5)
    Count
};
constexpr std::size_t kFileFaultCount = static_cast<std::size_t>(FileFault::Count);
std::string_view describe(FileFault fault);
std::string_view file_fault_key(FileFault fault);   // "no_drive", as the profile JSON spells it

}  // namespace slmp::devicemodel
