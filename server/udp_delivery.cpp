#include "server/udp_delivery.hpp"

namespace slmp::server {

namespace asio = boost::asio;

asio::awaitable<void> send_datagrams(asio::ip::udp::socket& socket, const asio::ip::udp::endpoint& to,
                                     const std::vector<std::uint8_t>& response, const scenarios::Delivery& delivery,
                                     boost::system::error_code& ec) {
    asio::steady_timer timer(socket.get_executor());
    auto wait = [&](std::chrono::microseconds d) -> asio::awaitable<void> {
        if (d.count() <= 0) co_return;
        timer.expires_after(d);
        boost::system::error_code ignored;
        co_await timer.async_wait(asio::redirect_error(asio::use_awaitable, ignored));
    };
    co_await wait(delivery.delay);
    if (delivery.pieces.empty()) {
        co_await socket.async_send_to(asio::buffer(response), to, asio::redirect_error(asio::use_awaitable, ec));
        co_return;
    }
    std::size_t at = 0;
    for (std::size_t i = 0; i < delivery.pieces.size() && !ec; ++i) {
        if (i > 0) co_await wait(delivery.pause);
        co_await socket.async_send_to(asio::buffer(response.data() + at, delivery.pieces[i]), to,
                                      asio::redirect_error(asio::use_awaitable, ec));
        at += delivery.pieces[i];
    }
}

}  // namespace slmp::server
