// A UDP port of a face (frontends/face.hpp: SLMP, the JW-51CM computer link):
// one datagram is one request, answered to the sender's address and port. No
// connection, so one protocol session serves the port. A timed unit's
// datagrams (SLMP's) the station serves when its timing mode says, each held
// by itself meanwhile (station::HeldDatagram); another face's unit answers at once.
#pragma once

#include <array>
#include <cstdint>
#include <map>
#include <optional>

#include "station/asio.hpp"

#include "config/config.hpp"
#include "frontends/face.hpp"
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
    // end_of_scan and model (docs/timing.md): one datagram, held on the
    // virtual clock until it is served, while the port receives the next.
    station::StrandTask<> serve_later(station::HeldDatagram datagram, boost::asio::ip::udp::endpoint sender);
    // A datagram for another station or the upstream (Handled::relay,
    // Handled::forward): its trip, then its answer.
    station::StrandTask<> relay_later(station::Handled pending, std::vector<std::uint8_t> datagram,
                                      boost::asio::ip::udp::endpoint sender);
    // The station's answer to one datagram, sent at once when it can be (no
    // scenario delay or split, room in the send buffer); else returned.
    std::optional<station::Handled> answer_now(std::span<const std::uint8_t> datagram,
                                               const boost::asio::ip::udp::endpoint& sender, const protocol::Peer& peer,
                                               station::Handled handled);
    // The answer answer_now() returned, sent as its delivery asks.
    station::StrandTask<> send_later(boost::asio::ip::udp::endpoint sender, station::Handled handled);
    protocol::Peer peer_of(const boost::asio::ip::udp::endpoint& sender) const;
    // An at-once unit's answer to one datagram (none: not answered).
    std::optional<station::Handled> face_answer(std::span<const std::uint8_t> datagram, const protocol::Peer& peer);

    station::Station& station_;
    frontends::Unit& unit_;
    protocol::DataCodePolicy policy_;
    config::PortConfig config_;   // its settings, for the sessions after a restart
    protocol::Session session_;
    station::StrandDatagramSocket socket_;
    std::uint16_t port_ = 0;
    std::map<boost::asio::ip::udp::endpoint, station::RequestShape> peers_;   // who an Ondemand push goes to
    station::Relays relays_;   // the port's sessions at the stations routes reach
};

}  // namespace slmp::server
