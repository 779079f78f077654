// The file drives' memo in the state directory (<state_dir>/drives.json,
// docs/files.md): file Nos. with their tombstones, attributes set by 1825 and
// the switches (card inserted, LOCK). The files themselves are already on
// disk (<state_dir>/drives/<n> or the drive's folder); this is what a restart
// would otherwise forget. Saved atomically (station/state_store.hpp) after
// every change, so a kill -9 loses nothing that was answered.
#pragma once

#include <filesystem>
#include <map>
#include <string>
#include <utility>

#include "devicemodel/drives.hpp"
#include "station/state_store.hpp"
#include "station/station_log.hpp"

namespace slmp::station {

class DriveState {
public:
    // Remembers the switches as configured, to tell a changed configuration
    // from a restart (throws config::ConfigError when the directory is unusable).
    DriveState(const std::filesystem::path& dir, devicemodel::DriveSet& drives, std::string profile, spdlog::logger& log);

    // Loads the memo if there is one. A damaged file stops the start
    // (ConfigError) rather than silently renumbering the files.
    void restore();
    // Saves now; logs and returns false on failure (the simulator keeps running).
    bool save();

private:
    devicemodel::DriveSet& drives_;
    std::string profile_;
    spdlog::logger& log_;
    StateStore store_;
    // Drive -> {present, write_protect} as the configuration set them.
    std::map<std::uint16_t, std::pair<bool, bool>> configured_;
};

}  // namespace slmp::station
