// Routes an HTTP request to an endpoint by method and path. Patterns are
// literal segments and {captures}: "/api/devices/{address}". Each route lists
// the query parameters it takes, so a misspelt one is an error, not ignored.
// Unknown paths answer 404 and known paths with another method 405 (with Allow).
#pragma once

#include <functional>
#include <map>
#include <string>
#include <string_view>
#include <vector>

#include <boost/beast/http/verb.hpp>

#include "control/http/reply.hpp"

namespace slmp::control {

using Verb = boost::beast::http::verb;

struct ApiRequest {
    Verb method = Verb::get;
    std::string path;                            // percent-decoded
    std::map<std::string, std::string> query;    // percent-decoded; only the route's parameters
    std::vector<std::string> captures;           // the {captures}, in pattern order
    std::string body;

    // The query parameter, or nullptr when it was not given.
    const std::string* param(const std::string& name) const;
};

using Handler = std::function<Reply(const ApiRequest&)>;

class Router {
public:
    void add(Verb method, std::string pattern, std::vector<std::string> parameters, Handler handler);

    // `target` is the request-target as received ("/api/devices/D100?count=3").
    // Exceptions of type ApiError become error replies.
    Reply route(Verb method, std::string_view target, std::string body) const;
    // True when a route has the target's path, with any method.
    bool serves(std::string_view target) const;

private:
    struct Route {
        Verb method;
        std::vector<std::string> segments;
        std::vector<std::string> parameters;
        Handler handler;
    };
    static bool match(const Route& route, const std::vector<std::string>& segments, std::vector<std::string>* captures);

    std::vector<Route> routes_;
};

// Percent-decoding; '+' is a space only in queries. Returns false on a bad escape.
bool percent_decode(std::string_view text, bool query, std::string* out);

}  // namespace slmp::control
