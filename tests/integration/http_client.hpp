// A minimal blocking HTTP/1.1 client for black-box tests of the HTTP API:
// one request per connection (Connection: close), every wait bounded. Also a
// reader for the /api/events server-sent event stream.
#pragma once

#include <catch2/catch.hpp>
#include <nlohmann/json.hpp>

#include <cctype>
#include <map>
#include <optional>
#include <string>

#include "sockets.hpp"

namespace slmp::test {

struct HttpResponse {
    int status = 0;
    std::map<std::string, std::string> headers;   // names lower-cased
    std::string body;

    nlohmann::json json() const {
        auto parsed = nlohmann::json::parse(body, nullptr, false);
        if (parsed.is_discarded()) FAIL("response body is not JSON: " << body);
        return parsed;
    }
    std::string error() const { return json().value("error", std::string("<no error key>")); }
    std::string header(const std::string& name) const {
        auto it = headers.find(name);
        return it == headers.end() ? std::string() : it->second;
    }
};

namespace detail {

inline std::string lower(std::string text) {
    for (auto& c : text) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
    return text;
}

// Splits "HTTP/1.1 200 OK\r\nName: value\r\n...\r\n\r\n" into status and headers.
inline std::size_t parse_head(const std::string& data, HttpResponse* out) {
    auto end = data.find("\r\n\r\n");
    if (end == std::string::npos) return std::string::npos;
    auto head = data.substr(0, end);
    auto line_end = head.find("\r\n");
    auto status_line = head.substr(0, line_end);
    out->status = std::stoi(status_line.substr(status_line.find(' ') + 1, 3));
    std::size_t pos = line_end == std::string::npos ? head.size() : line_end + 2;
    while (pos < head.size()) {
        auto next = head.find("\r\n", pos);
        auto line = head.substr(pos, next == std::string::npos ? std::string::npos : next - pos);
        auto colon = line.find(':');
        if (colon != std::string::npos) {
            auto value = line.substr(colon + 1);
            value.erase(0, value.find_first_not_of(' '));
            out->headers[lower(line.substr(0, colon))] = value;
        }
        pos = next == std::string::npos ? head.size() : next + 2;
    }
    return end + 4;
}

}  // namespace detail

// Sends one request and reads the whole response (the server closes after it).
inline HttpResponse http(std::uint16_t port, const std::string& method, const std::string& target,
                         const std::string& body = "", const std::string& extra_headers = "") {
    auto client = TcpClient::open(port);
    std::string request = method + " " + target + " HTTP/1.1\r\nHost: 127.0.0.1\r\nConnection: close\r\n" +
                          extra_headers;
    if (!body.empty() || method == "PUT" || method == "POST")
        request += "Content-Type: application/json\r\nContent-Length: " + std::to_string(body.size()) + "\r\n";
    request += "\r\n" + body;
    REQUIRE(client.send(request));
    std::string data;
    for (;;) {
        auto got = client.recv_some(kReplyTimeout);
        if (got.status == RecvStatus::Eof) break;
        if (got.status != RecvStatus::Data) FAIL("HTTP " << method << " " << target << ": no complete response; got: " << data);
        data.append(got.data.begin(), got.data.end());
    }
    HttpResponse response;
    auto body_start = detail::parse_head(data, &response);
    if (body_start == std::string::npos) FAIL("HTTP " << method << " " << target << ": no header in: " << data);
    response.body = data.substr(body_start);
    return response;
}

inline HttpResponse http_get(std::uint16_t port, const std::string& target) { return http(port, "GET", target); }
inline HttpResponse http_put(std::uint16_t port, const std::string& target, const std::string& body) {
    return http(port, "PUT", target, body);
}

struct ServerEvent {
    std::string type;
    nlohmann::json data;
};

// Subscribes to /api/events; the subscription is active once the constructor returns.
class EventReader {
public:
    // `path`: another station's stream in a plant ("/api/stations/press/events").
    EventReader(std::uint16_t port, const std::string& query = "", const std::string& path = "/api/events")
        : client_(TcpClient::open(port)) {
        REQUIRE(client_.send("GET " + path + query + " HTTP/1.1\r\nHost: 127.0.0.1\r\n\r\n"));
        // The server subscribes before it writes the header and its opening comment.
        while (detail::parse_head(buffer_, &head_) == std::string::npos || buffer_.find("\n\n", buffer_.find("\r\n\r\n") + 4) == std::string::npos) {
            auto got = client_.recv_some(kReplyTimeout);
            if (got.status != RecvStatus::Data) FAIL("event stream: no header; got: " << buffer_);
            buffer_.append(got.data.begin(), got.data.end());
        }
        auto start = buffer_.find("\r\n\r\n") + 4;
        buffer_.erase(0, buffer_.find("\n\n", start) + 2);   // the opening "retry" and comment block
    }

    const HttpResponse& head() const { return head_; }

    // The next event (comments skipped), or nullopt when none comes within the timeout.
    std::optional<ServerEvent> next(std::chrono::milliseconds timeout = kReplyTimeout) {
        for (;;) {
            auto end = buffer_.find("\n\n");
            if (end != std::string::npos) {
                auto block = buffer_.substr(0, end);
                buffer_.erase(0, end + 2);
                ServerEvent event;
                std::string data;
                std::size_t pos = 0;
                while (pos <= block.size()) {
                    auto next = block.find('\n', pos);
                    auto line = block.substr(pos, next == std::string::npos ? std::string::npos : next - pos);
                    if (line.rfind("event: ", 0) == 0) event.type = line.substr(7);
                    if (line.rfind("data: ", 0) == 0) data += line.substr(6);
                    if (next == std::string::npos) break;
                    pos = next + 1;
                }
                if (event.type.empty()) continue;   // a comment (keep-alive)
                event.data = nlohmann::json::parse(data, nullptr, false);
                return event;
            }
            auto got = client_.recv_some(timeout);
            if (got.status != RecvStatus::Data) return std::nullopt;
            buffer_.append(got.data.begin(), got.data.end());
        }
    }

    // The next event, skipping the simulator's own device changes (the scan
    // rewrites clock and scan-time registers all the time).
    std::optional<ServerEvent> next_external() {
        for (;;) {
            auto event = next();
            if (!event || event->type != "devices" || event->data.value("source", "") != "internal") return event;
        }
    }

    // The next event of `type`, skipping others and internal device changes.
    ServerEvent next_of(const std::string& type) {
        for (;;) {
            auto event = next_external();
            if (!event) FAIL("no '" << type << "' event within " << kReplyTimeout.count() << " ms");
            if (event->type == type) return *event;
        }
    }

private:
    TcpClient client_;
    HttpResponse head_;
    std::string buffer_;
};

}  // namespace slmp::test
