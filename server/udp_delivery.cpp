#include "server/udp_delivery.hpp"

namespace slmp::server {

namespace asio = boost::asio;

station::StrandTask<> send_datagrams(station::StrandDatagramSocket& socket, const asio::ip::udp::endpoint& to,
                                     const std::vector<std::uint8_t>& response, const scenarios::Delivery& delivery,
                                     boost::system::error_code& ec) {
    station::StrandTimer timer(socket.get_executor());
    auto wait = [&](std::chrono::microseconds d) -> station::StrandTask<> {
        if (d.count() <= 0) co_return;
        timer.expires_after(d);
        boost::system::error_code ignored;
        co_await timer.async_wait(asio::redirect_error(station::use_strand, ignored));
    };
    co_await wait(delivery.delay);
    if (delivery.pieces.empty()) {
        co_await socket.async_send_to(asio::buffer(response), to, asio::redirect_error(station::use_strand, ec));
        co_return;
    }
    std::size_t at = 0;
    for (std::size_t i = 0; i < delivery.pieces.size() && !ec; ++i) {
        if (i > 0) co_await wait(delivery.pause);
        co_await socket.async_send_to(asio::buffer(response.data() + at, delivery.pieces[i]), to,
                                      asio::redirect_error(station::use_strand, ec));
        at += delivery.pieces[i];
    }
}

}  // namespace slmp::server
