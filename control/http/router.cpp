#include "control/http/router.hpp"

#include <algorithm>

#include "devicemodel/hex.hpp"

namespace slmp::control {
namespace {

std::vector<std::string_view> split(std::string_view text, char separator) {
    std::vector<std::string_view> parts;
    std::size_t start = 0;
    for (;;) {
        auto end = text.find(separator, start);
        parts.push_back(text.substr(start, end == std::string_view::npos ? std::string_view::npos : end - start));
        if (end == std::string_view::npos) return parts;
        start = end + 1;
    }
}

// "/api/devices/D100" -> {"api", "devices", "D100"}; "/" -> {}.
std::vector<std::string> segments_of(std::string_view path) {
    std::vector<std::string> segments;
    for (auto part : split(path, '/'))
        if (!part.empty()) segments.emplace_back(part);
    return segments;
}

std::string join(const std::vector<std::string>& items) {
    std::string text;
    for (const auto& item : items) text += (text.empty() ? "" : ", ") + item;
    return text;
}

}  // namespace

bool percent_decode(std::string_view text, bool query, std::string* out) {
    out->clear();
    for (std::size_t i = 0; i < text.size(); ++i) {
        char c = text[i];
        if (c == '%') {
            if (i + 2 >= text.size()) return false;
            int high = devicemodel::hex_digit(text[i + 1]);
            int low = devicemodel::hex_digit(text[i + 2]);
            if (high < 0 || low < 0) return false;
            *out += static_cast<char>(high * 16 + low);
            i += 2;
        } else {
            *out += query && c == '+' ? ' ' : c;
        }
    }
    return true;
}

const std::string* ApiRequest::param(const std::string& name) const {
    auto it = query.find(name);
    return it == query.end() ? nullptr : &it->second;
}

void Router::add(Verb method, std::string pattern, std::vector<std::string> parameters, Handler handler) {
    routes_.push_back(Route{method, segments_of(pattern), std::move(parameters), std::move(handler)});
}

bool Router::match(const Route& route, const std::vector<std::string>& segments, std::vector<std::string>* captures) {
    if (route.segments.size() != segments.size()) return false;
    captures->clear();
    for (std::size_t i = 0; i < segments.size(); ++i) {
        const auto& want = route.segments[i];
        if (want.size() > 2 && want.front() == '{' && want.back() == '}') captures->push_back(segments[i]);
        else if (want != segments[i]) return false;
    }
    return true;
}

bool Router::serves(std::string_view target) const {
    auto segments = segments_of(target.substr(0, target.find('?')));
    std::vector<std::string> captures;
    return std::any_of(routes_.begin(), routes_.end(),
                       [&](const Route& route) { return match(route, segments, &captures); });
}

Reply Router::route(Verb method, std::string_view target, std::string body) const {
    auto question = target.find('?');
    auto raw_path = target.substr(0, question);
    auto raw_query = question == std::string_view::npos ? std::string_view{} : target.substr(question + 1);

    ApiRequest request;
    request.method = method;
    request.body = std::move(body);
    if (!percent_decode(raw_path, false, &request.path))
        return error_reply(Status::bad_request, "bad percent-escape in the path '" + std::string(raw_path) +
                                                     "'; write %XX with two hex digits");
    // Decoded per segment, so an escaped '/' inside an address stays in its segment.
    std::vector<std::string> segments;
    for (auto part : split(raw_path, '/')) {
        if (part.empty()) continue;
        std::string decoded;
        percent_decode(part, false, &decoded);
        segments.push_back(std::move(decoded));
    }

    const Route* found = nullptr;
    std::vector<std::string> allowed;
    for (const auto& route : routes_) {
        std::vector<std::string> captures;
        if (!match(route, segments, &captures)) continue;
        allowed.push_back(std::string(boost::beast::http::to_string(route.method)));
        if (route.method == method && !found) {
            found = &route;
            request.captures = std::move(captures);
        }
    }
    if (!found) {
        if (allowed.empty())
            return error_reply(Status::not_found, "no endpoint " + request.path +
                                                      "; the endpoints are listed in docs/api.md (e.g. /api/info)");
        auto reply = error_reply(Status::method_not_allowed,
                                 std::string(boost::beast::http::to_string(method)) + " is not served on " +
                                     request.path + "; use " + join(allowed));
        reply.headers.emplace_back("Allow", join(allowed));
        return reply;
    }

    if (!raw_query.empty()) {
        for (auto pair : split(raw_query, '&')) {
            if (pair.empty()) continue;
            auto equals = pair.find('=');
            std::string name, value;
            if (!percent_decode(pair.substr(0, equals), true, &name) ||
                (equals != std::string_view::npos && !percent_decode(pair.substr(equals + 1), true, &value)))
                return error_reply(Status::bad_request, "bad percent-escape in the query '" + std::string(pair) +
                                                             "'; write %XX with two hex digits");
            if (std::find(found->parameters.begin(), found->parameters.end(), name) == found->parameters.end())
                return error_reply(Status::bad_request,
                                   "unknown query parameter '" + name + "' for " + request.path +
                                       (found->parameters.empty() ? "; it takes none"
                                                                  : "; use " + join(found->parameters)));
            request.query[name] = value;
        }
    }

    try {
        return found->handler(request);
    } catch (const ApiError& e) {
        return error_reply(e.status, e.message);
    }
}

}  // namespace slmp::control
