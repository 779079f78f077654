// The CPU's file drives (SLMP 1810-182A act on them; this file knows no SLMP).
// Model: ../shared/spec/slmp-files.md §8. A drive has a kind, a capacity, a
// present flag and a write-protect flag (the SD card's LOCK switch), and keeps
// its files in a FileStore (a host folder or memory). Each directory is an
// array of slots: file No. = 1-based slot, a deleted entry leaves a tombstone
// that keeps its number, new entries take the first free slot (§8.1). Files
// dropped into a folder on the host join at the next look (1810, 1811, ...).
// Locks: a table of open files (pointer No. 0-15) with the §8.3 policy; they
// outlive the connection and go at Remote RESET / power cycle (clear_locks).
// Behaviour and choices: docs/files.md.
#pragma once

#include <cstdint>
#include <map>
#include <memory>
#include <optional>
#include <span>
#include <string>
#include <vector>

#include "devicemodel/cpu_profile.hpp"
#include "devicemodel/file_store.hpp"

namespace slmp::devicemodel {

enum class DriveKind : std::uint8_t {
    ProgramMemory, SramCard, SdCard, StandardRam, StandardRom, DeviceLabelMemory, DataMemory
};
std::string_view drive_kind_name(DriveKind kind);

struct DriveSpec {
    std::uint16_t number = 0;
    DriveKind kind = DriveKind::SdCard;
    std::uint64_t capacity = 0;       // bytes of file data the drive holds
    bool present = true;              // false: a card slot with no card
    bool write_protect = false;       // the SD card's LOCK switch
    std::optional<std::uint16_t> alias_of;   // iQ-R drive 1 -> drive 3
};

// The family's drives (docs/files.md): iQ-R 1 (alias of 3), 2, 3, 4; Q/L
// (and a QJ71E71 in front of a Q CPU) 0-4; FX5 none (its port refuses the
// file commands).
std::vector<DriveSpec> family_drives(Family family);

// Why a file operation was refused; the protocol turns each into an end code.
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
};
std::string_view describe(FileFault fault);

// How names arrive: 0000/0004 = one 8.3 name in the drive's root (raw bytes);
// 0040 = a UTF-8 path from the root, "\" between names, ≤ 64 characters a
// name, ≤ 252 in all.
enum class NameForm : std::uint8_t { Short83, Long };

struct FileEntry {
    std::uint32_t number = 0;        // file No. (1-based slot)
    std::string name;                // as the host spells it; "." / ".." for the 0040 entries
    bool directory = false;
    std::uint8_t attribute = 0x20;   // FAT: 01 read-only, 10 directory, 20 archive
    std::uint16_t dos_time = 0, dos_date = 0;
    std::uint64_t size = 0;
};

struct Listing {
    std::vector<FileEntry> entries;
    std::uint32_t last_number = 0;   // the last slot looked at (counts tombstones)
    bool past_end = false;           // start was after the last slot
};

struct FileRef {
    std::uint16_t drive = 0;
    std::string path;
};

enum class OpenMode : std::uint8_t { Read, Write };
using FileOwner = std::uint64_t;   // the connection (protocol::Session::id)

struct OpenFile {
    std::uint16_t pointer = 0;
    std::uint16_t drive = 0;
    HostPath path;
    OpenMode mode = OpenMode::Read;
    FileOwner owner = 0;
};

// MS-DOS packed date/time (§3.8), in the host's local time.
std::uint16_t dos_time(std::int64_t seconds);
std::uint16_t dos_date(std::int64_t seconds);
// nullopt: not a valid date/time (month 0, hour 24, ...).
std::optional<std::int64_t> from_dos(std::uint16_t date, std::uint16_t time);

class DriveSet {
public:
    static constexpr std::size_t kMaxOpenFiles = 16;   // pointer No. 0-15 (inferred, docs/files.md)

    explicit DriveSet(Family family);

    // Replaces a drive's limits and store (config); the drive must exist.
    void configure(const DriveSpec& spec, std::unique_ptr<FileStore> store);
    void set_password(std::uint16_t drive, const std::string& name, const std::string& password);
    void set_write_protect(std::uint16_t drive, bool on);
    void set_present(std::uint16_t drive, bool on);

    struct DriveView {
        DriveSpec spec;
        std::string location;
        std::uint64_t used = 0;
    };
    std::vector<DriveView> drives() const;
    // The drive a number reaches (aliases followed), or null.
    std::uint16_t resolve_number(std::uint16_t number) const;
    bool exists(std::uint16_t number) const;

    FileFault list(std::uint16_t drive, const std::string& dir, NameForm form, std::uint32_t start, std::uint16_t count,
                   Listing& out);
    FileFault find(const FileRef& file, NameForm form, std::uint32_t& number);
    // Checks a file's password ("" = none given; spaces are padding).
    FileFault check_password(const FileRef& file, NameForm form, const std::string& given);
    bool has_password(const FileRef& file, NameForm form);
    FileFault create(const FileRef& file, NameForm form, std::uint64_t size);
    FileFault remove(const FileRef& file, NameForm form);
    FileFault copy(const FileRef& to, const FileRef& from, NameForm form);
    FileFault set_attribute(const FileRef& file, NameForm form, std::uint8_t attribute);
    FileFault set_date(const FileRef& file, NameForm form, std::int64_t mtime);
    FileFault open(const FileRef& file, NameForm form, OpenMode mode, FileOwner owner, std::uint16_t& pointer);
    FileFault read(std::uint16_t pointer, FileOwner owner, std::uint32_t offset, std::uint16_t count,
                   std::vector<std::uint8_t>& out);
    FileFault write(std::uint16_t pointer, FileOwner owner, std::uint32_t offset, std::span<const std::uint8_t> data);
    // Close type 0: this pointer (owned by `owner`); 1: all of `owner`'s; 2: every lock.
    FileFault close(std::uint16_t pointer, FileOwner owner, std::uint16_t type);
    // Remote RESET, power cycle: every lock is gone.
    void clear_locks() { open_.clear(); }
    const std::vector<OpenFile>& open_files() const { return open_; }
    // HTTP release of one lock; false when no such pointer.
    bool release(std::uint16_t pointer);

    // Host access for the HTTP API (no locks asked; names checked the same way).
    FileFault host_list(std::uint16_t drive, const std::string& dir, Listing& out);
    FileFault host_read(const FileRef& file, std::vector<std::uint8_t>& out);
    FileFault host_write(const FileRef& file, std::span<const std::uint8_t> data);
    FileFault host_make_directory(const FileRef& dir);
    FileFault host_remove(const FileRef& file);

    // The Q/L RUN rules need to know what a file is (by extension, docs/files.md).
    static bool program_file(const std::string& name);
    static bool parameter_file(const std::string& name);
    static bool boot_file(const std::string& name);
    static bool project_data(const std::string& name);

private:
    struct Drive {
        DriveSpec spec;
        std::unique_ptr<FileStore> store;
        std::map<std::string, std::vector<std::string>> slots;   // folder key -> slot names ("" = free/tombstone)
        std::map<std::string, std::uint8_t> attributes;          // file key -> FAT attribute set by 1825
        std::map<std::string, std::string> passwords;            // upper-case name or path -> password
    };
    struct Resolved {
        Drive* drive = nullptr;
        HostPath parent;                      // host names of the folder
        std::string name;                     // the last name as given
        std::optional<HostEntry> entry;       // the entry, when it exists
        HostPath path() const;
    };

    Drive* drive_for(std::uint16_t number);
    const Drive* drive_for(std::uint16_t number) const;
    FileFault resolve(const FileRef& file, NameForm form, Resolved& out);
    FileFault resolve_folder(Drive& drive, const std::vector<std::string>& names, HostPath& out);
    // The folder's slot array brought up to date with what the store holds.
    std::vector<std::string>& slots(Drive& drive, const HostPath& folder, const std::vector<HostEntry>& entries);
    std::uint64_t used(const Drive& drive) const;
    std::uint8_t attribute_of(const Drive& drive, const HostPath& path, const HostEntry& entry) const;
    bool is_open(std::uint16_t drive, const HostPath& path) const;
    OpenFile* pointer(std::uint16_t number);

    Family family_;
    std::map<std::uint16_t, Drive> drives_;
    std::vector<OpenFile> open_;
};

// Checks one name or path for the dialect and splits it into names; nullopt
// when it is not valid (docs/files.md "Names and paths").
std::optional<std::vector<std::string>> split_checked(const std::string& path, NameForm form, bool allow_root = false);

}  // namespace slmp::devicemodel
