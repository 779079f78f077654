#include "control/observers/event_stream.hpp"

#include <string>

namespace slmp::control {

namespace asio = boost::asio;

asio::awaitable<void> stream_events(asio::ip::tcp::socket& socket, EventHub& hub, unsigned types) {
    auto subscriber = hub.subscribe(types);
    struct Leave {
        EventHub& hub;
        std::shared_ptr<EventHub::Subscriber>& subscriber;
        ~Leave() { hub.unsubscribe(subscriber); }
    } leave{hub, subscriber};

    // No Content-Length and no chunking: the body is the stream, ended by
    // closing the connection (so "Connection: close").
    std::string batch =
        "HTTP/1.1 200 OK\r\nServer: slmp-sim\r\nContent-Type: text/event-stream\r\nCache-Control: no-cache\r\n"
        "Connection: close\r\nX-Accel-Buffering: no\r\n\r\n"
        "retry: 2000\n: slmp-sim events\n\n";
    for (;;) {
        if (!batch.empty()) {
            boost::system::error_code ec;
            co_await asio::async_write(socket, asio::buffer(batch), asio::redirect_error(asio::use_awaitable, ec));
            if (ec) co_return;
            batch.clear();
        }
        if (subscriber->closed) co_return;
        if (subscriber->queue.empty() && subscriber->dropped == 0) {
            // The hub cancels the timer when it queues an event.
            subscriber->wake.expires_after(kEventKeepAlive);
            boost::system::error_code ec;
            co_await subscriber->wake.async_wait(asio::redirect_error(asio::use_awaitable, ec));
            if (subscriber->closed) co_return;
            if (!ec && subscriber->queue.empty()) batch = ": keep-alive\n\n";
        }
        if (subscriber->dropped > 0) {
            batch += "event: overflow\ndata: {\"dropped\":" + std::to_string(subscriber->dropped) + "}\n\n";
            subscriber->dropped = 0;
        }
        while (!subscriber->queue.empty()) {
            batch += *subscriber->queue.front();
            subscriber->queue.pop_front();
        }
    }
}

}  // namespace slmp::control
