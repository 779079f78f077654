#include "station/datagram_inbox.hpp"

#include <spdlog/spdlog.h>

#include "station/face_inbox.hpp"
#include "station/station.hpp"

namespace slmp::station {

std::unique_ptr<DatagramInbox> datagram_inbox(Station& station, frontends::Unit& unit, const config::PortConfig& port,
                                              protocol::DataCodePolicy policy) {
    if (unit.timed()) return std::make_unique<TimedDatagramInbox>(station, port, policy);
    return std::make_unique<FaceDatagramInbox>(station, unit, port);
}

TimedDatagramInbox::TimedDatagramInbox(Station& station, const config::PortConfig& port, protocol::DataCodePolicy policy)
    : station_(station),
      port_(port),
      policy_(policy),
      at_once_(station.serves_at_once()),
      session_(station.new_session(port)) {}

DatagramTaken TimedDatagramInbox::hand_over(std::span<const std::uint8_t> datagram, const protocol::Peer& peer) {
    if (!at_once_)   // each datagram waits on the clock by itself, from its arrival
        return {{}, held(HeldDatagram(station_, datagram, policy_, session_), peer)};
    DatagramTaken taken{station_.handle(datagram, policy_, session_, peer), std::nullopt};   // the answer built in place
    if (taken.now.relay || taken.now.forward)   // the port receives on while another station or the upstream serves it
        taken.later.emplace(relayed(std::move(taken.now), std::vector<std::uint8_t>(datagram.begin(), datagram.end()), peer));
    return taken;
}

StrandTask<std::optional<Handled>> TimedDatagramInbox::held(HeldDatagram datagram, protocol::Peer peer) {
    if (!co_await datagram.wait() || closed_) co_return std::nullopt;
    auto handled = datagram.serve(session_, peer);
    if (handled.relay || handled.forward)
        co_return co_await relayed(std::move(handled), std::vector<std::uint8_t>(datagram.bytes().begin(), datagram.bytes().end()),
                                   std::move(peer));
    co_return handled;
}

StrandTask<std::optional<Handled>> TimedDatagramInbox::relayed(Handled pending, std::vector<std::uint8_t> datagram,
                                                               protocol::Peer peer) {
    co_return co_await station_.pass_on(std::move(pending), std::move(datagram), policy_, relays_, session_, std::move(peer));
}

FaceDatagramInbox::FaceDatagramInbox(Station& station, frontends::Unit& unit, const config::PortConfig& port)
    : station_(station), unit_(unit), port_(port), session_(station.new_session(port)) {}

DatagramTaken FaceDatagramInbox::hand_over(std::span<const std::uint8_t> datagram, const protocol::Peer& peer) {
    auto [exchange, delivery] = call_face(station_, unit_, nullptr, session_.id, peer, datagram, true);
    DatagramTaken taken;
    auto& outcome = taken.now.outcome;
    outcome.consumed = datagram.size();   // one datagram, one request: nothing after it to speak of
    if (exchange.response.empty()) {
        station_.log().debug("{} UDP {}: datagram of {} byte(s) not answered", unit_.face().log_name(), peer.text(),
                             datagram.size());
        outcome.action = protocol::Outcome::Action::Silent;
        return taken;
    }
    outcome.action = protocol::Outcome::Action::Respond;
    outcome.response.assign(exchange.response.begin(), exchange.response.end());
    taken.now.delivery.delay = delivery.delay;   // the port's next datagram waits behind it, as on a busy unit
    return taken;
}

}  // namespace slmp::station
