// One /metrics for a plant: every station's families merged, samples labelled.
#include <charconv>
#include <cmath>
#include <cstdint>
#include <cstdlib>
#include <map>
#include <set>
#include <sstream>

#include "control/observers/metrics.hpp"

namespace slmp::control {

namespace {

// "name{a=\"b\"} 1" -> "name{station=\"s\",a=\"b\"} 1"; "name 1" -> "name{station=\"s\"} 1".
// A sample that has the label already keeps it (slmp_info's profile).
std::string labelled(const std::string& line, const std::string& key, const std::string& value) {
    auto label = key + "=\"" + value + "\"";
    if (line.find("{" + key + "=\"") != std::string::npos || line.find("," + key + "=\"") != std::string::npos)
        return line;
    auto brace = line.find('{');
    auto space = line.find(' ');
    if (brace != std::string::npos && brace < space) {
        bool empty = brace + 1 < line.size() && line[brace + 1] == '}';
        return line.substr(0, brace + 1) + label + (empty ? "" : ",") + line.substr(brace + 1);
    }
    if (space == std::string::npos) return line + "{" + label + "}";   // a series without its value (sum_metrics)
    return line.substr(0, space) + "{" + label + "}" + line.substr(space);
}


// A family's HELP and TYPE (from the first text that has them) and its lines.
struct Family {
    std::vector<std::string> comments;
    std::vector<std::string> samples;
};

// The families of several expositions, in the order they first appear.
class Families {
public:
    // Calls on_sample(family, line) for each sample line of `text`; keeps the comments.
    template <class OnSample>
    void read(const std::string& text, OnSample on_sample) {
        std::istringstream in(text);
        std::string line, current;
        while (std::getline(in, line)) {
            if (line.empty()) continue;
            if (line.rfind("# ", 0) == 0) {
                std::istringstream words(line.substr(2));
                std::string keyword, name;
                words >> keyword >> name;
                if (keyword != "HELP" && keyword != "TYPE") continue;
                current = name;
                auto& family = add(name);
                // The first text's comments only: the same in each.
                if (family.comments.size() < 2 && family.samples.empty()) family.comments.push_back(line);
                continue;
            }
            if (current.empty()) add(current = line.substr(0, line.find_first_of("{ ")));
            on_sample(current, line);
        }
    }
    Family& add(const std::string& name) {
        auto [it, fresh] = families_.try_emplace(name);
        if (fresh) order_.push_back(name);
        return it->second;
    }
    Family& operator[](const std::string& name) { return families_[name]; }
    template <class Rewrite>
    void rewrite_samples(Rewrite rewrite) {
        for (auto& [name, family] : families_)
            for (auto& line : family.samples) line = rewrite(line);
    }
    std::string text(const std::set<std::string>& left_out = {}) {
        std::string out;
        for (const auto& name : order_) {
            if (left_out.count(name)) continue;
            for (const auto& line : families_[name].comments) out += line + "\n";
            for (const auto& line : families_[name].samples) out += line + "\n";
        }
        return out;
    }

private:
    std::vector<std::string> order_;
    std::map<std::string, Family> families_;
};

std::string number_text(double value) {
    if (value == static_cast<double>(static_cast<std::int64_t>(value)) && std::abs(value) < 9.0e15)
        return std::to_string(static_cast<std::int64_t>(value));
    char buffer[32];
    auto end = std::to_chars(buffer, buffer + sizeof buffer, value).ptr;
    return std::string(buffer, end);
}

}  // namespace

std::string merge_metrics(const std::vector<std::pair<std::string, std::string>>& texts) {
    Families families;
    for (const auto& [station_name, text] : texts)
        families.read(text, [&, &station = station_name](const std::string& family, const std::string& line) {
            families[family].samples.push_back(labelled(line, "station", station));
        });
    return families.text();
}

std::string sum_metrics(const std::vector<std::pair<std::string, std::string>>& texts) {
    // Gauges whose sum means nothing; the CPU state becomes slmp_stations.
    const std::set<std::string> not_additive{"slmp_cpu_state", "slmp_scan_time_seconds", "slmp_program_execution_seconds"};
    Families families;
    std::map<std::string, double> sums;   // "name{profile=...,...}" (a family's sample line so far) -> the group's sum
    std::map<std::pair<std::string, std::string>, unsigned> states;   // (profile, state) -> stations
    // (Bindings captured by name: clang 14, the sanitizer build, cannot capture them implicitly.)
    for (const auto& [group_name, text] : texts)
        families.read(text, [&, &group = group_name](const std::string& family, const std::string& line) {
            auto space = line.rfind(' ');
            if (space == std::string::npos) return;
            double value = std::strtod(line.c_str() + space + 1, nullptr);
            if (family == "slmp_cpu_state") {
                auto state = value == 0 ? "RUN" : value == 2 ? "STOP" : value == 3 ? "PAUSE" : "other";
                ++states[{group, state}];
            }
            if (not_additive.count(family)) return;
            auto series = labelled(line.substr(0, space), "profile", group);
            auto [it, fresh] = sums.try_emplace(series, 0.0);
            it->second += value;
            if (fresh) families[family].samples.push_back(series);
        });
    // Each summed series gets its sum.
    families.rewrite_samples([&](const std::string& series) { return series + " " + number_text(sums[series]); });
    auto& stations = families.add("slmp_stations");
    stations.comments = {"# HELP slmp_stations Stations of each profile in each operating state (the plant's /metrics by profile).",
                         "# TYPE slmp_stations gauge"};
    for (const auto& [key, count] : states)
        stations.samples.push_back("slmp_stations{profile=\"" + key.first + "\",state=\"" + key.second + "\"} " +
                                   std::to_string(count));
    return families.text(not_additive);
}

}  // namespace slmp::control
