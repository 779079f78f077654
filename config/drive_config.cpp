#include "config/drive_config.hpp"

#include <filesystem>

#include "config/settings.hpp"
#include "devicemodel/drives.hpp"

namespace slmp::config {

namespace fs = std::filesystem;

namespace {

std::uint16_t drive_number(const std::string& text, const std::string& where) {
    if (text.empty() || text.size() > 2 || text.find_first_not_of("0123456789") != std::string::npos)
        throw ConfigError(where + ": '" + text + "' is not a drive number; use 0-4 (docs/files.md)");
    return static_cast<std::uint16_t>(std::stoi(text));
}

}  // namespace

void parse_drives(const JsonAt& root, ServerConfig& config) {
    if (!root.has("drives")) return;
    auto drives = root["drives"];
    drives.expect_object();
    for (const auto& item : drives.json().items()) {
        auto at = drives[item.key()];
        at.expect_object();
        check_keys(at, Section::Drive);
        DriveConfig d;
        d.where = at.source() + ": " + at.pointer();
        d.number = drive_number(item.key(), d.where);
        if (at.has("dir")) d.dir = at["dir"].string();
        if (at.has("capacity")) d.capacity = bounded_setting(at, Section::Drive, "capacity");
        if (at.has("write_protect")) d.write_protect = at["write_protect"].boolean();
        if (at.has("present")) d.present = at["present"].boolean();
        if (at.has("passwords")) {
            auto passwords = at["passwords"];
            passwords.expect_object();
            for (const auto& pw : passwords.json().items())
                d.passwords.emplace_back(pw.key(), passwords[pw.key()].string());
        }
        config.drives.push_back(std::move(d));
    }
}

DriveConfig parse_drive_option(const std::string& text) {
    auto eq = text.find('=');
    if (eq == std::string::npos || eq + 1 == text.size())
        throw ConfigError("--drive " + text + ": expected N=DIR, e.g. --drive 4=./plc-data");
    DriveConfig d;
    d.where = "--drive " + text;
    d.number = drive_number(text.substr(0, eq), d.where);
    d.dir = text.substr(eq + 1);
    return d;
}

void attach_drives(devicemodel::Cpu& cpu, const ServerConfig& config) {
    auto drives = std::make_shared<devicemodel::DriveSet>(cpu.profile().drives);
    const auto& state_dir = config.persistence.state_dir;
    for (auto spec : cpu.profile().drives) {
        if (spec.alias_of) continue;
        // Later entries win: the configuration file's, then --drive's.
        const DriveConfig* chosen = nullptr;
        std::vector<const DriveConfig*> all;
        for (const auto& d : config.drives)
            if (d.number == spec.number) all.push_back(&d);
        std::string dir;
        for (const auto* d : all) {
            chosen = d;
            if (d->capacity) spec.capacity = *d->capacity;
            if (d->write_protect) spec.write_protect = *d->write_protect;
            if (d->present) spec.present = *d->present;
            if (!d->dir.empty()) dir = d->dir;
        }
        // A folder for a card slot means a card is in it (unless "present" says otherwise).
        bool present_given = false;
        for (const auto* d : all) present_given = present_given || d->present.has_value();
        if (!dir.empty() && !present_given) spec.present = true;
        std::unique_ptr<devicemodel::FileStore> store;
        if (!dir.empty()) {
            std::error_code ec;
            if (!fs::is_directory(dir, ec))
                throw ConfigError(chosen->where + ": drive " + std::to_string(spec.number) + " folder '" + dir +
                                  "' does not exist; create it or give an existing folder");
            store = std::make_unique<devicemodel::FolderStore>(fs::absolute(dir));
        } else if (!state_dir.empty()) {
            auto folder = fs::path(state_dir) / "drives" / std::to_string(spec.number);
            std::error_code ec;
            fs::create_directories(folder, ec);
            if (ec)
                throw ConfigError("state_dir: cannot create the drive folder " + folder.string() + " (" + ec.message() +
                                  "); check the state directory's permissions");
            store = std::make_unique<devicemodel::FolderStore>(fs::absolute(folder));
        } else {
            store = std::make_unique<devicemodel::MemoryStore>();
        }
        drives->configure(spec, std::move(store));
        for (const auto* d : all)
            for (const auto& [name, password] : d->passwords) drives->set_password(spec.number, name, password);
    }
    for (const auto& d : config.drives) {
        const auto& family = cpu.profile().drives;
        bool known = false, alias = false;
        for (const auto& spec : family)
            if (spec.number == d.number) known = true, alias = spec.alias_of.has_value();
        if (!known)
            throw ConfigError(d.where + ": " + cpu.profile().name + " has no drive " + std::to_string(d.number) +
                              (family.empty() ? "; this family has no file drives"
                                              : "; see docs/files.md for the drives of each family"));
        if (alias)
            throw ConfigError(d.where + ": drive " + std::to_string(d.number) +
                              " is an alias of drive 3 on iQ-R; configure drive 3");
    }
    cpu.set_drives(std::move(drives));
}

}  // namespace slmp::config
