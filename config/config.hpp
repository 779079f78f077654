// Configuration: CPU profiles (config/profiles/*.json, compiled into the binary)
// and the server's JSON configuration file. Every error is a ConfigError whose
// message names the file, the key (as a JSON pointer) and the fix.
#pragma once

#include <cstdint>
#include <filesystem>
#include <optional>
#include <stdexcept>
#include <string>
#include <string_view>
#include <vector>

#include "devicemodel/cpu.hpp"
#include "devicemodel/cpu_profile.hpp"
#include "devicemodel/device_table.hpp"
#include "devicemodel/runtime_config.hpp"
#include "protocol/frame.hpp"
#include "protocol/peer.hpp"
#include "protocol/port_profile.hpp"
#include "config/config_error.hpp"
#include "config/timing_config.hpp"
#include "program/program.hpp"

namespace slmp::config {

// --- CPU profiles ----------------------------------------------------------
// Names of the profiles built into the binary ("R08CPU", "Q26UDEHCPU", ...).
std::vector<std::string> builtin_profile_names();
// One profile file: the CPU's own facts and what its SLMP port answers. A
// CPU model is still one file; the device model never sees the port's half.
// A behaviour where the manuals and real CPUs differ, and which of the two the
// profile follows (profile "manual_vs_hardware", docs/compatibility.md).
struct ManualVsHardware {
    std::string what;       // "1406 with word and bit blocks"
    std::string manual;     // what the manuals say
    std::string hardware;   // what a real CPU was seen to do
    bool follows_hardware = true;
};
struct Profile {
    devicemodel::CpuProfile cpu;
    protocol::PortProfile port;
    TimingModel timing;        // the response-time model's constants (docs/timing.md)
    std::string description;   // one line, for --list-profiles
    std::vector<ManualVsHardware> manual_vs_hardware;
};
// "iQ-R", "QnU", "L", "QJ71E71", "iQ-F": as profiles, logs and the API write it.
std::string_view family_name(devicemodel::Family family);
// A built-in profile by name (case-insensitive), or a profile JSON file by path
// (anything containing '/' or ending in ".json").
Profile load_profile(const std::string& name_or_path);
// Parses profile JSON text; `source` names it in error messages. A profile may
// "extends" a built-in one by name (a file may also extend a file, relative to
// `directory`) and give only what differs (profile_inheritance.cpp).
Profile parse_profile(const std::string& json_text, const std::string& source,
                      const std::filesystem::path& directory = {});

// --- Server configuration ----------------------------------------------------
enum class DataCode : std::uint8_t { Binary, Ascii, Auto };
using Transport = protocol::Transport;   // the port's transport (protocol/peer.hpp)

// "binary", "ascii" or "auto"; `where` names the option or key in the error.
DataCode parse_data_code(const std::string& text, const std::string& where);

// trace, debug, info, warn, error or off.
bool valid_log_level(const std::string& level);

struct PortConfig {
    Transport transport = Transport::Tcp;
    std::uint16_t port = 5000;             // 0: any free port (see ready_file)
    DataCode data_code = DataCode::Auto;
    // TCP clients at once; unset: the profile's "max_connections" (docs/configuration.md).
    std::optional<unsigned> max_connections = std::nullopt;
    unsigned idle_timeout_ms = 300000;     // TCP: close a silent connection; 0 = never
    // TCP: close a connection whose started frame is not whole this long after
    // its first byte, so half-frames cannot hold a connection slot; 0 = never.
    unsigned partial_frame_timeout_ms = 5000;
    unsigned max_connections_per_address = 0;   // TCP: clients from one IP address at once; 0 = no limit
    bool remote_password = true;           // the CPU's remote password (if any) locks this port's connections
    std::optional<bool> online_change = std::nullopt;   // writes served in RUN; unset: the profile's default
    // The station's network No. (1-239) and station No. (1-120) as set on the
    // real module; 0/0 = not set: only 00/FF addresses the own station.
    protocol::StationNumbers numbers{};
};
// Checks a network/station pair (both set or neither, in range); `where` names the key or option.
protocol::StationNumbers checked_station_numbers(unsigned network, unsigned station, const std::string& where);

struct InitialValue {
    devicemodel::DeviceAddress address;
    std::vector<std::uint32_t> values;     // consecutive devices from `address`
};

// An intelligent function module with buffer memory (U(io)\G, 0601/1601).
struct ModuleConfig {
    std::uint16_t io_number = 0;          // start I/O ÷ 16: "start_io": "0030" -> 3
    std::string model;
    std::uint32_t buffer_words = 0;
    std::uint32_t head_address = 0;       // 0601/1601 address of buffer word 0
};

// A network module whose link devices are reached as J(number)\X/Y/B/SB/W/SW.
// With `station`, the module is on that network as that station No., so
// requests routed through another station's module reach this CPU
// (docs/plants.md, "Networks and routes").
// One CPU of a redundant pair (docs/plants.md, "Redundant pairs"): the
// partner station's name and this CPU's system (A or B). System A is the
// control system at start; a system switch takes `switchover_ms` on the new
// control system's clock (given on either CPU, or the same on both; default 100).
// `tracking`: the device ranges the control system copies to the standby at
// each END (docs/plants.md, "Tracking"); empty: the default ranges.
struct RedundantConfig {
    std::string pair;
    char system = 'A';
    std::optional<double> switchover_ms;
    struct Range {
        const devicemodel::DeviceSpec* spec = nullptr;
        std::uint32_t first = 0;
        std::uint32_t count = 0;   // bit devices: a multiple of 16
        bool operator==(const Range&) const = default;
    };
    std::optional<std::vector<Range>> tracking;
};

// A multidrop station (docs/plants.md, "Multidrop stations"): behind the
// serial communication module at `start_io` of station `via`, multidrop No.
// `number` (0-31). Routes name it with module I/O start_io ÷ 16.
struct MultidropConfig {
    std::string via;
    std::uint16_t module_io = 0;   // start I/O ÷ 16: 0000-01FF
    std::uint8_t number = 0;
};

struct NetworkConfig {
    std::uint16_t number = 0;
    devicemodel::DeviceSizes sizes{};
    // 1-120, or 121-65534 on a network that numbers its stations past 120
    // (CC-Link IE TSN: reached only as station 7C of the station-number-
    // extended frame); 0: not set (the network's link devices only).
    std::uint16_t station = 0;
    bool master = false;        // the network's control/master station (routes 7D/7E)
    // What this station sends to the others at each link scan: ranges of its
    // LB/LW (J□\B, J□\W); by default 256 of each from (station − 1) × 256.
    struct Range {
        const devicemodel::DeviceSpec* spec = nullptr;   // B or W
        std::uint32_t first = 0;
        std::uint32_t count = 0;                          // B: a multiple of 16
    };
    std::vector<Range> send;
};

// A routing parameter, as GX Works sets it on a station (docs/plants.md,
// "Routing parameters"): to reach network `network`, this station passes a
// request to station `via_station` of its own network `via_network`. Without
// one for a network the way is derived from the plant's networks.
struct RouteConfig {
    std::uint16_t network = 0;       // transfer destination network No.
    std::uint16_t via_network = 0;   // relay destination network No. (one this station is on)
    std::uint16_t via_station = 0;   // relay destination station No. on it
};

// Node search by broadcast (docs/nodes.md, "Node search over UDP"): a UDP
// port shared by every node station of the host (SO_REUSEADDR), bound to the
// broadcast address of the station's bind address, on which 0E30 is answered
// after a random 0..max_delay_ms wait on the station's clock.
struct NodeSearchConfig {
    std::uint16_t port = 0;               // 0: no broadcast search port
    std::uint32_t max_delay_ms = 1500;    // the manual's 0-1500 ms
};

// CPU No.2–4 of a multi-CPU system (module I/O 03E1–03E3).
struct CpuConfig {
    int number = 2;
    std::string profile;
    std::vector<std::pair<devicemodel::Area, std::uint32_t>> device_sizes;
    std::vector<InitialValue> devices;
};

// The HTTP control API, metrics and web monitor (docs/api.md).
struct HttpConfig {
    bool enabled = true;
    std::uint16_t port = 8080;             // 0: any free port (see ready_file)
    std::string bind;                      // empty: the SLMP bind address
};

// The running CPU ("cpu" key; docs/cpu-runtime.md). The key lists name each
// timer/counter/latch entry's JSON pointer for messages at validation time.
// The user's PLC program ("cpu": {"program": ...}, --program; docs/program.md).
struct ProgramConfig {
    std::string file;        // empty: the CPU runs no program
    std::string comments;    // device comments (optional)
    program::ProgramOptions options;
};

struct CpuRuntimeConfig {
    devicemodel::RuntimeConfig runtime;
    ProgramConfig program;
    std::vector<std::string> timer_keys, counter_keys, latch_keys;
};

// The state directory: device memory saved atomically and restored at start.
struct PersistenceConfig {
    std::string state_dir;                 // empty: nothing touches disk
    double snapshot_interval_s = 0;        // 0: only at shutdown and on SIGUSR1
    bool restore_all = false;              // false: only latched devices come back (a power cycle)
};

// Global labels as declared (docs/labels.md): a "labels" and a "structures"
// section, a --labels file (the same JSON, or a GX Works3 CSV list). Kept as
// text until declare_labels() builds the CPU's LabelTable against its device
// sizes; `where` prefixes say which file and JSON pointer (or CSV line) an
// error is about, e.g. "labels.json: /labels/2".
struct LabelMemberEntry {
    std::string name, type;
    std::vector<std::uint32_t> dims;
    std::string where;
};
struct StructureEntry {
    std::string name;
    std::vector<LabelMemberEntry> members;
    std::string where;
};
struct LabelEntry {
    std::string name, type, device;
    std::vector<std::uint32_t> dims;
    bool external = true;                  // "Access from External Device": on unless declared off
    std::string where;                     // the entry
    std::string type_key = "/type", device_key = "/device";   // appended to `where` (CSV: column names)
};
struct LabelsConfig {
    std::vector<StructureEntry> structures;
    std::vector<LabelEntry> labels;
};

// A file drive served from a host folder or with other limits ("drives" key,
// --drive N=DIR; docs/files.md). Unset values keep the family's defaults.
struct DriveConfig {
    std::uint16_t number = 0;
    std::string dir;                       // empty: in memory (or <state-dir>/drives/<n>)
    std::optional<std::uint64_t> capacity;
    std::optional<bool> write_protect;     // the SD card's LOCK switch
    std::optional<bool> present;
    std::vector<std::pair<std::string, std::string>> passwords;   // file name -> file password
    std::string where;                     // the key or option, for messages
};

struct ServerConfig {
    std::string name;                      // the station's name in a plant (docs/plants.md); empty: one station
    std::string profile = "R08CPU";
    std::string bind = "0.0.0.0";
    std::vector<PortConfig> ports = {{Transport::Tcp, 5000}, {Transport::Udp, 5000}};
    std::size_t max_request_bytes = 8192;
    std::vector<std::pair<devicemodel::Area, std::uint32_t>> device_sizes;   // overrides of the profile's sizes
    std::vector<InitialValue> devices;
    std::string log_level = "info";
    std::string ready_file;                // written with the bound ports once listening
    HttpConfig http;
    std::vector<ModuleConfig> modules;     // on CPU No.1
    std::vector<NetworkConfig> networks;   // on CPU No.1
    std::vector<RouteConfig> routes;       // routing parameters given by hand (the rest derived)
    NodeSearchConfig node_search;          // node search by broadcast
    std::vector<CpuConfig> cpus;           // CPU No.2–4
    std::optional<RedundantConfig> redundant;   // one CPU of a redundant pair
    std::optional<MultidropConfig> multidrop;   // a multidrop station behind another's serial module
    CpuRuntimeConfig cpu;                  // CPU No.1's runtime parameters
    PersistenceConfig persistence;
    std::vector<std::string> scenarios;    // "scenarios" and --scenario files, run together (docs/scenarios.md)
    std::string record_file;               // --record: every request and response as JSON lines
    std::string record_pcap_file;          // --record-pcap: the same as a pcap capture for Wireshark
    double clock_speed = 1;                // the CPU's clock runs this many times faster than the host's
    bool clock_frozen = false;             // --clock frozen: no scan until POST /api/clock/step or PUT /api/clock
    std::string snapshot_file;             // --snapshot: start from a station snapshot saved to a file (docs/ci.md)
    LabelsConfig labels;                   // "labels", "structures", --labels files
    std::vector<DriveConfig> drives;       // "drives", --drive: file drives of CPU No.1 (docs/files.md)
    TimingConfig timing;                   // "timing", --timing: when answers leave (docs/timing.md)
    // Proxy mode (docs/twin.md, "Proxy"): every SLMP request goes on to this
    // "HOST:PORT" over TCP and its answer comes back; empty: served here.
    std::string upstream;
    unsigned upstream_timeout_ms = 3000;   // the upstream's answer must come within this (else CF71)
    // Differential mode (docs/twin.md, "Compare"): with an upstream, each
    // request is also served here, from this station's own memory and
    // profile, and every difference between the two answers is reported; the
    // client gets the upstream's. Answer times further apart than twice the
    // shorter plus this slack are a difference.
    bool compare = false;
    unsigned compare_slack_ms = 50;
};
inline constexpr double kMinClockSpeed = 0.01, kMaxClockSpeed = 1000;
inline constexpr const char* kClockSpeedFix = "use a factor from 0.01 to 1000 (default 1: real time)";

// "HOST:PORT" of "upstream" / --upstream, split; throws ConfigError naming
// `where` and the form when the text is not one ("[::1]:5000" for IPv6).
struct UpstreamAddress {
    std::string host;
    std::uint16_t port = 0;
    std::string text() const;   // "HOST:PORT" again, for logs
};
std::optional<UpstreamAddress> split_upstream(std::string_view text);
UpstreamAddress parse_upstream(std::string_view text, std::string_view where);
inline constexpr const char* kUpstreamFix = "give the upstream PLC's address and SLMP TCP port as HOST:PORT, e.g. 192.168.3.39:5000";

// Reads a configuration file; keys left out keep the defaults above.
ServerConfig load_server_config(const std::filesystem::path& file);
ServerConfig parse_server_config(const std::string& json_text, const std::string& source);
// The whole file as text; throws ConfigError naming the path when it cannot be read.
std::string read_config_file(const std::filesystem::path& file);

// A --labels file: JSON with "labels" and/or "structures" (like the
// configuration's sections), or a CSV global-label list (name ends in .csv).
LabelsConfig load_labels_file(const std::filesystem::path& file);
// Declares the labels on CPU No.1: types, devices (kind, range, overlap), the
// label area. Throws ConfigError naming the file, the key and the fix.
void declare_labels(devicemodel::Cpu& cpu, const LabelsConfig& labels);

// Gives CPU No.1 its file drives: the family's table, the "drives" / --drive
// folders, <state-dir>/drives/<n> when a state directory is set. Throws
// ConfigError naming the key and the fix (unknown drive, folder missing).
void attach_drives(devicemodel::Cpu& cpu, const ServerConfig& config);

// The profile named by the configuration, with its device-size overrides applied.
Profile resolve_profile(const ServerConfig& config);
// Writes the configured initial device values into a CPU (checked against its sizes).
void apply_initial_values(devicemodel::Cpu& cpu, const ServerConfig& config);
void apply_initial_values(devicemodel::Cpu& cpu, const std::vector<InitialValue>& values);
// Adds the configured modules and networks to CPU No.1.
void attach_hardware(devicemodel::Cpu& cpu, const ServerConfig& config);
// The profile of CPU No.2–4, with its size overrides.
Profile resolve_profile(const CpuConfig& cpu);
// The "cpu" parameters checked against the CPU's profile (device sizes, the
// family's password length rule); throws ConfigError naming the key and the fix.
devicemodel::RuntimeConfig checked_runtime_config(const CpuRuntimeConfig& cpu, const devicemodel::CpuProfile& profile);
// "RUN" or "STOP" (any case); `where` names the option or key in the error.
devicemodel::RunSwitch parse_run_switch(const std::string& text, const std::string& where);

}  // namespace slmp::config
