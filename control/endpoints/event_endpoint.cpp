// GET /api/events[?types=request,devices,connection,compare] — a server-sent event
// stream (text/event-stream). The router only checks the query; the HTTP
// session then hands the connection to stream_events() (event_stream.hpp).
#include "control/endpoints/api.hpp"
#include "control/observers/event_hub.hpp"

namespace slmp::control {

void add_event_endpoint(Router& router, Api&) {
    router.add(Verb::get, "/api/events", {"types"}, [](const ApiRequest& request) {
        unsigned types = kAllEvents;
        std::string error;
        if (const auto* text = request.param("types"); text && !parse_event_types(*text, &types, &error))
            return error_reply(Status::bad_request, error);
        Reply reply;
        reply.event_types = types;
        return reply;
    });
}

}  // namespace slmp::control
