#include "control/http/reply.hpp"

namespace slmp::control {

Reply json_reply(const nlohmann::json& body, Status status) {
    Reply reply;
    reply.status = status;
    // Device strings are bytes shown as Latin-1 code points, so dump() never
    // meets invalid UTF-8; "replace" is the guard should that ever change.
    reply.body = body.dump(-1, ' ', false, nlohmann::json::error_handler_t::replace);
    reply.body += '\n';
    return reply;
}

Reply error_reply(Status status, const std::string& message) {
    return json_reply(nlohmann::json{{"error", message}}, status);
}

}  // namespace slmp::control
