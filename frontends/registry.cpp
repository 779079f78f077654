// The one registration point of the protocol faces (frontends/face.hpp): one
// line a face. Nothing else in the tree names a particular face.
#include <algorithm>

#include "frontends/face.hpp"
#include "frontends/hostlink/face.hpp"
#include "frontends/jw51cm/face.hpp"

namespace slmp::frontends {

namespace {

std::vector<const Face*>& registered() {
    static std::vector<const Face*> list{
        &hostlink::face(),   // the Ladder Motion host link (docs/hostlink.md)
        &jw51cm::face(),     // the Sharp JW-51CM computer link (docs/jw51cm.md)
    };
    return list;
}

}  // namespace

const std::vector<const Face*>& faces() { return registered(); }

const Face* find_face(std::string_view name) {
    for (const auto* face : registered())
        if (face->name() == name) return face;
    return nullptr;
}

void register_face(const Face& face) {
    if (!find_face(face.name())) registered().push_back(&face);
}

std::string face_names(std::string_view first) {
    std::vector<std::string_view> names;
    if (!first.empty()) names.push_back(first);
    for (const auto* face : registered()) names.push_back(face->name());
    std::string text;
    for (std::size_t k = 0; k < names.size(); ++k) {
        if (k > 0) text += k + 1 == names.size() ? " or " : ", ";
        text += "\"" + std::string(names[k]) + "\"";
    }
    return text;
}

}  // namespace slmp::frontends
