// A protocol face's stream connection (frontends/face.hpp: the host link, the
// JW-51CM computer link), served by the same session class as SLMP
// (server/tcp_session.hpp): its unit cuts the requests from the stream
// (split ones assembled, coalesced ones answered in order) and answers each
// at once, in every timing mode; a scenario fault delays an answer or closes
// the connection instead.
#pragma once

#include <cstdint>
#include <functional>
#include <memory>
#include <span>
#include <vector>

#include "station/asio.hpp"

#include "frontends/face.hpp"
#include "protocol/peer.hpp"
#include "station/frontend_call.hpp"
#include "station/inbox.hpp"

namespace slmp::station {

// One request handed to a face, wrapped in a FrontEndCall (faults, recording,
// activity): the face's exchange, and what the transport does with its answer.
struct FaceAnswer {
    frontends::Exchange exchange;
    FrontEndCall::Delivery delivery;
};
// `session`: the connection's state (null for a datagram, which `datagram` says).
FaceAnswer call_face(Station& station, frontends::Unit& unit, frontends::SessionState* session, std::uint64_t connection,
                     const protocol::Peer& peer, std::span<const std::uint8_t> input, bool datagram);

// A new stream connection's inbox on a port of `unit`'s: the station's timed
// Inbox when the unit is timed (frontends::Unit::timed: SLMP), else a
// FaceInbox. `port`: the port's settings; `feed` and `connections` as Inbox takes them.
std::unique_ptr<ConnectionInbox> connection_inbox(Station& station, const Home& home, frontends::Unit& unit,
                                                  const config::PortConfig& port, protocol::DataCodePolicy policy,
                                                  const protocol::Peer& peer, Feed* feed,
                                                  std::function<std::size_t()> connections);

class FaceInbox final : public ConnectionInbox {
public:
    // On the station's strand, as every call after it (the listener puts the socket there).
    FaceInbox(Station& station, frontends::Unit& unit, const protocol::Peer& peer);

    std::uint64_t connection() const override { return id_; }
    std::vector<std::uint8_t>& bytes() override { return bytes_; }
    StrandTask<> serve() override;
    Served& served() override { return served_; }
    std::size_t pending() const override { return bytes_.size(); }

private:
    void serve_at_once();

    Station& station_;
    frontends::Unit& unit_;
    std::unique_ptr<frontends::SessionState> state_;   // the connection's own (the host link's QQMR list)
    const protocol::Peer& peer_;
    std::uint64_t id_;
    std::vector<std::uint8_t> bytes_;
    Served served_;
};

}  // namespace slmp::station
