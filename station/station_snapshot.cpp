// Station snapshots: taking one, putting one back, and their file form
// (station/station_snapshot.hpp). Everything runs on the io_context thread
// between two requests, so a restore is atomic for every client.
#include "station/station_snapshot.hpp"

#include "station/cpu_program.hpp"
#include "station/frontend_state.hpp"

#include <cstring>
#include <fstream>
#include <iterator>

#include <spdlog/spdlog.h>

#include "config/config_error.hpp"
#include "devicemodel/byte_reader.hpp"
#include "devicemodel/snapshot.hpp"
#include "station/persistence.hpp"
#include "station/scan_loop.hpp"
#include "station/station.hpp"

namespace slmp::station {

using devicemodel::RestoreScope;
using devicemodel::SnapshotContents;

namespace {

std::vector<std::uint8_t> encode(const devicemodel::DeviceMemory& memory, std::string_view profile) {
    return devicemodel::encode_snapshot(memory, profile, SnapshotContents::WithSystem);
}

// An in-memory snapshot of this very station cannot be foreign; a file can.
void put_back(std::span<const std::uint8_t> bytes, devicemodel::DeviceMemory& memory, const devicemodel::Cpu& cpu,
              const std::string& what) {
    auto result = devicemodel::restore_snapshot(bytes, memory, cpu.profile().name, cpu.runtime().latch(), RestoreScope::All);
    if (!result.ok) throw config::ConfigError(what + " cannot be restored: " + result.error);
    for (const auto& w : result.warnings) spdlog::warn("snapshot: {}: {}", what, w);
}

CpuSnapshot take(devicemodel::Cpu& cpu) {
    CpuSnapshot s;
    const auto& profile = cpu.profile().name;
    s.memory = encode(cpu.memory(), profile);
    s.runtime = cpu.runtime();
    s.run_switch = cpu.runtime().operating_state().run_switch();
    for (const auto& [io, module] : cpu.modules()) s.modules[io] = encode(module->memory, profile);
    for (const auto& [number, memory] : cpu.networks()) s.networks[number] = encode(*memory, profile);
    if (auto* own = cpu.own_station_buffer()) s.station_buffer = encode(*own, profile);
    s.node = cpu.node();
    return s;
}

void give_back(const CpuSnapshot& s, devicemodel::Cpu& cpu, const std::string& name) {
    // Every stored value first, then the runtime that goes with them.
    put_back(s.memory, cpu.memory(), cpu, name);
    for (const auto& [io, bytes] : s.modules)
        if (auto* module = cpu.module(io)) put_back(bytes, module->memory, cpu, name + " module U" + std::to_string(io));
    for (const auto& [number, bytes] : s.networks)
        if (auto* memory = cpu.network(number)) put_back(bytes, *memory, cpu, name + " network " + std::to_string(number));
    if (auto* own = cpu.own_station_buffer(); own && !s.station_buffer.empty())
        put_back(s.station_buffer, *own, cpu, name + " station buffer");
    if (s.has_node) cpu.node() = s.node;
    if (s.has_runtime) cpu.runtime() = s.runtime;
    else cpu.runtime().set_switch(cpu.memory(), s.run_switch);
}

// ---- the file form ----

void put_blob(devicemodel::ByteWriter& w, const std::string& name, std::span<const std::uint8_t> bytes) {
    w.name(name);
    w.u32(static_cast<std::uint32_t>(bytes.size()));
    w.bytes(bytes);
}

constexpr char kFileMagic[8] = {'S', 'L', 'M', 'P', 'S', 'T', 'N', '1'};

}  // namespace

std::size_t StationSnapshot::memory_bytes() const {
    std::size_t n = 0;
    for (const auto& c : cpus) {
        n += c.memory.size() + c.station_buffer.size();
        for (const auto& [_, b] : c.modules) n += b.size();
        for (const auto& [_, b] : c.networks) n += b.size();
    }
    return n;
}

std::vector<std::uint8_t> encode_station_file(const StationSnapshot& snapshot) {
    std::vector<std::pair<std::string, const std::vector<std::uint8_t>*>> blobs;
    std::vector<std::uint8_t> switch_byte;
    for (std::size_t i = 0; i < snapshot.cpus.size(); ++i) {
        const auto& c = snapshot.cpus[i];
        auto prefix = i == 0 ? std::string() : "cpu" + std::to_string(i + 1) + " ";
        blobs.emplace_back("cpu" + std::to_string(i + 1), &c.memory);
        for (const auto& [io, b] : c.modules) blobs.emplace_back(prefix + "module " + std::to_string(io), &b);
        for (const auto& [number, b] : c.networks) blobs.emplace_back(prefix + "network " + std::to_string(number), &b);
        if (!c.station_buffer.empty()) blobs.emplace_back(prefix + "station buffer", &c.station_buffer);
    }
    if (!snapshot.cpus.empty())
        switch_byte.push_back(snapshot.cpus[0].run_switch == devicemodel::RunSwitch::Run ? 1 : 0);
    devicemodel::ByteWriter w;
    w.out.assign(std::begin(kFileMagic), std::end(kFileMagic));
    for (const auto& [name, bytes] : snapshot.units) blobs.emplace_back("unit " + name, &bytes);
    w.u32(static_cast<std::uint32_t>(blobs.size() + 1));   // the parts, then "switch"
    for (const auto& [name, bytes] : blobs) put_blob(w, name, *bytes);
    put_blob(w, "switch", switch_byte);
    return std::move(w.out);
}

StationSnapshot decode_station_file(std::span<const std::uint8_t> bytes, const std::string& source) {
    auto fail = [&](const std::string& why) -> config::ConfigError {
        return config::ConfigError(source + ": " + why + "; give a file saved by GET /api/snapshots/{name}/file");
    };
    devicemodel::ByteReader r(bytes);
    auto need = [&](auto value) {
        if (!value) throw fail("truncated station snapshot");
        return *value;
    };
    auto magic = need(r.bytes(sizeof kFileMagic));
    if (std::memcmp(magic.data(), kFileMagic, sizeof kFileMagic) != 0) throw fail("not a slmp-sim station snapshot (bad magic)");
    StationSnapshot snapshot;
    snapshot.has_scenarios = false;
    auto count = need(r.u32());
    for (std::uint32_t i = 0; i < count; ++i) {
        auto name = need(r.name());
        auto bytes_of_blob = need(r.bytes(need(r.u32())));
        std::vector<std::uint8_t> blob(bytes_of_blob.begin(), bytes_of_blob.end());
        if (name.rfind("unit ", 0) == 0) {
            snapshot.units[name.substr(5)] = std::move(blob);
            continue;
        }
        // "cpuN" opens CPU N; the names after it without a "cpuN " prefix are CPU No.1's.
        std::size_t cpu = 0;
        std::string rest = name;
        if (name.rfind("cpu", 0) == 0 && name.size() >= 4 && name[3] >= '1' && name[3] <= '4') {
            cpu = static_cast<std::size_t>(name[3] - '1');
            rest = name.size() > 5 ? name.substr(5) : std::string();
        }
        if (name == "switch") {
            if (!snapshot.cpus.empty() && blob.size() == 1)
                snapshot.cpus[0].run_switch = blob[0] ? devicemodel::RunSwitch::Run : devicemodel::RunSwitch::Stop;
            continue;
        }
        if (snapshot.cpus.size() <= cpu) snapshot.cpus.resize(cpu + 1);
        auto& c = snapshot.cpus[cpu];
        c.has_runtime = false;
        c.has_node = false;   // the file form carries no node (docs/nodes.md)
        if (rest.empty()) c.memory = std::move(blob);
        else if (rest.rfind("module ", 0) == 0) c.modules[static_cast<std::uint16_t>(std::stoul(rest.substr(7)))] = std::move(blob);
        else if (rest.rfind("network ", 0) == 0) c.networks[static_cast<std::uint16_t>(std::stoul(rest.substr(8)))] = std::move(blob);
        else if (rest == "station buffer") c.station_buffer = std::move(blob);
        else spdlog::warn("snapshot: {}: unknown part '{}' skipped", source, name);
    }
    if (!r.done()) throw fail("unexpected bytes after the last part");
    if (snapshot.cpus.empty() || snapshot.cpus[0].memory.empty()) throw fail("no device memory of CPU No.1 in it");
    return snapshot;
}

// ---- the station's part ----

std::vector<devicemodel::Cpu*> Station::all_cpus() {
    std::vector<devicemodel::Cpu*> cpus{&cpu_};
    for (auto& other : other_cpus_) cpus.push_back(other.get());
    return cpus;
}

StationSnapshot Station::snapshot() {
    catch_up();
    StationSnapshot s;
    for (auto* cpu : all_cpus()) s.cpus.push_back(take(*cpu));
    s.scenarios = scenario_.scenario_groups();
    s.units = take_units(frontends_);
    if (program_) s.units["program"] = program_->save();
    if (scan_) {
        s.clock = scan_->clock().now();
        s.has_clock = true;
    }
    s.taken = std::chrono::system_clock::now();
    return s;
}

void Station::restore(const StationSnapshot& s, bool drop_connections) {
    catch_up();
    TouchedAtExit touch_after{*this};
    auto cpus = all_cpus();
    if (s.cpus.size() > cpus.size())
        throw config::ConfigError("the snapshot holds " + std::to_string(s.cpus.size()) + " CPUs and this station " +
                                  std::to_string(cpus.size()) + "; restore it with the configuration it was taken with");
    // The front ends' state first: it is checked whole before anything changes.
    give_units(s.units, frontends_);
    if (auto part = s.units.find("program"); program_ && part != s.units.end()) program_->restore(part->second, "the snapshot");
    // The scenarios first: stopping one ends its power cut, which restarts sessions.
    if (s.has_scenarios) scenario_.replace_scenarios(s.scenarios);
    for (std::size_t i = 0; i < s.cpus.size(); ++i) give_back(s.cpus[i], *cpus[i], "CPU No." + std::to_string(i + 1));
    // A redundant pair's roles are the plant's, not the snapshot's: its SM/SD show them now.
    if (pair_) publish_pair_flags();
    if (scan_ && s.has_clock) scan_->set_time(s.clock);
    if (drop_connections) {
        std::vector<std::uint64_t> ids;
        for (const auto& [id, _] : activity_.connections()) ids.push_back(id);
        for (auto id : ids) activity_.close(id, "snapshot restored with drop_connections");
        if (transports_) transports_->restart_sessions();
    }
}

void Station::attach_frontends(FrontEnds frontends) {
    frontends_ = frontends;
    if (!persistence_) return;
    if (auto bytes = persistence_->load_units()) {
        const auto source = persistence_->units_file().string();
        give_units(decode_units(*bytes, source), frontends_);
        log_->info("state directory: restored the front ends' unit state from {}", source);
    }
    persistence_->units = [this]() -> std::optional<std::vector<std::uint8_t>> {
        auto parts = take_units(frontends_);
        if (parts.empty()) return std::nullopt;   // the front ends are gone (shutdown): keep the file
        return encode_units(parts);
    };
}

void Station::reset(bool drop_connections) {
    if (initial_) restore(*initial_, drop_connections);
}

void Station::take_initial_snapshot() {
    initial_ = std::make_unique<StationSnapshot>(snapshot());
    if (config_.snapshot_file.empty()) return;
    std::ifstream in(config_.snapshot_file, std::ios::binary);
    if (!in) throw config::ConfigError("--snapshot " + config_.snapshot_file + ": cannot be read; give a file saved "
                                       "by GET /api/snapshots/{name}/file");
    std::vector<std::uint8_t> bytes{std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
    restore(decode_station_file(bytes, config_.snapshot_file), false);
    log_->info("snapshot: started from {}", config_.snapshot_file);
}

}  // namespace slmp::station
