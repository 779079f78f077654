// One /metrics for a plant: every station's families merged, samples labelled.
#include <map>
#include <sstream>

#include "control/observers/metrics.hpp"

namespace slmp::control {

namespace {

// "name{a=\"b\"} 1" -> "name{station=\"s\",a=\"b\"} 1"; "name 1" -> "name{station=\"s\"} 1".
std::string labelled(const std::string& line, const std::string& station) {
    auto label = "station=\"" + station + "\"";
    auto brace = line.find('{');
    auto space = line.find(' ');
    if (brace != std::string::npos && brace < space) {
        bool empty = brace + 1 < line.size() && line[brace + 1] == '}';
        return line.substr(0, brace + 1) + label + (empty ? "" : ",") + line.substr(brace + 1);
    }
    if (space == std::string::npos) return line;
    return line.substr(0, space) + "{" + label + "}" + line.substr(space);
}

}  // namespace

std::string merge_metrics(const std::vector<std::pair<std::string, std::string>>& texts) {
    struct Family {
        std::vector<std::string> comments;   // "# HELP ..." and "# TYPE ...", from the first station
        std::vector<std::string> samples;
    };
    std::vector<std::string> order;
    std::map<std::string, Family> families;
    for (const auto& [station, text] : texts) {
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
                auto [it, fresh] = families.try_emplace(name);
                if (fresh) order.push_back(name);
                // The first station's comments only: the same text in each.
                if (it->second.comments.size() < 2 && it->second.samples.empty()) it->second.comments.push_back(line);
                continue;
            }
            if (current.empty()) {
                current = line.substr(0, line.find_first_of("{ "));
                if (families.try_emplace(current).second) order.push_back(current);
            }
            families[current].samples.push_back(labelled(line, station));
        }
    }
    std::string out;
    for (const auto& name : order) {
        for (const auto& line : families[name].comments) out += line + "\n";
        for (const auto& line : families[name].samples) out += line + "\n";
    }
    return out;
}

}  // namespace slmp::control
