// The CPU's file drives (SLMP 1810-182A act on them; this file knows no SLMP).
// Model: SLMP Reference Manual §5.8. A drive has a kind, a capacity, a
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
#include <functional>
#include <map>
#include <memory>
#include <optional>
#include <span>
#include <string>
#include <vector>

#include "devicemodel/drive_spec.hpp"
#include "devicemodel/file_store.hpp"

namespace slmp::devicemodel {

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

// What a drive keeps besides its files, for the state directory
// (station/drive_state.cpp): file Nos. with their tombstones, the attributes
// 1825 set, and the switches (card inserted, LOCK).
struct DriveMemo {
    std::uint16_t number = 0;
    bool present = true;
    bool write_protect = false;
    std::map<std::string, std::vector<std::string>> slots;   // folder key -> slot names ("" = tombstone)
    std::map<std::string, std::uint8_t> attributes;          // file key -> FAT attribute
};

class DriveSet {
public:
    static constexpr std::size_t kMaxOpenFiles = 16;   // pointer No. 0-15 (inferred, docs/files.md)

    // The CPU's drives as its profile lists them ("file_drives"), in memory
    // until configure() gives each its store.
    explicit DriveSet(const std::vector<DriveSpec>& drives);

    // The CPU's calendar in seconds since the epoch: what 1820, 1829 and an
    // HTTP upload date a file with. The station gives its virtual clock
    // (--clock frozen, --clock-speed); until then, the host's time.
    using Clock = std::function<std::int64_t()>;
    void set_clock(Clock clock) { clock_ = std::move(clock); }

    // Called after anything a DriveMemo holds changed (a file No. taken or
    // freed, an attribute, a switch), so the state directory can save it.
    void set_on_change(std::function<void()> on_change) { on_change_ = std::move(on_change); }
    std::vector<DriveMemo> memos() const;
    // A saved memo back (at start, before any request); a drive this CPU
    // lacks is skipped. The switches come back only with `switches`.
    void restore(const DriveMemo& memo, bool switches);

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

    std::int64_t now() const;
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

    std::map<std::uint16_t, Drive> drives_;
    std::vector<OpenFile> open_;
    Clock clock_;
    std::function<void()> on_change_;
    void changed() const {
        if (on_change_) on_change_();
    }
};

// Checks one name or path for the dialect and splits it into names; nullopt
// when it is not valid (docs/files.md "Names and paths").
std::optional<std::vector<std::string>> split_checked(const std::string& path, NameForm form, bool allow_root = false);

}  // namespace slmp::devicemodel
