// Which process of a sharded plant serves which station (docs/plants.md,
// "Shards"): one plant file, N processes, `--shard K/N` on each. A station's
// shard is chosen by rendezvous hashing of its name, so it depends on the name
// and N alone — never on the file's order or on the other stations — and when N
// grows by one, only the stations the new shard wins move (about 1/(N+1)).
#pragma once

#include <cstdint>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace slmp::config {

struct PlantConfig;

// The shard (0..shards-1) that serves the station `name`: the one with the
// highest shard_score. The Python generator (deploy/k8s/render_shards.py)
// computes the same.
unsigned shard_of(std::string_view name, unsigned shards);
std::uint64_t shard_score(std::string_view name, unsigned shard);

// What --shard says: "K/N", "K" (N from the file's "shards"), "auto" or
// "auto/N" (K from the host name's trailing "-K": a StatefulSet pod's ordinal).
struct ShardOption {
    std::optional<unsigned> index;   // unset: from the host name
    std::optional<unsigned> count;   // unset: the file's "shards"
};
ShardOption parse_shard_option(const std::string& text);
// "slmp-plant-3" -> 3; throws ConfigError when the name ends in no "-<digits>".
unsigned ordinal_of_host_name(const std::string& host_name);
// "slmp-plant-{shard}.slmp-plant" -> "slmp-plant-3.slmp-plant".
std::string shard_host(const std::string& pattern, unsigned shard);

// Keeps the plant's stations that shard `index` of `count` serves and records
// every station's shard in plant.layout (GET /api/plant). With count > 1 each
// SLMP port must be fixed (not 0): a client finds a station on any shard by it.
// Throws ConfigError naming the fix.
void select_shard(PlantConfig& plant, unsigned index, unsigned count);

}  // namespace slmp::config
