// "kind" and the faces' sections of the server configuration
// (docs/configuration.md; each face reads its own section: frontends/face.hpp).
#include "config/frontend_config.hpp"

#include <algorithm>
#include <utility>

#include "config/json_path.hpp"

namespace slmp::config {

const frontends::Settings* FrontEndsConfig::find(std::string_view face) const {
    for (const auto& s : faces)
        if (s.face->name() == face) return &s;
    return nullptr;
}

frontends::Settings* FrontEndsConfig::find(std::string_view face) {
    return const_cast<frontends::Settings*>(std::as_const(*this).find(face));
}

const frontends::Face* FrontEndsConfig::kind_face() const {
    if (kind == StationKind::Melsec) return nullptr;
    for (const auto* face : frontends::faces())
        if (face->station_kind() == kind.name) return face;
    return nullptr;
}

frontends::Settings& FrontEndsConfig::enable(const frontends::Face& face) {
    if (auto* s = find(face.name())) return *s;
    // Kept in registration order, whatever order they are turned on in.
    const auto& order = frontends::faces();
    auto rank = [&](const frontends::Face* f) { return std::find(order.begin(), order.end(), f) - order.begin(); };
    auto at = std::find_if(faces.begin(), faces.end(), [&](const frontends::Settings& s) { return rank(s.face) > rank(&face); });
    return *faces.insert(at, face.defaults());
}

FrontEndsConfig parse_frontends_config(const std::string& json_text, const std::string& source) {
    auto json = parse_json(json_text, source);
    return parse_frontends_config(JsonAt(json, source));
}

FrontEndsConfig parse_frontends_config(const JsonAt& root) {
    FrontEndsConfig c;
    if (root.has("kind")) {
        auto kind = root["kind"].string();
        std::string kinds = "\"melsec\" (default)";
        std::vector<std::string_view> names;
        for (const auto* face : frontends::faces())
            if (!face->station_kind().empty()) names.push_back(face->station_kind());
        for (std::size_t k = 0; k < names.size(); ++k) kinds += (k + 1 == names.size() ? " or \"" : ", \"") + std::string(names[k]) + "\"";
        if (kind == "melsec") c.kind = StationKind::Melsec;
        else if (auto it = std::find(names.begin(), names.end(), kind); it != names.end()) c.kind = StationKind{*it};
        else root["kind"].fail("unknown station kind '" + kind + "'", "use " + kinds);
    }
    for (const auto* face : frontends::faces())
        if (root.has(face->name())) face->parse(root[face->name()], c.enable(*face));
    if (const auto* only = c.kind_face()) {
        // A controller of another kind has no SLMP port, and no other face.
        if (root.has("ports"))
            root["ports"].fail("a " + std::string(c.kind.name) + " station serves no SLMP ports", only->ports_fix());
        for (const auto* face : frontends::faces())
            if (face != only && root.has(face->name()))
                root[face->name()].fail("a " + std::string(c.kind.name) + " station has no " + std::string(face->missing_noun()),
                                        "remove \"" + std::string(face->name()) + "\"");
        c.enable(*only);
    }
    return c;
}

FrontEndsConfig load_frontends_config(const std::filesystem::path& file) {
    return parse_frontends_config(read_config_file(file), file.string());
}

}  // namespace slmp::config
