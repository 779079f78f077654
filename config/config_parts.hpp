// Pieces of the configuration parser shared by its files (not for other modules).
#pragma once

#include <filesystem>
#include <string>
#include <utility>
#include <vector>

#include "config/builtin_profiles.hpp"
#include "config/config.hpp"
#include "config/json_path.hpp"

namespace slmp::config {

// Where a profile's JSON came from: its name in messages, and for a file the
// folder a relative "extends" is resolved against (empty for built-in ones).
struct ProfileSource {
    std::string name;
    std::filesystem::path directory;
};
// A built-in profile by name, case-insensitive (null when none has it), and
// their names as "FX5U-32MR, L26CPU-BT, ..." for messages (profile_loader.cpp).
const BuiltinProfile* find_builtin_profile(const std::string& name);
std::string builtin_profile_list();
// The profile's JSON with its "extends" chain resolved (profile_inheritance.cpp).
nlohmann::json resolve_profile_json(const std::string& json_text, const ProfileSource& source);

// One station's keys (docs/configuration.md); `directory` resolves relative
// "scenarios" and label CSV names. A plant gives each station its merged keys.
ServerConfig parse_server_config(const JsonAt& root, const std::filesystem::path& directory);
// A station's "name": 1-64 of [A-Za-z0-9._-], as URLs and metrics labels take it.
std::string checked_station_name(const JsonAt& at);

std::vector<std::pair<devicemodel::Area, std::uint32_t>> parse_device_sizes(const JsonAt& sizes);
std::vector<InitialValue> parse_initial_values(const JsonAt& devices);
// One entry of such an object: "D100": 5 (also used by scenarios' "set", which
// lets labels sit beside devices).
InitialValue parse_initial_value(const std::string& address, const JsonAt& at);
// "modules", "networks" and "cpus" (hardware_config.cpp).
void parse_hardware(const JsonAt& root, ServerConfig& config);
// "cpu", "state_dir", "snapshot_interval_s", "restore" (cpu_config.cpp).
void parse_cpu_runtime(const JsonAt& root, ServerConfig& config);
// "labels" (a list, or the name of a CSV file) and "structures" (label_config.cpp);
// `directory` is where a relative CSV name is looked for.
void parse_labels(const JsonAt& root, const std::filesystem::path& directory, LabelsConfig& labels);
// A GX Works3 global-label list exported as CSV (label_csv.cpp).
LabelsConfig parse_labels_csv(const std::string& text, const std::string& source);

}  // namespace slmp::config
