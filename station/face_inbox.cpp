#include "station/face_inbox.hpp"

#include "station/station.hpp"

namespace slmp::station {

FaceAnswer call_face(Station& station, frontends::Unit& unit, frontends::SessionState* session, std::uint64_t connection,
                     const protocol::Peer& peer, std::span<const std::uint8_t> input, bool datagram) {
    FrontEndCall call(station, unit.face().name(), connection, peer);
    FaceAnswer answer{datagram ? unit.datagram(input, call.gate(), peer) : unit.stream(input, session, call.gate()), {}};
    auto& e = answer.exchange;
    if (e.need_more) return answer;
    answer.delivery = call.finish(input.first(e.consumed), e.command, e.known, e.name, e.code,
                                  {reinterpret_cast<const std::uint8_t*>(e.response.data()), e.response.size()});
    return answer;
}

std::unique_ptr<ConnectionInbox> connection_inbox(Station& station, const Home& home, frontends::Unit& unit,
                                                  const config::PortConfig& port, protocol::DataCodePolicy policy,
                                                  const protocol::Peer& peer, Feed* feed,
                                                  std::function<std::size_t()> connections) {
    if (unit.timed())
        return std::make_unique<Inbox>(station, home, station.new_session(port), peer, policy, feed, std::move(connections));
    return std::make_unique<FaceInbox>(station, unit, peer);
}

FaceInbox::FaceInbox(Station& station, frontends::Unit& unit, const protocol::Peer& peer)
    : station_(station), unit_(unit), state_(unit.new_session(peer)), peer_(peer), id_(station.next_session_id()) {}

StrandTask<> FaceInbox::serve() {
    serve_at_once();
    co_return;
}

void FaceInbox::serve_at_once() {
    served_.responses.clear();   // keeps its capacity
    served_ = {std::move(served_.responses)};
    std::size_t offset = 0;
    while (offset < bytes_.size()) {
        auto [exchange, delivery] =
            call_face(station_, unit_, state_.get(), id_, peer_, std::span<const std::uint8_t>(bytes_).subspan(offset), false);
        if (exchange.need_more) break;
        offset += exchange.consumed;
        if (delivery.close || delivery.reset) {   // the answers before it are sent, then the connection ends
            served_.close = true;
            served_.reset = delivery.reset;
            served_.close_reason = std::string("scenario fault: connection ") + (delivery.reset ? "reset (RST)" : "closed (FIN)");
            break;
        }
        if (!exchange.response.empty() || delivery.delay.count() > 0) {
            scenarios::Delivery later;
            later.delay = delivery.delay;   // and every answer after it, as on a busy unit
            served_.responses.emplace_back(std::vector<std::uint8_t>(exchange.response.begin(), exchange.response.end()), later);
        }
        if (exchange.consumed == 0) break;   // a face that takes nothing would loop forever
    }
    bytes_.erase(bytes_.begin(), bytes_.begin() + static_cast<std::ptrdiff_t>(offset));
    served_.consumed_a_frame = offset > 0;
}

}  // namespace slmp::station
