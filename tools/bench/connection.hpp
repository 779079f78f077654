// One benchmark connection: keeps `depth` requests in flight, times each one
// from just before its send to the arrival of its whole response, and
// reconnects after a timeout, a broken stream or a closed connection.
#pragma once

#include <utility>   // before Boost 1.74's Asio headers, which use std::exchange without it

#include <boost/asio/any_io_executor.hpp>
#include <boost/asio/ip/address.hpp>

#include <cstdint>

#include "tools/bench/control.hpp"

namespace slmp::bench {

// Spawns the connection's coroutines on `executor`. They finish by themselves
// once `state.control` says the run is over and nothing is left in flight
// (each request is bounded by the control's timeout). `index` staggers where
// each connection starts in the --mix list.
void start_connection(const boost::asio::any_io_executor& executor, RunState& state, unsigned index, bool udp,
                      const boost::asio::ip::address& address, std::uint16_t port);

}  // namespace slmp::bench
