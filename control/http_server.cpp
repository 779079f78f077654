#include "control/http_server.hpp"

#include <array>

#include <boost/beast/core.hpp>
#include <boost/beast/http.hpp>
#include <spdlog/spdlog.h>

#include "control/event_stream.hpp"
#include "station/log_exception.hpp"

namespace slmp::control {

namespace asio = boost::asio;
namespace beast = boost::beast;
namespace bhttp = boost::beast::http;
using asio::ip::tcp;

namespace {

constexpr std::size_t kMaxBodyBytes = 1 << 20;
constexpr auto kIdleTimeout = std::chrono::seconds(60);    // between requests on a keep-alive connection
constexpr auto kWriteTimeout = std::chrono::seconds(30);

template <class Body>
void common_fields(bhttp::response<Body>& response) {
    response.set(bhttp::field::server, "slmp-sim");
    // Device values change all the time; nothing here may be cached.
    response.set(bhttp::field::cache_control, "no-store");
}

}  // namespace

HttpServer::HttpServer(asio::io_context& io, station::Station& station, const config::HttpConfig& config,
                       const asio::ip::address& bind, PortList ports)
    : io_(io),
      metrics_(station),
      events_(io, station),
      waits_(io, events_),
      api_{station, events_, metrics_, waits_, std::move(ports), std::chrono::system_clock::now()},
      acceptor_(io) {
    tcp::endpoint endpoint(bind, config.port);
    try {
        acceptor_.open(endpoint.protocol());
        acceptor_.set_option(tcp::acceptor::reuse_address(true));
        acceptor_.bind(endpoint);
        acceptor_.listen();
    } catch (const boost::system::system_error& e) {
        throw config::ConfigError("cannot listen on HTTP " + bind.to_string() + ":" + std::to_string(config.port) + ": " +
                                  e.code().message() + "; choose another port (--http-port, 0 = any free port) or turn "
                                  "the HTTP API off (--no-http)");
    }
    port_ = acceptor_.local_endpoint().port();
    api_.ports.http = port_;

    add_device_endpoints(router_, api_);
    add_wait_endpoints(router_, api_);
    add_snapshot_endpoints(router_, api_);
    add_clock_endpoints(router_, api_);
    add_buffer_endpoints(router_, api_);
    add_file_endpoints(router_, api_);
    add_label_endpoints(router_, api_);
    add_scenario_endpoints(router_, api_);
    add_fault_endpoints(router_, api_);
    add_recording_endpoints(router_, api_);
    add_connection_endpoints(router_, api_);
    add_info_endpoint(router_, api_);
    add_ondemand_endpoint(router_, api_);
    add_state_endpoints(router_, api_);
    add_event_endpoint(router_, api_);
    add_metrics_endpoint(router_, api_);
    add_static_pages(router_);

    asio::co_spawn(io_, accept_loop(), station::log_exception("HTTP port " + std::to_string(port_) + ": accept loop failed"));
}

void HttpServer::stop() {
    boost::system::error_code ec;
    acceptor_.close(ec);
    waits_.close_all();
    events_.close_all();
    for (auto* socket : sockets_) socket->close(ec);
}

asio::awaitable<void> HttpServer::accept_loop() {
    while (acceptor_.is_open()) {
        boost::system::error_code ec;
        auto socket = co_await acceptor_.async_accept(asio::redirect_error(asio::use_awaitable, ec));
        if (ec) {
            if (ec == asio::error::operation_aborted || !acceptor_.is_open()) co_return;
            spdlog::warn("HTTP port {}: accept failed: {}", port_, ec.message());
            continue;
        }
        asio::co_spawn(io_, serve(std::move(socket)), station::log_exception("HTTP connection failed"));
    }
}

// One connection: requests answered in order (keep-alive), until the client
// closes, stays idle too long, or asks for the event stream, which then owns
// the connection.
asio::awaitable<void> HttpServer::serve(tcp::socket socket) {
    beast::tcp_stream stream(std::move(socket));
    auto* registered = &stream.socket();
    sockets_.insert(registered);
    struct Unregister {
        std::unordered_set<tcp::socket*>& sockets;
        tcp::socket* socket;
        ~Unregister() { sockets.erase(socket); }
    } unregister{sockets_, registered};

    beast::flat_buffer buffer;
    bool refused_body = false;
    for (;;) {
        bhttp::request_parser<bhttp::string_body> parser;
        parser.body_limit(kMaxBodyBytes);
        stream.expires_after(kIdleTimeout);
        boost::system::error_code ec;
        co_await bhttp::async_read(stream, buffer, parser, asio::redirect_error(asio::use_awaitable, ec));

        Reply reply;
        bool keep_alive = false;
        refused_body = ec == bhttp::error::body_limit;
        unsigned version = 11;
        if (ec == bhttp::error::body_limit) {
            reply = error_reply(Status::payload_too_large, "the request body is over " + std::to_string(kMaxBodyBytes) +
                                                               " bytes; write fewer values per request");
        } else if (ec) {
            break;   // closed, timed out, or not HTTP: nothing to answer
        } else {
            auto& request = parser.get();
            version = request.version();
            keep_alive = request.keep_alive();
            auto target = request.target();
            reply = router_.route(request.method(), std::string_view(target.data(), target.size()), std::move(request.body()));
            spdlog::debug("HTTP {} {} -> {}", std::string(request.method_string()), std::string(request.target()),
                          static_cast<unsigned>(reply.status));
        }

        if (reply.deferred) {
            stream.expires_never();   // a wait has its own timeout
            auto later = std::move(reply.deferred);
            reply = co_await later();
        }
        if (reply.event_types != 0) {
            stream.expires_never();
            co_await stream_events(stream.socket(), events_, reply.event_types);
            break;
        }

        bhttp::response<bhttp::string_body> response{reply.status, version};
        common_fields(response);
        response.set(bhttp::field::content_type, reply.content_type);
        for (const auto& [name, value] : reply.headers) response.set(name, value);
        response.keep_alive(keep_alive);
        response.body() = std::move(reply.body);
        response.prepare_payload();
        stream.expires_after(kWriteTimeout);
        co_await bhttp::async_write(stream, response, asio::redirect_error(asio::use_awaitable, ec));
        if (ec || !keep_alive) break;
    }
    boost::system::error_code ignored;
    stream.socket().shutdown(tcp::socket::shutdown_send, ignored);
    if (refused_body) {
        // Lingering close: the client is still sending the body we refused.
        // Closing with that data unread makes the kernel answer with an RST,
        // which can destroy the 413 before the client reads it; so read and
        // drop the rest (bounded in bytes and time) until the client closes.
        stream.expires_after(std::chrono::seconds(2));
        std::array<char, 16384> sink;
        for (std::size_t drained = 0; drained < 4 * kMaxBodyBytes;) {
            boost::system::error_code ec;
            drained += co_await stream.async_read_some(asio::buffer(sink), asio::redirect_error(asio::use_awaitable, ec));
            if (ec) break;
        }
    }
}

}  // namespace slmp::control
