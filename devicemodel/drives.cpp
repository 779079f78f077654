#include "devicemodel/drives.hpp"

#include <algorithm>
#include <cctype>
#include <cstdint>
#include <ctime>

namespace slmp::devicemodel {
namespace {

constexpr std::uint8_t kReadOnly = 0x01, kDirectory = 0x10, kArchive = 0x20;
// 1810/0040 entries stop before the response data passes 1920 bytes (counted
// as binary; "fewer entries than requested because of name length", §4.7).
constexpr std::size_t kMaxListingBytes = 1920;

std::string lower(std::string_view text) {
    std::string out(text);
    for (auto& c : out) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
    return out;
}

std::string key_of(const HostPath& path) {
    std::string out;
    for (const auto& name : path) {
        if (!out.empty()) out += '\\';
        out += lower(name);
    }
    return out;
}

std::string upper_joined(const std::vector<std::string>& names) {
    std::string out;
    for (const auto& name : names) {
        if (!out.empty()) out += '\\';
        for (char c : name) out += static_cast<char>(std::toupper(static_cast<unsigned char>(c)));
    }
    return out;
}

const HostEntry* find_named(const std::vector<HostEntry>& entries, const std::string& name) {
    auto want = lower(name);
    for (const auto& entry : entries)
        if (lower(entry.name) == want) return &entry;
    return nullptr;
}

bool fits_83(const std::string& name) { return split_checked(name, NameForm::Short83).has_value(); }

}  // namespace

std::int64_t DriveSet::now() const {
    return clock_ ? clock_() : static_cast<std::int64_t>(std::time(nullptr));
}

HostPath DriveSet::Resolved::path() const {
    auto out = parent;
    out.push_back(entry ? entry->name : name);
    return out;
}

DriveSet::DriveSet(const std::vector<DriveSpec>& specs) {
    for (const auto& spec : specs) {
        auto& drive = drives_[spec.number];
        drive.spec = spec;
        if (!spec.alias_of) drive.store = std::make_unique<MemoryStore>();
    }
}

void DriveSet::configure(const DriveSpec& spec, std::unique_ptr<FileStore> store) {
    auto& drive = drives_.at(spec.number);
    drive.spec = spec;
    drive.store = std::move(store);
    drive.slots.clear();
    drive.attributes.clear();
}

void DriveSet::set_password(std::uint16_t drive, const std::string& name, const std::string& password) {
    auto* d = drive_for(drive);
    if (!d) return;
    auto names = split_checked(name, NameForm::Long);
    d->passwords[names ? upper_joined(*names) : name] = password;
}

void DriveSet::set_write_protect(std::uint16_t drive, bool on) {
    auto* d = drive_for(drive);
    if (!d || d->spec.write_protect == on) return;
    d->spec.write_protect = on;
    changed();
}

void DriveSet::set_present(std::uint16_t drive, bool on) {
    auto* d = drive_for(drive);
    if (!d || d->spec.present == on) return;
    d->spec.present = on;
    changed();
}

std::vector<DriveMemo> DriveSet::memos() const {
    std::vector<DriveMemo> out;
    for (const auto& [number, drive] : drives_) {
        if (!drive.store) continue;   // an alias keeps nothing of its own
        out.push_back({number, drive.spec.present, drive.spec.write_protect, drive.slots, drive.attributes});
    }
    return out;
}

void DriveSet::restore(const DriveMemo& memo, bool switches) {
    auto it = drives_.find(memo.number);
    if (it == drives_.end() || !it->second.store) return;
    auto& drive = it->second;
    drive.slots = memo.slots;
    drive.attributes = memo.attributes;
    if (switches) {
        drive.spec.present = memo.present;
        drive.spec.write_protect = memo.write_protect;
    }
}

std::uint16_t DriveSet::resolve_number(std::uint16_t number) const {
    auto it = drives_.find(number);
    if (it != drives_.end() && it->second.spec.alias_of) return *it->second.spec.alias_of;
    return number;
}

bool DriveSet::exists(std::uint16_t number) const { return drives_.count(number) > 0; }

DriveSet::Drive* DriveSet::drive_for(std::uint16_t number) {
    auto it = drives_.find(resolve_number(number));
    return it == drives_.end() || !it->second.store ? nullptr : &it->second;
}

const DriveSet::Drive* DriveSet::drive_for(std::uint16_t number) const {
    auto it = drives_.find(resolve_number(number));
    return it == drives_.end() || !it->second.store ? nullptr : &it->second;
}

std::vector<DriveSet::DriveView> DriveSet::drives() const {
    std::vector<DriveView> out;
    for (const auto& [number, drive] : drives_) {
        DriveView view{drive.spec, drive.store ? drive.store->location() : "alias", 0};
        if (drive.store) view.used = used(drive);
        out.push_back(std::move(view));
    }
    return out;
}

std::uint64_t DriveSet::used(const Drive& drive) const {
    std::uint64_t total = 0;
    std::vector<HostPath> folders{{}};
    while (!folders.empty()) {
        auto folder = std::move(folders.back());
        folders.pop_back();
        auto entries = drive.store->list(folder);
        if (!entries) continue;
        for (const auto& entry : *entries) {
            if (!entry.directory) {
                total += entry.size;
                continue;
            }
            auto sub = folder;
            sub.push_back(entry.name);
            folders.push_back(std::move(sub));
        }
    }
    return total;
}

std::vector<std::string>& DriveSet::slots(Drive& drive, const HostPath& folder, const std::vector<HostEntry>& entries) {
    auto& slots = drive.slots[key_of(folder)];
    const auto before = slots;
    if (slots.empty() && !folder.empty()) slots = {".", ".."};   // §6.1: "." and ".." are slots 1 and 2
    for (auto& name : slots) {
        if (name.empty() || name == "." || name == "..") continue;
        bool still = std::any_of(entries.begin(), entries.end(), [&name](const HostEntry& e) { return e.name == name; });
        if (!still) name.clear();   // deleted here or on the host: a tombstone keeps the number
    }
    for (const auto& entry : entries) {
        if (std::find(slots.begin(), slots.end(), entry.name) != slots.end()) continue;
        auto free = std::find(slots.begin(), slots.end(), std::string());
        if (free != slots.end())
            *free = entry.name;
        else
            slots.push_back(entry.name);
    }
    if (slots != before) changed();
    return slots;
}

std::uint8_t DriveSet::attribute_of(const Drive& drive, const HostPath& path, const HostEntry& entry) const {
    auto it = drive.attributes.find(key_of(path));
    if (it != drive.attributes.end()) return it->second;
    if (entry.directory) return kDirectory | kArchive;
    return entry.writable ? kArchive : kArchive | kReadOnly;
}

FileFault DriveSet::resolve_folder(Drive& drive, const std::vector<std::string>& names, HostPath& out) {
    out.clear();
    for (const auto& name : names) {
        auto entries = drive.store->list(out);
        if (!entries) return FileFault::NotFound;
        const auto* found = find_named(*entries, name);
        if (!found || !found->directory) return FileFault::NotFound;
        out.push_back(found->name);
    }
    return FileFault::None;
}

FileFault DriveSet::resolve(const FileRef& file, NameForm form, Resolved& out) {
    auto* drive = drive_for(file.drive);
    if (!drive || !drive->spec.present) return FileFault::NoDrive;
    auto names = split_checked(file.path, form);
    if (!names) return FileFault::BadName;
    out.drive = drive;
    out.name = names->back();
    names->pop_back();
    if (auto fault = resolve_folder(*drive, *names, out.parent); fault != FileFault::None) return fault;
    auto entries = drive->store->list(out.parent);
    if (!entries) return FileFault::NotFound;
    slots(*drive, out.parent, *entries);
    if (const auto* found = find_named(*entries, out.name)) out.entry = *found;
    return FileFault::None;
}

bool DriveSet::is_open(std::uint16_t drive, const HostPath& path) const {
    auto key = key_of(path);
    return std::any_of(open_.begin(), open_.end(),
                       [&](const OpenFile& f) { return f.drive == drive && key_of(f.path) == key; });
}

OpenFile* DriveSet::pointer(std::uint16_t number) {
    auto it = std::find_if(open_.begin(), open_.end(), [number](const OpenFile& f) { return f.pointer == number; });
    return it == open_.end() ? nullptr : &*it;
}

FileFault DriveSet::list(std::uint16_t number, const std::string& dir, NameForm form, std::uint32_t start,
                         std::uint16_t count, Listing& out) {
    out = {};
    auto* drive = drive_for(number);
    if (!drive || !drive->spec.present) return FileFault::NoDrive;
    auto names = split_checked(dir, NameForm::Long, true);
    if (!names || (form == NameForm::Short83 && !names->empty())) return FileFault::BadName;
    HostPath folder;
    if (auto fault = resolve_folder(*drive, *names, folder); fault != FileFault::None) return fault;
    auto entries = drive->store->list(folder);
    if (!entries) return FileFault::NotFound;
    const auto& table = slots(*drive, folder, *entries);
    auto entry_for = [&](std::size_t slot) -> std::optional<FileEntry> {
        const auto& name = table[slot - 1];
        if (name.empty()) return std::nullopt;
        if (name == "." || name == "..") {
            // The folder's own date: the time it was made (§3.8).
            auto parent = folder;
            parent.pop_back();
            auto up = drive->store->list(parent);
            const HostEntry* self = up ? find_named(*up, folder.back()) : nullptr;
            auto mtime = self ? self->mtime : 0;
            return FileEntry{static_cast<std::uint32_t>(slot), name, true, kDirectory | kArchive, dos_time(mtime),
                             dos_date(mtime), 0};
        }
        const auto* e = find_named(*entries, name);
        if (!e || (form == NameForm::Short83 && !fits_83(e->name))) return std::nullopt;
        auto path = folder;
        path.push_back(e->name);
        return FileEntry{static_cast<std::uint32_t>(slot), e->name, e->directory, attribute_of(*drive, path, *e),
                         dos_time(e->mtime), dos_date(e->mtime), e->directory ? 0 : e->size};
    };
    const std::size_t size = table.size();
    if (start > size) {
        out.past_end = true;
        out.last_number = static_cast<std::uint32_t>(size);
        return FileFault::None;
    }
    if (form == NameForm::Short83) {
        // 0000 pages by slot windows: [start, start + count - 1] (§8.2).
        std::size_t last = std::min<std::size_t>(size, start + count - 1);
        for (std::size_t slot = start; slot <= last; ++slot)
            if (auto entry = entry_for(slot)) out.entries.push_back(std::move(*entry));
        out.last_number = static_cast<std::uint32_t>(last);
        return FileFault::None;
    }
    std::size_t bytes = 6;
    // host_list asks for everything (count FFFFH): no response to fit.
    const std::size_t cap = count == 0xFFFF ? SIZE_MAX : kMaxListingBytes;
    out.last_number = static_cast<std::uint32_t>(size);
    for (std::size_t slot = start; slot <= size; ++slot) {
        auto entry = entry_for(slot);
        if (!entry) continue;
        auto entry_bytes = 23 + 2 * std::max<std::size_t>(1, entry->name.size());
        if (out.entries.size() == count || bytes + entry_bytes > cap) {
            out.last_number = out.entries.empty() ? static_cast<std::uint32_t>(slot - 1) : out.entries.back().number;
            return FileFault::None;
        }
        bytes += entry_bytes;
        out.entries.push_back(std::move(*entry));
    }
    return FileFault::None;
}

FileFault DriveSet::find(const FileRef& file, NameForm form, std::uint32_t& number) {
    Resolved r;
    if (auto fault = resolve(file, form, r); fault != FileFault::None) return fault;
    if (!r.entry) return FileFault::NotFound;
    const auto& table = r.drive->slots[key_of(r.parent)];
    auto it = std::find(table.begin(), table.end(), r.entry->name);
    if (it == table.end()) return FileFault::NotFound;
    number = static_cast<std::uint32_t>(it - table.begin() + 1);
    return FileFault::None;
}

bool DriveSet::has_password(const FileRef& file, NameForm form) {
    auto* drive = drive_for(file.drive);
    auto names = split_checked(file.path, form);
    return drive && names && drive->passwords.count(upper_joined(*names)) > 0;
}

FileFault DriveSet::check_password(const FileRef& file, NameForm form, const std::string& given) {
    auto* drive = drive_for(file.drive);
    auto names = split_checked(file.path, form);
    if (!drive || !names) return FileFault::None;   // the operation itself reports the drive or name
    auto it = drive->passwords.find(upper_joined(*names));
    if (it == drive->passwords.end()) return FileFault::None;
    auto trimmed = given.substr(0, given.find_last_not_of(' ') + 1);
    if (given.find_first_not_of(' ') == std::string::npos) trimmed.clear();
    return trimmed == it->second ? FileFault::None : FileFault::Password;
}

FileFault DriveSet::create(const FileRef& file, NameForm form, std::uint64_t size) {
    Resolved r;
    if (auto fault = resolve(file, form, r); fault != FileFault::None) return fault;
    if (r.drive->spec.write_protect) return FileFault::WriteProtected;
    if (r.entry) return FileFault::Exists;
    if (used(*r.drive) + size > r.drive->spec.capacity) return FileFault::NoCapacity;
    std::vector<std::uint8_t> zeros(size, 0);   // the reserved area, zero-filled (§8.2)
    if (!r.drive->store->write(r.path(), zeros, now())) return FileFault::HostError;
    if (auto entries = r.drive->store->list(r.parent)) slots(*r.drive, r.parent, *entries);
    return FileFault::None;
}

FileFault DriveSet::remove(const FileRef& file, NameForm form) {
    Resolved r;
    if (auto fault = resolve(file, form, r); fault != FileFault::None) return fault;
    if (r.drive->spec.write_protect) return FileFault::WriteProtected;
    if (!r.entry) return FileFault::NotFound;
    if (r.entry->directory) return FileFault::NotAFile;
    auto path = r.path();
    if (is_open(resolve_number(file.drive), path)) return FileFault::Locked;
    if (attribute_of(*r.drive, path, *r.entry) & kReadOnly) return FileFault::ReadOnly;
    if (!r.drive->store->remove(path)) return FileFault::HostError;
    r.drive->attributes.erase(key_of(path));
    if (auto entries = r.drive->store->list(r.parent)) slots(*r.drive, r.parent, *entries);
    return FileFault::None;
}

FileFault DriveSet::copy(const FileRef& to, const FileRef& from, NameForm form) {
    Resolved src, dst;
    if (auto fault = resolve(from, form, src); fault != FileFault::None) return fault;
    if (!src.entry) return FileFault::NotFound;
    if (src.entry->directory) return FileFault::NotAFile;
    if (auto fault = resolve(to, form, dst); fault != FileFault::None) return fault;
    if (dst.drive->spec.write_protect) return FileFault::WriteProtected;
    if (dst.entry) return FileFault::Exists;   // inferred: no overwrite (§8.2)
    auto source_path = src.path();
    for (const auto& f : open_)
        if (f.mode == OpenMode::Write && f.drive == resolve_number(from.drive) && key_of(f.path) == key_of(source_path))
            return FileFault::Locked;   // a writer may be half-way through
    auto bytes = src.drive->store->read(source_path);
    if (!bytes) return FileFault::HostError;
    if (used(*dst.drive) + bytes->size() > dst.drive->spec.capacity) return FileFault::NoCapacity;
    auto target = dst.path();
    // The copy keeps the source's date (inferred).
    if (!dst.drive->store->write(target, *bytes, src.entry->mtime)) return FileFault::HostError;
    auto attr = attribute_of(*src.drive, source_path, *src.entry);
    if (attr != kArchive) dst.drive->attributes[key_of(target)] = attr;
    if (auto entries = dst.drive->store->list(dst.parent)) slots(*dst.drive, dst.parent, *entries);
    return FileFault::None;
}

FileFault DriveSet::set_attribute(const FileRef& file, NameForm form, std::uint8_t attribute) {
    Resolved r;
    if (auto fault = resolve(file, form, r); fault != FileFault::None) return fault;
    if (r.drive->spec.write_protect) return FileFault::WriteProtected;
    if (!r.entry) return FileFault::NotFound;
    if (r.entry->directory) return FileFault::NotAFile;
    auto path = r.path();
    if (is_open(resolve_number(file.drive), path)) return FileFault::Locked;
    r.drive->attributes[key_of(path)] = static_cast<std::uint8_t>(attribute & ~kDirectory);
    changed();
    return FileFault::None;
}

FileFault DriveSet::set_date(const FileRef& file, NameForm form, std::int64_t mtime) {
    Resolved r;
    if (auto fault = resolve(file, form, r); fault != FileFault::None) return fault;
    if (r.drive->spec.write_protect) return FileFault::WriteProtected;
    if (!r.entry) return FileFault::NotFound;
    return r.drive->store->set_mtime(r.path(), mtime) ? FileFault::None : FileFault::HostError;
}

FileFault DriveSet::open(const FileRef& file, NameForm form, OpenMode mode, FileOwner owner, std::uint16_t& number) {
    Resolved r;
    if (auto fault = resolve(file, form, r); fault != FileFault::None) return fault;
    if (!r.entry) return FileFault::NotFound;
    if (r.entry->directory) return FileFault::NotAFile;
    auto path = r.path();
    auto drive = resolve_number(file.drive);
    if (mode == OpenMode::Write && (attribute_of(*r.drive, path, *r.entry) & kReadOnly)) return FileFault::ReadOnly;
    // §8.3: a writer is alone; readers share with readers.
    for (const auto& f : open_)
        if (f.drive == drive && key_of(f.path) == key_of(path) && (mode == OpenMode::Write || f.mode == OpenMode::Write))
            return FileFault::Locked;
    for (std::uint16_t candidate = 0; candidate < kMaxOpenFiles; ++candidate) {
        if (pointer(candidate)) continue;
        open_.push_back({candidate, drive, path, mode, owner});
        number = candidate;
        return FileFault::None;
    }
    return FileFault::TooManyOpen;
}

FileFault DriveSet::read(std::uint16_t number, FileOwner owner, std::uint32_t offset, std::uint16_t count,
                         std::vector<std::uint8_t>& out) {
    auto* f = pointer(number);
    if (!f) return FileFault::BadPointer;
    if (f->owner != owner) return FileFault::Locked;
    auto* drive = drive_for(f->drive);
    if (!drive || !drive->spec.present) return FileFault::NoDrive;
    auto bytes = drive->store->read(f->path);
    if (!bytes) return FileFault::NotFound;
    if (offset > bytes->size()) return FileFault::OutOfRange;
    auto n = std::min<std::size_t>(count, bytes->size() - offset);
    out.assign(bytes->begin() + offset, bytes->begin() + static_cast<std::ptrdiff_t>(offset + n));
    return FileFault::None;
}

FileFault DriveSet::write(std::uint16_t number, FileOwner owner, std::uint32_t offset,
                          std::span<const std::uint8_t> data) {
    auto* f = pointer(number);
    if (!f) return FileFault::BadPointer;
    if (f->owner != owner) return FileFault::Locked;
    if (f->mode != OpenMode::Write) return FileFault::NotWriteMode;
    auto* drive = drive_for(f->drive);
    if (!drive || !drive->spec.present) return FileFault::NoDrive;
    if (drive->spec.write_protect) return FileFault::WriteProtected;
    auto bytes = drive->store->read(f->path);
    if (!bytes) return FileFault::NotFound;
    // Not past the size reserved by 1820 (the file's size, §8.2).
    if (static_cast<std::uint64_t>(offset) + data.size() > bytes->size()) return FileFault::OutOfRange;
    std::copy(data.begin(), data.end(), bytes->begin() + offset);
    return drive->store->write(f->path, *bytes, now()) ? FileFault::None : FileFault::HostError;
}

FileFault DriveSet::close(std::uint16_t number, FileOwner owner, std::uint16_t type) {
    if (type == 2) {
        open_.clear();
        return FileFault::None;
    }
    if (type == 1) {
        std::erase_if(open_, [owner](const OpenFile& f) { return f.owner == owner; });
        return FileFault::None;
    }
    auto* f = pointer(number);
    if (!f) return FileFault::BadPointer;
    if (f->owner != owner) return FileFault::Locked;   // §5: another device's lock
    std::erase_if(open_, [number](const OpenFile& g) { return g.pointer == number; });
    return FileFault::None;
}

bool DriveSet::release(std::uint16_t number) {
    return std::erase_if(open_, [number](const OpenFile& f) { return f.pointer == number; }) > 0;
}

FileFault DriveSet::host_list(std::uint16_t drive, const std::string& dir, Listing& out) {
    return list(drive, dir, NameForm::Long, 1, 0xFFFF, out);
}

FileFault DriveSet::host_read(const FileRef& file, std::vector<std::uint8_t>& out) {
    Resolved r;
    if (auto fault = resolve(file, NameForm::Long, r); fault != FileFault::None) return fault;
    if (!r.entry) return FileFault::NotFound;
    if (r.entry->directory) return FileFault::NotAFile;
    auto bytes = r.drive->store->read(r.path());
    if (!bytes) return FileFault::HostError;
    out = std::move(*bytes);
    return FileFault::None;
}

FileFault DriveSet::host_write(const FileRef& file, std::span<const std::uint8_t> data) {
    Resolved r;
    if (auto fault = resolve(file, NameForm::Long, r); fault != FileFault::None) return fault;
    if (r.entry && r.entry->directory) return FileFault::NotAFile;
    auto path = r.path();
    if (is_open(resolve_number(file.drive), path)) return FileFault::Locked;
    auto current = r.entry ? r.entry->size : 0;
    if (used(*r.drive) - current + data.size() > r.drive->spec.capacity) return FileFault::NoCapacity;
    if (!r.drive->store->write(path, data, now())) return FileFault::HostError;
    if (auto entries = r.drive->store->list(r.parent)) slots(*r.drive, r.parent, *entries);
    return FileFault::None;
}

FileFault DriveSet::host_make_directory(const FileRef& dir) {
    Resolved r;
    if (auto fault = resolve(dir, NameForm::Long, r); fault != FileFault::None) return fault;
    if (r.entry) return FileFault::Exists;
    if (!r.drive->store->make_directory(r.path(), now())) return FileFault::HostError;
    if (auto entries = r.drive->store->list(r.parent)) slots(*r.drive, r.parent, *entries);
    return FileFault::None;
}

FileFault DriveSet::host_remove(const FileRef& file) {
    Resolved r;
    if (auto fault = resolve(file, NameForm::Long, r); fault != FileFault::None) return fault;
    if (!r.entry) return FileFault::NotFound;
    if (r.entry->directory) return FileFault::NotAFile;
    auto path = r.path();
    if (is_open(resolve_number(file.drive), path)) return FileFault::Locked;
    if (!r.drive->store->remove(path)) return FileFault::HostError;
    r.drive->attributes.erase(key_of(path));
    if (auto entries = r.drive->store->list(r.parent)) slots(*r.drive, r.parent, *entries);
    return FileFault::None;
}

}  // namespace slmp::devicemodel
