// Reading a plant: defaults, stations, templates (docs/plants.md).
#include "config/plant_config.hpp"

#include <algorithm>
#include <cctype>
#include <fstream>
#include <map>
#include <set>

#include "config/config_parts.hpp"
#include "config/json_path.hpp"
#include "config/settings.hpp"
#include "config/station_pattern.hpp"

namespace slmp::config {

namespace {

// Keys that belong to the whole process, not to one station.
constexpr const char* kPlantWideKeys[] = {"http", "log_level", "threads", "stations", "shards", "shard_host", "metrics_by"};

// digits, i, + - * and parentheses; nothing else.
class IndexExpression {
public:
    IndexExpression(const std::string& text, long i) : text_(text), i_(i) {}
    bool evaluate(long* value) {
        long v = sum();
        skip_spaces();
        if (!ok_ || pos_ != text_.size()) return false;
        *value = v;
        return true;
    }

private:
    void skip_spaces() {
        while (pos_ < text_.size() && text_[pos_] == ' ') ++pos_;
    }
    bool next_is(char ch) {
        skip_spaces();
        if (pos_ < text_.size() && text_[pos_] == ch) {
            ++pos_;
            return true;
        }
        return false;
    }
    long primary() {
        if (next_is('(')) {
            long v = sum();
            if (!next_is(')')) ok_ = false;
            return v;
        }
        if (next_is('i')) return i_;
        if (next_is('-')) return -primary();
        long v = 0;
        std::size_t digits = 0;
        while (pos_ < text_.size() && std::isdigit(static_cast<unsigned char>(text_[pos_])) && digits < 10) {
            v = v * 10 + (text_[pos_++] - '0');
            ++digits;
        }
        if (digits == 0 || digits == 10) ok_ = false;
        return v;
    }
    long product() {
        long v = primary();
        while (ok_ && next_is('*')) v *= primary();
        return v;
    }
    long sum() {
        long v = product();
        while (ok_) {
            if (next_is('+')) v += product();
            else if (next_is('-')) v -= product();
            else break;
        }
        return v;
    }

    const std::string& text_;
    long i_;
    std::size_t pos_ = 0;
    bool ok_ = true;
};

nlohmann::json expanded(const nlohmann::json& value, long i, const std::string& where) {
    if (value.is_string()) return expand_placeholders(value.get<std::string>(), i, where);
    if (value.is_array() || value.is_object()) {
        auto copy = value;
        for (auto& item : copy) item = expanded(item, i, where);
        return copy;
    }
    return value;
}

// "tcp_port": "20000+i" and the "port" of each "ports" entry: numbers for the parser.
void resolve_port_expressions(nlohmann::json& station, const long* i, const std::string& where) {
    auto resolve = [&](nlohmann::json& value, const std::string& key) {
        if (!value.is_string()) return;
        auto text = value.get<std::string>();
        long number = 0;
        if (!i || !evaluate_index_expression(text, *i, &number))
            throw ConfigError(where + ": /" + key + ": '" + text + "' is not a port number" +
                              (i ? "; write a number or an expression in i such as \"20000+i\""
                                 : "; an expression in i needs a template entry (\"template\", \"count\"): write a number"));
        if (number < 0 || number > 65535)
            throw ConfigError(where + ": /" + key + ": '" + text + "' gives port " + std::to_string(number) + " for i = " +
                              std::to_string(*i) + "; keep every station's port within 0-65535");
        value = number;
    };
    for (const char* key : {"tcp_port", "udp_port"})
        if (station.contains(key)) resolve(station[key], key);
    if (station.contains("ports") && station["ports"].is_array())
        for (std::size_t k = 0; k < station["ports"].size(); ++k)
            if (station["ports"][k].is_object() && station["ports"][k].contains("port"))
                resolve(station["ports"][k]["port"], "ports/" + std::to_string(k) + "/port");
}

bool is_melsec(const nlohmann::json& station) {
    return !station.contains("kind") || station["kind"] == "melsec";
}

class PlantReader {
public:
    PlantReader(const nlohmann::json& root, std::string source, std::filesystem::path directory)
        : source_(std::move(source)), directory_(std::move(directory)) {
        defaults_ = root;
        // The plant's own keys (its rows) are no station's default; nor is a name.
        for (auto key : section_keys(Section::Plant)) defaults_.erase(std::string(key));
        defaults_.erase("name");
    }

    // One station entry (a template's already expanded); `i` is its template index.
    void add(const nlohmann::json& entry, std::size_t position, const long* i, const std::string& entry_where) {
        for (const char* key : kPlantWideKeys)
            if (entry.contains(key))
                throw ConfigError(entry_where + ": /" + key + ": \"" + key +
                                  "\" is plant-wide; move it to the top level of the file");
        auto merged = defaults_;
        // A station's own ports (or kind without SLMP ports) replace the default ports whole.
        if (entry.contains("ports") || entry.contains("tcp_port") || entry.contains("udp_port") || !is_melsec(entry))
            for (const char* key : {"ports", "tcp_port", "udp_port"}) merged.erase(key);
        for (const auto& [key, value] : entry.items()) merged[key] = value;
        if (!merged.contains("name"))
            merged["name"] = i ? "station-" + std::to_string(*i) : "station-" + std::to_string(position);
        auto name = merged["name"].is_string() ? merged["name"].get<std::string>() : std::string();
        // The plant's state directory is shared: each station keeps its own folder in it.
        if (defaults_.contains("state_dir") && defaults_["state_dir"].is_string() && !entry.contains("state_dir"))
            merged["state_dir"] = (std::filesystem::path(defaults_["state_dir"].get<std::string>()) / name).string();
        auto where = source_ + ", station '" + name + "'";
        resolve_port_expressions(merged, i, where);
        JsonAt at(merged, where);
        StationConfig station{parse_server_config(at, directory_), parse_frontends_config(at)};
        if (station.frontends.kind != StationKind::Melsec) station.server.ports.clear();
        check_unique(station, where);
        stations_.push_back(std::move(station));
    }

    std::vector<StationConfig> take() {
        check_pairs();
        check_routes();
        return std::move(stations_);
    }

private:
    void check_unique(const StationConfig& station, const std::string& where) {
        const auto& name = station.server.name;
        if (auto [it, fresh] = names_.emplace(name, where); !fresh)
            throw ConfigError(where + ": the name '" + name + "' is taken by another station; give each station its "
                              "own \"name\" (a template: \"name\": \"press-{i}\")");
        for (const auto& port : station.server.ports) {
            if (port.port == 0) continue;
            auto key = station.server.bind + (port.transport == Transport::Tcp ? " TCP " : " UDP ") +
                       std::to_string(port.port);
            if (auto [it, fresh] = ports_.emplace(key, name); !fresh)
                throw ConfigError(where + ": stations '" + it->second + "' and '" + name + "' both listen on " + key +
                                  "; give each station its own port (\"tcp_port\": \"20000+i\") or bind address "
                                  "(\"bind\": \"127.0.1.{i}\")");
        }
        // A network's station Nos. and its master are one each (docs/plants.md, "Networks and routes").
        for (const auto& n : station.server.networks) {
            if (n.station == 0) continue;
            const auto key = std::to_string(n.number) + "/" + std::to_string(n.station);
            if (auto [it, fresh] = network_stations_.emplace(key, name); !fresh)
                throw ConfigError(where + ": stations '" + it->second + "' and '" + name + "' are both station No. " +
                                  std::to_string(n.station) + " of network " + std::to_string(n.number) +
                                  "; give each station of a network its own \"station\"");
            if (!n.master) continue;
            if (auto [it, fresh] = masters_.emplace(n.number, name); !fresh)
                throw ConfigError(where + ": stations '" + it->second + "' and '" + name + "' are both the master of network " +
                                  std::to_string(n.number) + "; mark one with \"master\": true");
        }
    }

    // Redundant pairs and multidrop stations name other stations (docs/plants.md):
    // a pair is two CPUs, one system A and one system B, each naming the other
    // or only one naming its partner; a multidrop station hangs on a station
    // of the plant.
    void check_pairs() {
        std::map<std::string, const StationConfig*> by_name;
        for (const auto& s : stations_) by_name[s.server.name] = &s;
        auto where = [&](const std::string& name) { return source_ + ", station '" + name + "'"; };
        for (const auto& s : stations_) {
            const auto& name = s.server.name;
            if (const auto& m = s.server.multidrop) {
                if (m->via == name) throw ConfigError(where(name) + ": /multidrop/via: a station cannot hang on itself; name the station with the serial module");
                if (!by_name.contains(m->via))
                    throw ConfigError(where(name) + ": /multidrop/via: no station is named '" + m->via + "'");
            }
            const auto& r = s.server.redundant;
            if (!r) continue;
            if (r->pair == name) throw ConfigError(where(name) + ": /redundant/pair: a station cannot pair with itself; name the other CPU");
            auto other = by_name.find(r->pair);
            if (other == by_name.end()) throw ConfigError(where(name) + ": /redundant/pair: no station is named '" + r->pair + "'");
            const auto& o = other->second->server.redundant;
            if (o && o->pair != name)
                throw ConfigError(where(name) + ": /redundant/pair: '" + r->pair + "' is paired with '" + o->pair +
                                  "'; a CPU is in one pair");
            if (o && o->system == r->system)
                throw ConfigError(where(name) + ": /redundant/system: '" + name + "' and '" + r->pair + "' are both system " +
                                  std::string(1, r->system) + "; make one \"A\" and the other \"B\"");
            if (o && o->switchover_ms && r->switchover_ms && *o->switchover_ms != *r->switchover_ms)
                throw ConfigError(where(name) + ": /redundant/switchover_ms: '" + name + "' and '" + r->pair +
                                  "' give different switch times; give it once, or the same on both");
            if (o && o->tracking && r->tracking && *o->tracking != *r->tracking)
                throw ConfigError(where(name) + ": /redundant/tracking: '" + name + "' and '" + r->pair +
                                  "' track different ranges; give them once, or the same on both");
            for (const auto& t : stations_)   // a third station naming either as its partner
                if (&t != &s && &t != other->second && t.server.redundant &&
                    (t.server.redundant->pair == name || t.server.redundant->pair == r->pair))
                    throw ConfigError(where(t.server.name) + ": /redundant/pair: '" + t.server.redundant->pair +
                                      "' is in the pair of '" + name + "' and '" + r->pair + "' already; a CPU is in one pair");
        }
    }

    // A routing parameter's relay destination is a station of the plant on
    // that network (docs/plants.md, "Routing parameters").
    void check_routes() const {
        for (const auto& s : stations_)
            for (std::size_t i = 0; i < s.server.routes.size(); ++i) {
                const auto& r = s.server.routes[i];
                const auto key = std::to_string(r.via_network) + "/" + std::to_string(r.via_station);
                const auto relay = network_stations_.find(key);
                const auto where = source_ + ", station '" + s.server.name + "': /routes/" + std::to_string(i);
                if (relay == network_stations_.end())
                    throw ConfigError(where + "/via_station: network " + std::to_string(r.via_network) + " has no station No. " +
                                      std::to_string(r.via_station) + "; name a station of the plant on it");
                if (relay->second == s.server.name)
                    throw ConfigError(where + "/via_station: station No. " + std::to_string(r.via_station) + " of network " +
                                      std::to_string(r.via_network) + " is this station; name the relay station");
            }
    }

    std::string source_;
    std::filesystem::path directory_;
    nlohmann::json defaults_;
    std::vector<StationConfig> stations_;
    std::map<std::string, std::string> names_;
    std::map<std::string, std::string> ports_;   // "bind TCP port" -> station name
    std::map<std::string, std::string> network_stations_;   // "network/station" -> station name
    std::map<std::uint16_t, std::string> masters_;          // network -> its master station's name
};


}  // namespace

bool evaluate_index_expression(const std::string& text, long i, long* value) {
    return !text.empty() && IndexExpression(text, i).evaluate(value);
}

std::string expand_placeholders(const std::string& text, long i, const std::string& where) {
    std::string out;
    for (std::size_t pos = 0; pos < text.size();) {
        auto open = text.find('{', pos);
        if (open == std::string::npos) {
            out += text.substr(pos);
            break;
        }
        out += text.substr(pos, open - pos);
        auto close = text.find('}', open);
        auto inside = close == std::string::npos ? std::string() : text.substr(open + 1, close - open - 1);
        auto colon = inside.find(':');
        auto expression = inside.substr(0, colon);
        std::size_t width = 0;
        bool ok = close != std::string::npos;
        if (ok && colon != std::string::npos) {
            auto format = inside.substr(colon + 1);
            ok = format.size() == 2 && format[0] == '0' && format[1] >= '1' && format[1] <= '9';
            if (ok) width = static_cast<std::size_t>(format[1] - '0');
        }
        long value = 0;
        if (!ok || !evaluate_index_expression(expression, i, &value))
            throw ConfigError(where + ": '" + text + "': a brace holds no placeholder; write {i}, {i+100}, {i:03} or "
                              "{2*i+1}");
        auto digits = std::to_string(value < 0 ? -value : value);
        if (digits.size() < width) digits.insert(0, width - digits.size(), '0');
        out += (value < 0 ? "-" : "") + digits;
        pos = close + 1;
    }
    return out;
}

namespace {

// A scenario file that names its "stations" must name some station of the
// configuration: a typo would otherwise leave it silently unused.
void check_scenario_stations(const PlantConfig& plant) {
    std::set<std::string> files;
    for (const auto& station : plant.stations) files.insert(station.server.scenarios.begin(), station.server.scenarios.end());
    for (const auto& file : files) {
        std::ifstream in(file);
        if (!in) continue;   // the station reports a missing file when it loads it
        auto json = nlohmann::json::parse(in, nullptr, false);
        if (!json.is_object() || !json.contains("stations")) continue;
        JsonAt at(json, file);
        auto patterns = parse_station_patterns(at["stations"]);
        bool used = false;
        for (const auto& station : plant.stations)   // a lone unnamed station runs every scenario
            used = used || station.server.name.empty() || station_patterns_match(patterns, station.server.name);
        if (!used)
            at["stations"].fail("no station of the plant is named " + json["stations"].dump(),
                                "write a station name or pattern of the configuration, e.g. \"press-*\"");
    }
}

}  // namespace

PlantConfig parse_plant_config(const std::string& json_text, const std::string& source,
                               const std::filesystem::path& directory, const std::string& profile) {
    auto json = parse_json(json_text, source);
    JsonAt root(json, source);
    root.expect_object();
    PlantConfig plant;
    if (root.has("threads")) plant.threads = static_cast<unsigned>(whole_setting(root, Section::Plant, "threads"));
    if (!root.has("stations")) {
        auto body = json;
        body.erase("threads");
        if (!profile.empty()) body["profile"] = profile;
        JsonAt at(body, source);
        plant.stations.push_back({parse_server_config(at, directory), parse_frontends_config(at)});
        if (plant.stations.back().frontends.kind != StationKind::Melsec) plant.stations.back().server.ports.clear();
        check_scenario_stations(plant);
        return plant;
    }
    plant.plant = true;
    if (root.has("shards")) plant.layout.file_count = static_cast<unsigned>(whole_setting(root, Section::Plant, "shards"));
    if (root.has("shard_host")) plant.layout.host_pattern = root["shard_host"].string();
    if (root.has("metrics_by")) {
        plant.metrics_by = root["metrics_by"].string();
        if (plant.metrics_by != "auto" && plant.metrics_by != "station" && plant.metrics_by != "profile")
            root["metrics_by"].fail("'" + plant.metrics_by + "' is not a metrics mode", "use \"auto\", \"station\" or \"profile\"");
    }
    if (root.has("name"))
        root["name"].fail("a plant has no name of its own", "name each station in \"stations\" instead");
    auto list = root["stations"];
    list.expect_array();
    if (list.json().empty()) list.fail("no stations", "list at least one station, e.g. [{\"name\": \"press-1\"}]");
    PlantReader reader(json, source, directory);
    std::size_t position = 0;
    for (std::size_t k = 0; k < list.json().size(); ++k) {
        auto entry = list[k];
        entry.expect_object();
        auto where = source + ": " + entry.pointer();
        if (!entry.has("template") && !entry.has("count")) {
            reader.add(entry.json(), ++position, nullptr, where);
            continue;
        }
        auto body = entry["template"];
        body.expect_object();
        auto count = bounded_setting(entry, Section::Template, "count");
        long first = entry.has("first") ? static_cast<long>(bounded_setting(entry, Section::Template, "first")) : 1;
        // The entry's own keys sit beside the template's (and win): {"template": {...}, "count": 500, "name": "press-{i}"}.
        const auto template_keys = section_keys(Section::Template);
        auto station = body.json();
        for (const auto& [key, value] : entry.json().items())
            if (std::find(template_keys.begin(), template_keys.end(), key) == template_keys.end()) station[key] = value;
        for (std::uint64_t n = 0; n < count; ++n) {
            long i = first + static_cast<long>(n);
            ++position;
            reader.add(expanded(station, i, where), position, &i, where + " (i = " + std::to_string(i) + ")");
        }
    }
    plant.stations = reader.take();
    check_scenario_stations(plant);
    return plant;
}

PlantConfig load_plant_config(const std::filesystem::path& file, const std::string& profile) {
    return parse_plant_config(read_config_file(file), file.string(), file.parent_path(), profile);
}

}  // namespace slmp::config
