// What an endpoint answers: a status, a body and its content type. Errors are
// JSON {"error": "..."} whose message names the fix (docs/api.md).
#pragma once

#include <functional>
#include <string>
#include <utility>
#include <vector>

#include <boost/asio/awaitable.hpp>
#include <boost/beast/http/status.hpp>
#include <nlohmann/json.hpp>

namespace slmp::control {

using Status = boost::beast::http::status;

struct Reply {
    Status status = Status::ok;
    std::string content_type = "application/json";
    std::string body;
    std::vector<std::pair<std::string, std::string>> headers;   // extra header fields (Allow, ...)
    unsigned event_types = 0;    // non-zero (GET /api/events): the connection becomes an event stream of these types
    // Set (GET .../wait): the answer comes later; the connection awaits it
    // while the server goes on serving every other connection.
    std::function<boost::asio::awaitable<Reply>()> deferred;
};

Reply json_reply(const nlohmann::json& body, Status status = Status::ok);
Reply error_reply(Status status, const std::string& message);

// Thrown by endpoint code that finds bad input deep down; the router turns it
// into error_reply(status, message).
struct ApiError {
    Status status;
    std::string message;
};
[[noreturn]] inline void fail(Status status, const std::string& message) { throw ApiError{status, message}; }
[[noreturn]] inline void bad(const std::string& message) { fail(Status::bad_request, message); }

}  // namespace slmp::control
