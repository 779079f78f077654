// "extends": a profile written as the differences from another. The base
// profile's JSON is taken whole and the extending profile's keys are laid
// over it: objects merge key by key (so "device_sizes": {"D": 20480} changes
// one size and keeps the others), anything else — strings, numbers, arrays —
// replaces the base's value, and null removes the base's key (a probed
// profile, docs/twin.md, says so of a frame or limit its base has and the
// probed port has not). A base may itself extend another; a cycle or an
// unknown base stops with the chain that led there.
#include <filesystem>
#include <fstream>
#include <sstream>

#include "config/config.hpp"
#include "config/config_parts.hpp"

namespace slmp::config {

namespace {

constexpr std::size_t kMaxDepth = 8;

void lay_over(nlohmann::json& base, const nlohmann::json& over) {
    for (const auto& [key, value] : over.items()) {
        if (value.is_null())
            base.erase(key);
        else if (value.is_object() && base.contains(key) && base[key].is_object())
            lay_over(base[key], value);
        else
            base[key] = value;
    }
}

// The base's text and how to name it: a built-in profile by name, or (only
// for profiles read from files) a file relative to the extending one.
std::pair<std::string, ProfileSource> find_base(const JsonAt& at, const ProfileSource& from) {
    auto name = at.string();
    const bool is_path = name.find('/') != std::string::npos || name.ends_with(".json");
    if (is_path) {
        if (from.directory.empty())
            at.fail("a built-in profile extends a file ('" + name + "')", "extend a built-in profile by name");
        auto path = std::filesystem::path(name).is_absolute() ? std::filesystem::path(name) : from.directory / name;
        std::ifstream file(path);
        if (!file) at.fail("cannot open the base profile " + path.string(), "check the path (relative to this file)");
        std::stringstream text;
        text << file.rdbuf();
        return {text.str(), {path.string(), path.parent_path()}};
    }
    if (const auto* p = find_builtin_profile(name)) return {std::string(p->json), {"profile " + std::string(p->name), {}}};
    at.fail("unknown base profile '" + name + "'", "extend one of: " + builtin_profile_list() + " (or a .json file)");
}

nlohmann::json resolve(const std::string& json_text, const ProfileSource& source, std::vector<std::string>& chain) {
    auto json = parse_json(json_text, source.name);
    JsonAt root(json, source.name);
    root.expect_object();
    for (const auto& seen : chain)
        if (seen == source.name) root.fail("profiles extend each other in a cycle", "break the chain of \"extends\"");
    if (chain.size() >= kMaxDepth) root.fail("\"extends\" goes deeper than 8 profiles", "extend a profile nearer the base");
    chain.push_back(source.name);
    if (!root.has("extends")) return json;
    if (!root.has("name") || !root.has("description"))
        root.fail("a profile that extends another needs its own \"name\" and \"description\"",
                  "add both, so --list-profiles and the logs tell it from its base");
    auto [base_text, base_source] = find_base(root["extends"], source);
    auto merged = resolve(base_text, base_source, chain);
    json.erase("extends");
    lay_over(merged, json);
    return merged;
}

}  // namespace

nlohmann::json resolve_profile_json(const std::string& json_text, const ProfileSource& source) {
    std::vector<std::string> chain;
    return resolve(json_text, source, chain);
}

}  // namespace slmp::config
