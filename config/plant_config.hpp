// A configuration file as stations: one station (the keys of
// docs/configuration.md), or a plant of many ("stations", docs/plants.md).
// A plant's top-level keys are every station's defaults; a station's own key
// replaces the default whole. Template entries expand to `count` stations
// with {i} placeholders in their strings and "20000+i" port expressions.
#pragma once

#include <cstdint>
#include <filesystem>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "config/config.hpp"
#include "config/frontend_config.hpp"

namespace slmp::config {

struct StationConfig {
    ServerConfig server;          // its name, profile, ports, bind, state directory, ...
    FrontEndsConfig frontends;    // its kind and host-link / JW-51CM ports
};

// One station of the whole plant as GET /api/plant shows it: who serves it and
// where a client reaches it (its configured ports).
struct PlantStation {
    std::string name;
    unsigned shard = 0;
    std::string bind;
    std::vector<std::uint16_t> tcp, udp;
};

// How the plant is split over processes (config/shard.hpp, docs/plants.md "Shards").
struct ShardLayout {
    unsigned count = 1;           // processes serving the plant (--shard K/N)
    unsigned index = 0;           // this one's
    unsigned file_count = 1;      // the file's "shards": N for --shard K and --shard auto, and the manifests' replicas
    std::string host_pattern;     // "shard_host": the DNS name of shard {shard} ("slmp-plant-{shard}.slmp-plant")
    std::vector<PlantStation> stations;   // every station of the file, in its order (select_shard fills it)
};

struct PlantConfig {
    bool plant = false;           // the file has "stations" (names are shown, routes and metrics carry them)
    unsigned threads = 0;         // "threads"; 0: --threads or the machine's cores
    std::vector<StationConfig> stations;   // one or more, names unique: the ones this process serves
    ShardLayout layout;
    std::string metrics_by = "auto";   // "metrics_by": the plant's /metrics per station or per profile
};

// A file with or without "stations". Throws ConfigError naming the file, the
// station, the key and the fix. `profile`: --profile, which replaces a
// one-station file's "profile" before its addresses are read (an FX5 reads
// X/Y in octal).
PlantConfig load_plant_config(const std::filesystem::path& file, const std::string& profile = {});
PlantConfig parse_plant_config(const std::string& json_text, const std::string& source,
                               const std::filesystem::path& directory, const std::string& profile = {});

// The placeholders of a template's strings, for station i: "{i}", "{i:03}"
// (zero-padded to 3 digits), "{i+100}", "{2*i+1}". Throws ConfigError (with
// `where`) for a brace that holds no such expression.
std::string expand_placeholders(const std::string& text, long i, const std::string& where);
// An integer expression in i: digits, i, + - * and parentheses ("20000+2*i").
// Returns false when `text` is not one.
bool evaluate_index_expression(const std::string& text, long i, long* value);

}  // namespace slmp::config
