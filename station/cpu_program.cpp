#include "station/cpu_program.hpp"

#include <filesystem>
#include <fstream>
#include <sstream>
#include <stdexcept>

#include <spdlog/logger.h>

#include "devicemodel/byte_reader.hpp"
#include "program/operand_device.hpp"

namespace slmp::station {

using devicemodel::RunState;

namespace {

std::string read_file(const std::string& path, std::string_view what) {
    std::ifstream in(path, std::ios::binary);
    if (!in) throw config::ConfigError(std::string(what) + " " + path + " cannot be read; check the path (relative paths start at the configuration file's folder)");
    std::ostringstream bytes;
    bytes << in.rdbuf();
    return bytes.str();
}

std::string file_name(const std::string& path) { return std::filesystem::path(path).filename().string(); }

}  // namespace

CpuProgram::CpuProgram(devicemodel::Cpu& cpu, config::ProgramConfig config, spdlog::logger& log)
    : cpu_(cpu), config_(std::move(config)), log_(log) {
    try {
        if (!config_.comments.empty())
            comments_ = program::read_comments(read_file(config_.comments, "device comment file"), file_name(config_.comments));
        if (!config_.file.empty()) {
            std::vector<std::string> warnings;
            auto compiled = compile(read_file(config_.file, "program file"), file_name(config_.file), warnings);
            install(std::move(compiled), std::move(warnings));
        }
    } catch (const program::LoadError& e) {
        throw config::ConfigError(e.what());   // one line per problem; main prints each
    }
    cpu_.runtime().set_observer(this);
}

CpuProgram::~CpuProgram() { cpu_.runtime().set_observer(nullptr); }

// A timer or counter the program drives must not also be one of the "cpu"
// section's timers/counters, which the runtime times at END: two owners of one
// coil measure wrongly (docs/program.md "Timers").
std::vector<std::string> CpuProgram::shared_coils(const program::Program& compiled) const {
    using devicemodel::Area;
    const auto& runtime = cpu_.runtime().config();
    auto configured = [&](Area area, std::uint32_t number) {
        for (const auto& t : runtime.timers)
            if (t.area == area && number >= t.first && number - t.first < t.count) return true;
        for (const auto& c : runtime.counters)
            if (c.area == area && number >= c.first && number - c.first < c.count) return true;
        return false;
    };
    std::vector<std::string> problems;
    const auto& source = program::source_of(compiled);
    for (const auto& step : program::compiled_steps(compiled)) {
        if (step.operands.empty() || step.mnemonic.rfind("OUT", 0) != 0) continue;
        const auto coil = program::operand_device(step.operands.front(), cpu_.profile().numbering);
        if (coil && configured(coil->area, coil->number))
            problems.push_back(source.file + ": " + (source.format == program::Format::Text ? "line " : "row ") +
                               std::to_string(step.row) + ": " + step.operands.front() + " is driven by the program and "
                               "is also in the configuration's cpu.timers/cpu.counters; remove it from one of them");
    }
    return problems;
}

std::shared_ptr<const program::Program> CpuProgram::compile(std::string_view bytes, const std::string& file,
                                                            std::vector<std::string>& warnings) const {
    auto source = program::read_source(bytes, file);
    warnings = source.warnings;
    auto compiled = program::compile(source, cpu_.profile(), config_.options, &warnings);
    if (auto problems = shared_coils(*compiled); !problems.empty()) throw program::LoadError(std::move(problems));
    return compiled;
}

void CpuProgram::install(std::shared_ptr<const program::Program> compiled, std::vector<std::string> warnings) {
    for (const auto& warning : warnings) log_.warn("program: {}", warning);
    const auto& source = program::source_of(*compiled);
    log_.info("program {} ({}): {} steps", source.file, source.name, program::step_count(*compiled));
    execution_.emplace(std::move(compiled));
    ++loads_;
    warnings_ = std::move(warnings);
    statistics_ = {};
}

bool CpuProgram::can_change() const { return cpu_.runtime().state() == RunState::Stop; }

void CpuProgram::replace(std::string_view bytes, std::string file) {
    if (!can_change()) throw std::logic_error("the CPU is not in STOP; a program is written in STOP only");
    std::vector<std::string> warnings;
    auto compiled = compile(bytes, file, warnings);
    install(std::move(compiled), std::move(warnings));
}

void CpuProgram::unload() {
    if (!can_change()) throw std::logic_error("the CPU is not in STOP; a program is removed in STOP only");
    if (execution_) log_.info("program {} removed", program::source_of(execution_->program()).file);
    execution_.reset();
    warnings_.clear();
    statistics_ = {};
}

void CpuProgram::reload() {
    if (config_.file.empty()) throw program::LoadError({"no program file is configured (cpu.program.file or --program)"});
    try {
        replace(read_file(config_.file, "program file"), file_name(config_.file));
    } catch (const config::ConfigError& e) {
        throw program::LoadError({e.what()});
    }
}

bool CpuProgram::running() const {
    return execution_ && cpu_.runtime().state() == RunState::Run;
}

void CpuProgram::execute() {
    if (!execution_ || cpu_.runtime().state() != RunState::Run) return;
    auto& memory = cpu_.memory();
    const auto started = std::chrono::steady_clock::now();
    auto outcome = execution_->scan(memory);
    auto& s = statistics_;
    s.host_last = std::chrono::steady_clock::now() - started;
    s.executed_last = outcome.executed;
    ++s.scans;
    if (outcome.error) ++s.operation_errors;
    using Kind = program::ScanOutcome::Kind;
    switch (outcome.kind) {
        case Kind::Ok:
            // A continuation error: SM0/SM1/SD0 are set by the engine; the
            // runtime keeps the error so Clear Error (1617) can clear it.
            if (outcome.error) cpu_.runtime().raise_error(memory, {outcome.error->code, false});
            break;
        case Kind::StopError:
        case Kind::Watchdog:
            log_.warn("program: {} at step {} ({} in row {}): CPU stop error {:04X}", outcome.error->message,
                      outcome.error->step_index, outcome.error->mnemonic, outcome.error->row, outcome.error->code);
            cpu_.runtime().raise_error(memory, {outcome.error->code, true});
            break;
        case Kind::StopInstruction:
            log_.info("program: STOP instruction executed; the CPU stops");
            cpu_.runtime().stop_by_program(memory);
            break;
    }
}

void CpuProgram::end_of_scan(std::chrono::microseconds scan_time) {
    if (execution_ && cpu_.runtime().state() == RunState::Run) execution_->end_of_scan(scan_time);
}

void CpuProgram::state_changing(devicemodel::DeviceMemory& memory, RunState before, RunState after) {
    const auto* y = devicemodel::find_by_symbol("Y");
    const auto words = (memory.size(devicemodel::Area::Y) + 15) / 16;
    if (before == RunState::Run && after == RunState::Stop) {
        // Saved before the runtime turns Y off (output_off_at_stop).
        y_image_.assign(words, 0);
        memory.read_words(*y, 0, y_image_);
    }
    if (after == RunState::Run && before == RunState::Stop) {
        // A new RUN: step 0, SM402 in scan 1, edges and accumulators afresh.
        if (execution_) execution_->restart();
        if (execution_ && config_.options.output_mode_at_run == program::OutputModeAtRun::Previous && !y_image_.empty())
            memory.write_words(*y, 0, y_image_);
        y_image_.clear();
    }
    // PAUSE -> RUN: step 0 again with edges kept, timing from now (docs/program.md).
    if (after == RunState::Run && before == RunState::Pause && execution_) execution_->resume();
}

void CpuProgram::devices_cleared() {
    // Remote RUN with a clear mode clears devices before scan 1, so
    // "previous" then restores an all-OFF image (docs/program.md).
    std::fill(y_image_.begin(), y_image_.end(), 0);
    if (execution_) execution_->restart();
}

void CpuProgram::powered_on() {
    y_image_.clear();
    if (!execution_) return;
    execution_->restart();
    execution_->clear_last_error();   // a RESET or power cycle erases the CPU's error
}

namespace {

void put_part(devicemodel::ByteWriter& w, std::span<const std::uint8_t> bytes) {
    w.u32(static_cast<std::uint32_t>(bytes.size()));
    w.bytes(bytes);
}

std::span<const std::uint8_t> as_bytes(const std::string& text) {
    return {reinterpret_cast<const std::uint8_t*>(text.data()), text.size()};
}

}  // namespace

// Layout: u32 n + file name | u32 n + the source as GX Works CSV | u32 n + engine state.
std::vector<std::uint8_t> CpuProgram::save() const {
    devicemodel::ByteWriter w;
    if (!execution_) return std::move(w.out);
    const auto& source = program::source_of(execution_->program());
    put_part(w, as_bytes(source.file));
    put_part(w, as_bytes(program::write_csv(source)));
    put_part(w, execution_->save_state());
    return std::move(w.out);
}

void CpuProgram::restore(std::span<const std::uint8_t> bytes, const std::string& source) {
    if (bytes.empty()) {
        execution_.reset();
        return;
    }
    devicemodel::ByteReader in(bytes);
    auto part = [&]() {
        auto n = in.u32();
        auto data = n ? in.bytes(*n) : std::nullopt;
        if (!data) throw config::ConfigError(source + ": the program part is cut short; take the snapshot again");
        return *data;
    };
    const auto file = part();
    const auto csv = part();
    const auto state = part();
    const std::string name(file.begin(), file.end());
    const std::string text(csv.begin(), csv.end());
    try {
        if (!execution_ || program::write_csv(program::source_of(execution_->program())) != text) {
            std::vector<std::string> warnings;
            install(compile(text, name, warnings), std::move(warnings));
        }
    } catch (const program::LoadError& e) {
        throw config::ConfigError(source + ": its program does not load on this CPU: " + e.problems.front());
    }
    if (!execution_->restore_state(std::vector<std::uint8_t>(state.begin(), state.end()))) execution_->restart();
}

}  // namespace slmp::station
