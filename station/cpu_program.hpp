// The user's PLC program on CPU No.1 of a station (docs/program.md): loaded
// from cpu.program / --program or the HTTP API, executed once a scan between
// the input refresh and END processing, and told by the CPU's runtime what
// RUN/STOP/PAUSE/RESET do to it (RuntimeObserver). Lives on the station's strand.
#pragma once

#include <chrono>
#include <cstdint>
#include <memory>
#include <optional>
#include <span>
#include <string>
#include <string_view>
#include <vector>

#include "config/config.hpp"
#include "devicemodel/cpu.hpp"
#include "program/program.hpp"

namespace spdlog { class logger; }

namespace slmp::station {

class CpuProgram final : public devicemodel::RuntimeObserver {
public:
    // Loads cpu.program.file when it is set; throws config::ConfigError with
    // one line per problem (file, row or line, step, fix) when it does not load.
    CpuProgram(devicemodel::Cpu& cpu, config::ProgramConfig config, spdlog::logger& log);
    ~CpuProgram();
    CpuProgram(const CpuProgram&) = delete;
    CpuProgram& operator=(const CpuProgram&) = delete;

    bool loaded() const { return execution_.has_value(); }
    // Loaded and the CPU in RUN: it executes every scan (the scan loop never sleeps then).
    bool running() const;
    const program::Program* program() const { return loaded() ? &execution_->program() : nullptr; }
    const config::ProgramConfig& config() const { return config_; }
    const std::vector<std::string>& warnings() const { return warnings_; }
    const std::vector<program::DeviceComment>& comments() const { return comments_; }
    // How many programs were written to this CPU (start, PUT, reload, restore):
    // the program page redraws when it changes.
    std::uint64_t load_number() const { return loads_; }

    // Write to PLC: only while the CPU is in STOP (a real CPU refuses a
    // program write in RUN without online change). Throws program::LoadError
    // (the program stays as it was) or std::logic_error when not in STOP.
    void replace(std::string_view bytes, std::string file);
    void unload();                   // STOP only, as replace()
    void reload();                   // cpu.program.file read again (STOP only)
    bool can_change() const;         // the CPU is in STOP

    // Phase 3 of a scan (station/scan_loop.cpp): the program once, if the CPU
    // is in RUN; a stop error, watchdog or STOP instruction acts on the runtime.
    void execute();
    // Phase 5: the scan's time into the running timers' accumulators.
    void end_of_scan(std::chrono::microseconds scan_time);

    // The scans since the program was loaded, for GET /api/program (the
    // modelled times and the last error are the Execution's own).
    struct Statistics {
        std::uint64_t scans = 0;
        std::uint64_t operation_errors = 0;
        std::chrono::nanoseconds host_last{0};
        std::uint64_t executed_last = 0;
    };
    const program::Execution* execution() const { return execution_ ? &*execution_ : nullptr; }
    const Statistics& statistics() const { return statistics_; }

    // The program and its engine state for station snapshots (a "program"
    // part, so the file form carries it too): the source as GX Works CSV, its
    // file name, edge bits and accumulators. Empty: no program loaded.
    std::vector<std::uint8_t> save() const;
    // Puts back the program of `bytes` (compiled again when it differs) and
    // its engine state; throws config::ConfigError naming `source` when the
    // bytes are damaged or the program no longer loads on this CPU.
    void restore(std::span<const std::uint8_t> bytes, const std::string& source);

private:
    void state_changing(devicemodel::DeviceMemory& memory, devicemodel::RunState before,
                        devicemodel::RunState after) override;
    void devices_cleared() override;
    void powered_on() override;
    void install(std::shared_ptr<const program::Program> compiled, std::vector<std::string> warnings);
    std::vector<std::string> shared_coils(const program::Program& compiled) const;
    std::shared_ptr<const program::Program> compile(std::string_view bytes, const std::string& file,
                                                    std::vector<std::string>& warnings) const;

    devicemodel::Cpu& cpu_;
    config::ProgramConfig config_;
    spdlog::logger& log_;
    std::optional<program::Execution> execution_;
    std::vector<std::string> warnings_;
    std::vector<program::DeviceComment> comments_;
    // Y as they were when the CPU left RUN, put back before the first scan
    // of the next RUN (output_mode_at_run "previous"); empty: none kept.
    std::vector<std::uint16_t> y_image_;
    Statistics statistics_;
    std::uint64_t loads_ = 0;
};

}  // namespace slmp::station
