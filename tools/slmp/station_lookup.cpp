#include "tools/slmp/station_lookup.hpp"

#include <boost/asio.hpp>
#include <boost/beast/core.hpp>
#include <boost/beast/http.hpp>
#include <nlohmann/json.hpp>

#include "tools/slmp/errors.hpp"

namespace slmp::cli {

namespace asio = boost::asio;
namespace beast = boost::beast;
namespace bhttp = boost::beast::http;

void look_up_station(Target& target, devicemodel::Numbering& numbering, const std::string& name,
                     std::uint16_t api_port) {
    asio::io_context io;
    bhttp::response<bhttp::string_body> response;
    std::exception_ptr failure;
    auto path = "/api/stations/" + name;
    asio::co_spawn(
        io,
        [&]() -> asio::awaitable<void> {
            asio::ip::tcp::resolver resolver(io);
            auto endpoints = co_await resolver.async_resolve(target.host, std::to_string(api_port), asio::use_awaitable);
            beast::tcp_stream stream(io);
            stream.expires_after(target.timeout);
            co_await stream.async_connect(endpoints, asio::use_awaitable);
            bhttp::request<bhttp::empty_body> request{bhttp::verb::get, path, 11};
            request.set(bhttp::field::host, target.host);
            co_await bhttp::async_write(stream, request, asio::use_awaitable);
            beast::flat_buffer buffer;
            co_await bhttp::async_read(stream, buffer, response, asio::use_awaitable);
        },
        [&](std::exception_ptr e) { failure = e; });
    io.run();
    auto where = target.host + ":" + std::to_string(api_port);
    if (failure) {
        try {
            std::rethrow_exception(failure);
        } catch (const std::exception& e) {
            throw ConnectionError("cannot ask slmp-sim's HTTP API at " + where + " where station '" + name + "' is: " +
                                  e.what() + " (check --api-port and --host)");
        }
    }
    auto body = nlohmann::json::parse(response.body(), nullptr, false);
    if (response.result() == bhttp::status::not_found)
        throw UsageError("the simulator at " + where + " has no station '" + name + "' (GET /api/stations lists them)");
    if (response.result() != bhttp::status::ok || !body.is_object())
        throw ConnectionError("GET " + path + " on " + where + " answered " + std::to_string(response.result_int()) +
                              "; is this slmp-sim's HTTP port? (check --api-port)");
    const auto& ports = body[target.udp ? "udp" : "tcp"];
    if (!ports.is_array() || ports.empty())
        throw UsageError("station '" + name + "' serves no " + (target.udp ? "UDP" : "TCP") + " port" +
                         (target.udp ? "; leave out --udp" : "; try --udp"));
    target.port = ports[0].get<std::uint16_t>();
    auto bind = body.value("bind", std::string());
    if (!bind.empty() && bind != "0.0.0.0" && bind != "::") target.host = bind;
    if (body.value("xy_radix", 16) == 8) numbering.xy = devicemodel::Radix::Oct;
}

}  // namespace slmp::cli
