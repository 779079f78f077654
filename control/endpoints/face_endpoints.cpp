// /api/<face>/...: the resources a protocol face serves itself (the JW-51CM's
// ring buffers, docs/api.md), routed to the station's unit of that face. The
// face answers; this file only finds the unit and reports the writes.
#include "control/endpoints/api.hpp"
#include "control/observers/event_hub.hpp"
#include "frontends/face.hpp"

namespace slmp::control {

namespace {

Reply call_face(Api& api, const frontends::Face& face, const frontends::ApiRoute& route, const ApiRequest& request) {
    frontends::Unit* unit = nullptr;
    for (auto* candidate : api.station.frontends())
        if (&candidate->face() == &face) unit = candidate;
    if (!unit)
        throw ApiError{Status::not_found, "this station has no " + std::string(face.title()) + "; give it a \"" +
                                              std::string(face.name()) + "\" section in the configuration"};
    api.events.flush_writes("internal");
    auto answer = route.handler(*unit, request.captures, request.body);
    api.events.flush_writes("api");
    if (answer.status != 200) return error_reply(static_cast<Status>(answer.status), answer.body);
    Reply reply;
    reply.body = std::move(answer.body);
    reply.body += '\n';   // as json_reply ends its bodies
    return reply;
}

}  // namespace

void add_face_endpoints(Router& router, Api& api) {
    for (const auto* face : frontends::faces())
        for (const auto& route : face->api_routes())
            router.add(route.post ? Verb::post : Verb::get, "/api/" + std::string(face->name()) + "/" + std::string(route.pattern), {},
                       [&api, face, &route](const ApiRequest& request) { return call_face(api, *face, route, request); });
}

}  // namespace slmp::control
