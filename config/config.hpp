// Configuration: CPU profiles (config/profiles/*.json, compiled into the binary)
// and the server's JSON configuration file. Every error is a ConfigError whose
// message names the file, the key (as a JSON pointer) and the fix.
#pragma once

#include <cstdint>
#include <filesystem>
#include <stdexcept>
#include <string>
#include <vector>

#include "devicemodel/cpu.hpp"
#include "devicemodel/cpu_profile.hpp"
#include "devicemodel/device_table.hpp"

namespace slmp::config {

struct ConfigError : std::runtime_error {
    using std::runtime_error::runtime_error;
};

// --- CPU profiles ----------------------------------------------------------
// Names of the profiles built into the binary ("R08CPU", "Q26UDEHCPU", ...).
std::vector<std::string> builtin_profile_names();
// A built-in profile by name (case-insensitive), or a profile JSON file by path
// (anything containing '/' or ending in ".json").
devicemodel::CpuProfile load_profile(const std::string& name_or_path);
// Parses profile JSON text; `source` names it in error messages.
devicemodel::CpuProfile parse_profile(const std::string& json_text, const std::string& source);

// --- Server configuration ----------------------------------------------------
enum class DataCode : std::uint8_t { Binary, Ascii, Auto };
enum class Transport : std::uint8_t { Tcp, Udp };

// "binary", "ascii" or "auto"; `where` names the option or key in the error.
DataCode parse_data_code(const std::string& text, const std::string& where);

struct PortConfig {
    Transport transport = Transport::Tcp;
    std::uint16_t port = 5000;             // 0: any free port (see ready_file)
    DataCode data_code = DataCode::Auto;
    unsigned max_connections = 64;         // TCP: 1 reproduces an iQ-R built-in port
    unsigned idle_timeout_ms = 300000;     // TCP: close a silent connection; 0 = never
};

struct InitialValue {
    devicemodel::DeviceAddress address;
    std::vector<std::uint32_t> values;     // consecutive devices from `address`
};

struct ServerConfig {
    std::string profile = "R08CPU";
    std::string bind = "0.0.0.0";
    std::vector<PortConfig> ports = {{Transport::Tcp, 5000}, {Transport::Udp, 5000}};
    std::size_t max_request_bytes = 8192;
    std::vector<std::pair<devicemodel::Area, std::uint32_t>> device_sizes;   // overrides of the profile's sizes
    std::vector<InitialValue> devices;
    std::string log_level = "info";
    std::string ready_file;                // written with the bound ports once listening
};

// Reads a configuration file; keys left out keep the defaults above.
ServerConfig load_server_config(const std::filesystem::path& file);
ServerConfig parse_server_config(const std::string& json_text, const std::string& source);

// The profile named by the configuration, with its device-size overrides applied.
devicemodel::CpuProfile resolve_profile(const ServerConfig& config);
// Writes the configured initial device values into a CPU (checked against its sizes).
void apply_initial_values(devicemodel::Cpu& cpu, const ServerConfig& config);

}  // namespace slmp::config
