// Writes one /api/events subscription to its connection as server-sent events
// until the client leaves or the server stops. A comment line every 15 s
// keeps proxies from timing the stream out and finds clients that left.
#pragma once

#include "station/asio.hpp"

#include "control/observers/event_hub.hpp"

namespace slmp::control {

inline constexpr std::chrono::seconds kEventKeepAlive{15};

boost::asio::awaitable<void> stream_events(boost::asio::ip::tcp::socket& socket, EventHub& hub, unsigned types);

}  // namespace slmp::control
