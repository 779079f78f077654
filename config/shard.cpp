// Rendezvous hashing of station names over shards (docs/plants.md, "Shards").
#include "config/shard.hpp"

#include <cctype>

#include "config/config_error.hpp"
#include "config/plant_config.hpp"

namespace slmp::config {

namespace {

std::uint64_t fnv1a(std::string_view text) {
    std::uint64_t hash = 0xcbf29ce484222325ULL;
    for (unsigned char ch : text) hash = (hash ^ ch) * 0x100000001b3ULL;
    return hash;
}

// splitmix64's finalizer: every input bit reaches every output bit, so the
// scores of one name for two shards are unrelated.
std::uint64_t mix(std::uint64_t z) {
    z = (z ^ (z >> 30)) * 0xbf58476d1ce4e5b9ULL;
    z = (z ^ (z >> 27)) * 0x94d049bb133111ebULL;
    return z ^ (z >> 31);
}

unsigned whole_number(const std::string& text, const std::string& what) {
    if (text.empty() || text.size() > 6)
        throw ConfigError("--shard " + what + ": '" + text + "' is not a number; write --shard K/N, e.g. --shard 3/10");
    unsigned value = 0;
    for (char ch : text) {
        if (!std::isdigit(static_cast<unsigned char>(ch)))
            throw ConfigError("--shard " + what + ": '" + text + "' is not a number; write --shard K/N, e.g. --shard 3/10");
        value = value * 10 + static_cast<unsigned>(ch - '0');
    }
    return value;
}

}  // namespace

std::uint64_t shard_score(std::string_view name, unsigned shard) {
    return mix(fnv1a(name) ^ (0x9e3779b97f4a7c15ULL * (static_cast<std::uint64_t>(shard) + 1)));
}

unsigned shard_of(std::string_view name, unsigned shards) {
    unsigned best = 0;
    std::uint64_t best_score = shard_score(name, 0);
    for (unsigned k = 1; k < shards; ++k)
        if (auto score = shard_score(name, k); score > best_score) {
            best = k;
            best_score = score;
        }
    return best;
}

ShardOption parse_shard_option(const std::string& text) {
    ShardOption option;
    auto slash = text.find('/');
    auto index = text.substr(0, slash);
    if (index != "auto") option.index = whole_number(index, "index");
    if (slash != std::string::npos) {
        option.count = whole_number(text.substr(slash + 1), "count");
        if (*option.count == 0) throw ConfigError("--shard " + text + ": a plant has at least 1 shard");
    }
    return option;
}

unsigned ordinal_of_host_name(const std::string& host_name) {
    auto dash = host_name.rfind('-');
    auto digits = dash == std::string::npos ? std::string() : host_name.substr(dash + 1);
    bool numeric = !digits.empty() && digits.size() <= 6;
    for (char ch : digits) numeric = numeric && std::isdigit(static_cast<unsigned char>(ch));
    if (!numeric)
        throw ConfigError("--shard auto: the host name '" + host_name + "' does not end in '-<number>' (a StatefulSet "
                          "pod's ordinal, as in slmp-plant-3); give the shard explicitly: --shard K/N");
    return whole_number(digits, "index");
}

std::string shard_host(const std::string& pattern, unsigned shard) {
    std::string out = pattern;
    for (std::size_t at; (at = out.find("{shard}")) != std::string::npos;) out.replace(at, 7, std::to_string(shard));
    return out;
}

void select_shard(PlantConfig& plant, unsigned index, unsigned count) {
    if (index >= count)
        throw ConfigError("--shard " + std::to_string(index) + "/" + std::to_string(count) + ": shards are numbered 0 to " +
                          std::to_string(count - 1));
    plant.layout.index = index;
    plant.layout.count = count;
    plant.layout.stations.clear();
    std::vector<StationConfig> mine;
    for (auto& station : plant.stations) {
        const auto& server = station.server;
        PlantStation entry{server.name, shard_of(server.name, count), server.bind, {}, {}};
        for (const auto& port : server.ports) {
            if (count > 1 && port.port == 0)
                throw ConfigError("station '" + server.name + "': port 0 (any free port) in a plant of " +
                                  std::to_string(count) + " shards; give each station a fixed port (\"tcp_port\": "
                                  "\"20000+i\"): clients find a station on any shard by it");
            (port.transport == Transport::Tcp ? entry.tcp : entry.udp).push_back(port.port);
        }
        if (entry.shard == index) mine.push_back(std::move(station));
        plant.layout.stations.push_back(std::move(entry));
    }
    if (mine.empty())
        throw ConfigError("shard " + std::to_string(index) + " of " + std::to_string(count) + " serves none of the " +
                          std::to_string(plant.stations.size()) + " stations; use fewer shards");
    plant.stations = std::move(mine);
}

}  // namespace slmp::config
