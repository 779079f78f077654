// A UDP port of a face (frontends/face.hpp: SLMP, the JW-51CM computer link):
// one datagram is one request, answered to the sender's address and port. No
// connection, so one protocol session serves the port. The port reads a
// datagram, hands it to the station's datagram inbox (station/datagram_inbox.hpp)
// and writes the answer it gets, now or later; when is the station's business.
#pragma once

#include <array>
#include <cstdint>
#include <map>
#include <memory>
#include <optional>

#include "station/asio.hpp"

#include "config/config.hpp"
#include "frontends/face.hpp"
#include "station/datagram_inbox.hpp"
#include "station/inbox.hpp"
#include "station/station.hpp"

namespace slmp::server {

class UdpListener {
public:
    // Serves `unit`'s face.
    UdpListener(const station::Home& home, station::Station& station, frontends::Unit& unit, const config::PortConfig& port,
                const boost::asio::ip::address& bind);

    std::uint16_t port() const { return port_; }
    void stop();
    // After a Remote RESET: the port's session starts afresh (locked again when
    // the CPU has a remote password).
    void restart_session();
    // Ondemand: every peer that has sent this port a request (station/transports.hpp).
    void push_targets(std::vector<station::PushTarget>& targets);

private:
    station::StrandTask<> serve();
    // A datagram the inbox answers later (held on the clock, routed): its answer once it has it.
    station::StrandTask<> answer_later(station::StrandTask<std::optional<station::Handled>> later,
                                       std::vector<std::uint8_t> datagram, boost::asio::ip::udp::endpoint sender);
    // The station's answer to one datagram, sent at once when it can be (no
    // scenario delay or split, room in the send buffer); else moved out and returned.
    std::optional<station::Handled> answer_now(std::span<const std::uint8_t> datagram,
                                               const boost::asio::ip::udp::endpoint& sender, const protocol::Peer& peer,
                                               station::Handled& handled);
    // The answer answer_now() returned, sent as its delivery asks.
    station::StrandTask<> send_later(boost::asio::ip::udp::endpoint sender, station::Handled handled);
    protocol::Peer peer_of(const boost::asio::ip::udp::endpoint& sender) const;

    station::Station& station_;
    std::unique_ptr<station::DatagramInbox> inbox_;
    station::StrandDatagramSocket socket_;
    std::uint16_t port_ = 0;
    std::map<boost::asio::ip::udp::endpoint, station::RequestShape> peers_;   // who an Ondemand push goes to
};

}  // namespace slmp::server
