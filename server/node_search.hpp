// Node search by broadcast (docs/nodes.md, "Node search over UDP"): a node
// station's second UDP socket, on the search port every node station of the
// host shares, bound with SO_REUSEADDR to the broadcast address of the
// station's bind address so that each of them gets its own copy of a
// broadcast (Linux delivers a broadcast to every socket bound to the port on
// 0.0.0.0 or on the broadcast address, none bound to 127.0.0.1). Only Node
// Search (0E30) is answered there, after the manual's random delay (JA
// §4.1.1: 0-1500 ms, so the answers of many devices do not collide), drawn per
// answer and waited on the station's clock; the answer goes to the sender.
#pragma once

#include <cstdint>
#include <random>
#include <vector>

#include "station/asio.hpp"

#include "config/config.hpp"
#include "station/station.hpp"

namespace slmp::server {

class NodeSearchListener {
public:
    // `answer_port`: the station's SLMP UDP port, which the answer reports as
    // the server port (where the client talks to the node next).
    NodeSearchListener(const station::Home& home, station::Station& station, const config::NodeSearchConfig& config,
                       const boost::asio::ip::address& bind, std::uint16_t answer_port);
    void stop();

    // Where it binds: 127.255.255.255 for a loopback address, 0.0.0.0 otherwise.
    static boost::asio::ip::address search_address(const boost::asio::ip::address& bind);

private:
    station::StrandTask<> serve();
    // One datagram: a node search answered after its delay; anything else ignored.
    station::StrandTask<> answer(std::vector<std::uint8_t> datagram, boost::asio::ip::udp::endpoint sender);

    station::Station& station_;
    config::NodeSearchConfig config_;
    std::uint16_t answer_port_;
    protocol::Session session_;
    station::StrandDatagramSocket socket_;
    std::mt19937 random_;
};

}  // namespace slmp::server
