// The datagram side of the one serve path (docs/architecture.md), as
// ConnectionInbox (station/inbox.hpp) is the stream side: a datagram port
// (server/udp_listener.cpp) reads a datagram, hands it over here and writes
// the answer it gets back — now, or later when the station holds it on the
// clock (end_of_scan, model: HeldDatagram) or sends it down a route or to the
// upstream. The port knows no timing mode and no face.
#pragma once

#include <cstdint>
#include <memory>
#include <optional>
#include <span>
#include <vector>

#include "station/asio.hpp"

#include "config/config.hpp"
#include "frontends/face.hpp"
#include "protocol/peer.hpp"
#include "station/inbox.hpp"

namespace slmp::station {

// What handing one datagram over gave: its answer now, or a task that gives
// it later (nullopt then: the station stopped meanwhile, nothing to send)
// while the port receives the next datagram.
struct DatagramTaken {
    Handled now;   // when there is no `later`
    std::optional<StrandTask<std::optional<Handled>>> later;
};

class DatagramInbox {
public:
    virtual ~DatagramInbox() = default;
    // One datagram from `peer`, on the station's strand.
    virtual DatagramTaken hand_over(std::span<const std::uint8_t> datagram, const protocol::Peer& peer) = 0;
    // The port's session id (logs, activity, Ondemand push targets).
    virtual std::uint64_t session_id() const = 0;
    // After a Remote RESET: the port's session starts afresh (locked again when
    // the CPU has a remote password).
    virtual void restart() = 0;
    // The port closed: a datagram still held on the clock is not served.
    void close() { closed_ = true; }

protected:
    bool closed_ = false;
};

// A datagram port's inbox for `unit`: the station's timed one when the unit is
// timed (frontends::Unit::timed: SLMP), else the face's, which answers at once.
std::unique_ptr<DatagramInbox> datagram_inbox(Station& station, frontends::Unit& unit, const config::PortConfig& port,
                                              protocol::DataCodePolicy policy);

// SLMP's datagrams: served at once in instant mode, each held by itself on
// the clock from its arrival in end_of_scan and model; a routed or proxied
// one after its trip.
class TimedDatagramInbox final : public DatagramInbox {
public:
    TimedDatagramInbox(Station& station, const config::PortConfig& port, protocol::DataCodePolicy policy);

    DatagramTaken hand_over(std::span<const std::uint8_t> datagram, const protocol::Peer& peer) override;
    std::uint64_t session_id() const override { return session_.id; }
    void restart() override { session_ = station_.new_session(port_); }

private:
    StrandTask<std::optional<Handled>> held(HeldDatagram datagram, protocol::Peer peer);
    StrandTask<std::optional<Handled>> relayed(Handled pending, std::vector<std::uint8_t> datagram, protocol::Peer peer);

    Station& station_;
    config::PortConfig port_;   // its settings, for the sessions after a restart
    protocol::DataCodePolicy policy_;
    bool at_once_;              // Station::serves_at_once()
    protocol::Session session_;
    Relays relays_;             // the port's sessions at the stations routes reach
};

// Another face's datagrams (the JW-51CM computer link): its unit answers each
// at once, in every timing mode; a scenario fault may delay the answer.
class FaceDatagramInbox final : public DatagramInbox {
public:
    FaceDatagramInbox(Station& station, frontends::Unit& unit, const config::PortConfig& port);

    DatagramTaken hand_over(std::span<const std::uint8_t> datagram, const protocol::Peer& peer) override;
    std::uint64_t session_id() const override { return session_.id; }
    void restart() override { session_ = station_.new_session(port_); }

private:
    Station& station_;
    frontends::Unit& unit_;
    config::PortConfig port_;
    protocol::Session session_;   // only its id: the face keeps no per-port state
};

}  // namespace slmp::station
