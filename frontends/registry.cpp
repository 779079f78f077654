// The one registration point of the protocol faces (frontends/face.hpp): one
// line a face. Nothing else in the tree names a particular face.
#include <algorithm>

#include "frontends/face.hpp"
#include "frontends/hostlink/face.hpp"
#include "frontends/jw51cm/face.hpp"
#include "frontends/slmp/face.hpp"

namespace slmp::frontends {

namespace {

std::vector<const Face*>& registered() {
    static std::vector<const Face*> list{
        &slmp_face::face(),  // SLMP, the MELSEC CPU's own (docs/frames.md): its ports are the station's "ports"
        &hostlink::face(),   // the Ladder Motion host link (docs/hostlink.md)
        &jw51cm::face(),     // the Sharp JW-51CM computer link (docs/jw51cm.md)
    };
    return list;
}

// faces(): the registered list without the faces configured by the station's
// own keys, kept in step with it (register_face may add a face later).
std::vector<const Face*>& sectioned() {
    static std::vector<const Face*> list;
    return list;
}

void list_sectioned() {
    auto& list = sectioned();
    list.clear();
    for (const auto* face : registered())
        if (face->own_section()) list.push_back(face);
}

}  // namespace

const std::vector<const Face*>& all_faces() { return registered(); }

const std::vector<const Face*>& faces() {
    if (sectioned().empty()) list_sectioned();
    return sectioned();
}

const Face* find_face(std::string_view name) {
    for (const auto* face : registered())
        if (face->name() == name) return face;
    return nullptr;
}

void register_face(const Face& face) {
    if (find_face(face.name())) return;
    registered().push_back(&face);
    list_sectioned();
}

std::string face_names(std::string_view first) {
    std::vector<std::string_view> names;
    if (!first.empty()) names.push_back(first);
    for (const auto* face : faces()) names.push_back(face->name());
    std::string text;
    for (std::size_t k = 0; k < names.size(); ++k) {
        if (k > 0) text += k + 1 == names.size() ? " or " : ", ";
        text += "\"" + std::string(names[k]) + "\"";
    }
    return text;
}

}  // namespace slmp::frontends
