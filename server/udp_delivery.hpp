// Sending one UDP response as a scenario's Delivery asks: after its delay,
// and split into several datagrams with pauses (a client that expects one
// datagram per response sees broken ones, which is the point). Coalescing
// does not apply to UDP: one datagram carries one response.
#pragma once

#include <cstdint>
#include <vector>

#include "station/asio.hpp"

#include "scenarios/faults.hpp"

namespace slmp::server {

station::StrandTask<> send_datagrams(station::StrandDatagramSocket& socket, const boost::asio::ip::udp::endpoint& to,
                                            const std::vector<std::uint8_t>& response,
                                            const scenarios::Delivery& delivery, boost::system::error_code& ec);

}  // namespace slmp::server
