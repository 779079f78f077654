// A profile's file drives and file end codes (docs/files.md, docs/end-codes.md):
//   "file_drives": {"2": {"kind": "sd_card", "capacity": 8388608, "present": true,
//                         "write_protect": false}, "1": {"alias_of": 3}, ...}
//   "file_end_codes": {"no_drive": "4021", "not_found": "4022", ...}
// Keyed by drive number, so a profile that "extends" another changes one
// drive's capacity without repeating the rest, and removes a drive with null.
// A profile with drives must give every end code: a file command has no
// fallback worth guessing.
#include "config/profile_drives.hpp"

#include <string>

#include "config/settings.hpp"

namespace slmp::config {

using devicemodel::DriveKind;
using devicemodel::DriveSpec;
using devicemodel::FileFault;

namespace {

constexpr std::uint16_t kMaxDriveNumber = 0xFF;

// The drive's "kind": one of its row's choices, which are devicemodel::drive_kind_key's names.
DriveKind kind(const JsonAt& at, Section section) {
    auto text = choice_setting(at, section, "kind");
    for (auto k : {DriveKind::ProgramMemory, DriveKind::SramCard, DriveKind::SdCard, DriveKind::StandardRam,
                   DriveKind::StandardRom, DriveKind::DeviceLabelMemory, DriveKind::DataMemory})
        if (text == devicemodel::drive_kind_key(k)) return k;
    at["kind"].fail("drive kind '" + text + "' has no devicemodel::DriveKind", "report this: the settings table and "
                    "devicemodel/drive_spec.cpp disagree");
}

std::uint16_t number(const std::string& key, const JsonAt& at) {
    if (key.empty() || key.size() > 3 || key.find_first_not_of("0123456789") != std::string::npos ||
        std::stoul(key) > kMaxDriveNumber)
        at.fail("'" + key + "' is not a drive number", "key each drive by its number, e.g. \"2\"");
    return static_cast<std::uint16_t>(std::stoul(key));
}

// A drive's keys are the settings table's FileDrive rows, an alias's its DriveAlias rows.
DriveSpec drive(std::uint16_t n, const JsonAt& at) {
    at.expect_object();
    DriveSpec spec;
    spec.number = n;
    if (at.has("alias_of")) {   // iQ-R drive 1: another name for drive 3, nothing of its own
        check_keys(at, Section::DriveAlias);
        spec.alias_of = static_cast<std::uint16_t>(bounded_setting(at, Section::DriveAlias, "alias_of"));
        if (at.has("kind")) spec.kind = kind(at, Section::DriveAlias);
        return spec;
    }
    check_keys(at, Section::FileDrive);
    spec.kind = kind(at, Section::FileDrive);
    spec.capacity = bounded_setting(at, Section::FileDrive, "capacity");
    if (at.has("present")) spec.present = at["present"].boolean();
    if (at.has("write_protect")) spec.write_protect = at["write_protect"].boolean();
    return spec;
}

}  // namespace

void parse_file_drives(const JsonAt& root, devicemodel::CpuProfile& cpu, protocol::PortProfile& port) {
    if (!root.has("file_drives")) return;
    auto drives = root["file_drives"];
    drives.expect_object();
    for (const auto& item : drives.json().items()) {
        if (item.value().is_null()) continue;   // removed by an extending profile
        auto at = drives[item.key()];
        cpu.drives.push_back(drive(number(item.key(), at), at));
    }
    for (const auto& spec : cpu.drives) {
        if (!spec.alias_of) continue;
        bool target = false;
        for (const auto& other : cpu.drives) target = target || (other.number == *spec.alias_of && !other.alias_of);
        if (!target)
            drives[std::to_string(spec.number)]["alias_of"].fail(
                "drive " + std::to_string(*spec.alias_of) + " is not a drive of its own in this profile",
                "alias a drive listed in file_drives");
    }
    if (cpu.drives.empty()) return;
    if (!root.has("file_end_codes"))
        root.fail("a profile with file_drives needs file_end_codes",
                  "give the end code of every refused file operation (docs/end-codes.md)");
    auto codes = root["file_end_codes"];
    codes.expect_object();
    for (std::size_t i = 1; i < devicemodel::kFileFaultCount; ++i) {
        auto key = devicemodel::file_fault_key(static_cast<FileFault>(i));
        port.file_end_codes[i] = codes[key].hex_code();
    }
    for (const auto& item : codes.json().items()) {
        bool listed = false;
        for (std::size_t i = 1; i < devicemodel::kFileFaultCount; ++i)
            listed = listed || item.key() == devicemodel::file_fault_key(static_cast<FileFault>(i));
        if (!listed) codes[item.key()].fail("unknown file end code", "see docs/end-codes.md for the keys");
    }
}

}  // namespace slmp::config
