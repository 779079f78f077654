// Device memory that outlives the process (docs/cpu-runtime.md, "Persistence"):
// restored from the state directory at start, saved at clean shutdown, every
// snapshot_interval_s, on SIGUSR1 and when asked. Without a state directory
// this object does not exist and nothing touches disk.
#pragma once

#include <chrono>
#include <functional>
#include <optional>
#include <vector>
#include <string_view>

#include "station/asio.hpp"

#include "config/config.hpp"
#include "devicemodel/cpu.hpp"
#include "station/state_store.hpp"
#include "station/station_log.hpp"

namespace slmp::station {

class Persistence {
public:
    // Throws config::ConfigError when the directory cannot be used.
    Persistence(const station::Home& home, devicemodel::Cpu& cpu, const config::PersistenceConfig& config,
                spdlog::logger& log);

    // Loads the snapshot if there is one. A damaged or foreign snapshot stops the
    // start (ConfigError) rather than silently starting from empty memory.
    void restore();
    // Saves now; logs and returns false on failure (the simulator keeps running).
    bool save(std::string_view why);
    void start();   // the interval timer, when an interval is configured
    void stop();

    // The front ends' unit state (station/frontend_state.hpp) beside the
    // device memory, in units.bin: what save() writes (nullopt: nothing to
    // save, the file stays), and what was saved last (nullopt: none).
    std::function<std::optional<std::vector<std::uint8_t>>()> units;
    // Called before each save: the scan loop catches up, so a sleeping
    // station saves what a scanning one would (ScanLoop::catch_up).
    std::function<void()> before_save;
    std::optional<std::vector<std::uint8_t>> load_units() const { return units_store_.load(); }
    const std::filesystem::path& units_file() const { return units_store_.file(); }

private:
    boost::asio::awaitable<void> every_interval();

    devicemodel::Cpu& cpu_;
    spdlog::logger& log_;
    StateStore store_;
    StateStore units_store_;
    std::chrono::milliseconds interval_;
    bool restore_all_;
    boost::asio::steady_timer timer_;
    bool stopped_ = false;
};

}  // namespace slmp::station
