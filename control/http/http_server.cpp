#include "control/http/http_server.hpp"

#include <array>

#include <boost/beast/core.hpp>
#include <boost/beast/http.hpp>
#include <spdlog/spdlog.h>

#include "control/observers/event_stream.hpp"
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
// A plant's /metrics in "auto" mode: one series set per station up to this many stations, per profile above.
constexpr std::size_t kStationSeriesLimit = 1000;

template <class Body>
void common_fields(bhttp::response<Body>& response) {
    response.set(bhttp::field::server, "slmp-sim");
    // Device values change all the time; nothing here may be cached.
    response.set(bhttp::field::cache_control, "no-store");
}

}  // namespace

HttpServer::HttpServer(const station::Home& strand, const std::vector<ServedStation>& stations,
                       const config::HttpConfig& config, const asio::ip::address& bind,
                       const config::PlantConfig& plant)
    : strand_(strand), acceptor_(strand) {
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
    plant_.named = plant.plant;
    plant_.layout = &plant.layout;
    // Per-station series of more than a thousand stations are more than a scrape should carry (docs/plants.md).
    plant_.metrics_by_profile =
        plant.metrics_by == "profile" || (plant.metrics_by == "auto" && stations.size() > kStationSeriesLimit);
    for (const auto& served : stations) plant_.stations.push_back(std::make_unique<StationSide>(served, port_));
    add_plant_endpoints(plant_router_, plant_);
    add_static_pages(plant_router_);

    asio::co_spawn(strand_, accept_loop(), station::log_exception("HTTP port " + std::to_string(port_) + ": accept loop failed"));
}

void HttpServer::stop() {
    stopping_ = true;
    boost::system::error_code ec;
    acceptor_.close(ec);
    // Waits and event streams end on their stations' threads; the sockets
    // they hold are closed by the connections themselves when they end.
    for (auto& side : plant_.stations)
        asio::post(side->home, [s = side.get()] {
            s->waits.close_all();
            s->events.close_all();
        });
    for (auto* socket : sockets_)
        if (!lent_.contains(socket)) socket->close(ec);
}

StationSide* HttpServer::station_for(std::string_view target, std::string* station_target, Reply* error) {
    constexpr std::string_view kPrefix = "/api/stations/";
    if (target.substr(0, kPrefix.size()) != kPrefix) {
        *station_target = std::string(target);
        return plant_.stations.front().get();
    }
    auto rest = target.substr(kPrefix.size());
    auto slash = rest.find_first_of("/?");
    std::string name;
    if (!percent_decode(rest.substr(0, slash), false, &name)) name.clear();
    auto* side = plant_.find(name);
    if (!side) {
        *error = error_reply(Status::not_found, "no station '" + name + "'; GET /api/stations lists them");
        return nullptr;
    }
    auto inner = slash == std::string_view::npos ? std::string_view() : rest.substr(slash + 1);
    // /api/stations/{name}/metrics is the station's /metrics; the rest are its /api/... routes.
    *station_target = (inner.substr(0, 7) == "metrics" ? "/" : "/api/") + std::string(inner);
    return side;
}

namespace {

// A station's request on its own thread: its route, a wait's deferred answer,
// or the event stream that then owns the connection (event_types stays set).
asio::awaitable<Reply> station_request(StationSide& side, bhttp::verb method, std::string target, std::string body,
                                       tcp::socket& socket) {
    // A sleeping station first runs the scans due by now; whatever is not a
    // read may change it (a timer coil, the clock, a scenario), and a device
    // watcher (event stream, wait) needs every scan, so its scan loop looks
    // again after (docs/timing.md, "What wakes a station").
    side.station.catch_up();
    const bool changes = method != bhttp::verb::get && method != bhttp::verb::head;
    auto look_again = [&side, changes] {
        if (changes || side.station.cpu().memory().observed()) side.station.touched();
    };
    auto reply = side.router().route(method, target, std::move(body));
    look_again();
    if (reply.deferred) {
        auto later = std::move(reply.deferred);
        reply = co_await later();
        side.station.catch_up();
        look_again();
    }
    if (reply.event_types != 0) co_await stream_events(socket, side.events, reply.event_types);
    co_return reply;
}

}  // namespace

asio::awaitable<void> HttpServer::accept_loop() {
    while (acceptor_.is_open()) {
        boost::system::error_code ec;
        auto socket = co_await acceptor_.async_accept(asio::redirect_error(asio::use_awaitable, ec));
        if (ec) {
            if (ec == asio::error::operation_aborted || !acceptor_.is_open()) co_return;
            spdlog::warn("HTTP port {}: accept failed: {}", port_, ec.message());
            continue;
        }
        asio::co_spawn(strand_, serve(std::move(socket)), station::log_exception("HTTP connection failed"));
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
            auto target_view = request.target();
            std::string_view target(target_view.data(), target_view.size());
            std::string station_target;
            StationSide* side = nullptr;
            if (plant_router_.serves(target)) reply = plant_router_.route(request.method(), target, std::move(request.body()));
            else side = station_for(target, &station_target, &reply);
            if (side) {
                stream.expires_never();   // a wait and an event stream have their own timeouts
                lent_.insert(registered);
                // On the station's strand, which is never the HTTP server's own.
                reply = co_await asio::co_spawn(side->home,
                                                station_request(*side, request.method(), std::move(station_target),
                                                                std::move(request.body()), stream.socket()),
                                                asio::use_awaitable);
                lent_.erase(registered);
                if (stopping_) keep_alive = false;   // stop() left this connection to end here
            }
            spdlog::debug("HTTP {} {} -> {}", std::string(request.method_string()), std::string(request.target()),
                          static_cast<unsigned>(reply.status));
        }

        if (reply.deferred) {   // the plant's own routes: they visit the stations in turn
            stream.expires_never();
            auto later = std::move(reply.deferred);
            reply = co_await later();
        }
        if (reply.event_types != 0) break;   // the event stream has ended

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
