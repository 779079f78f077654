// The one serve path (docs/architecture.md): a transport reads bytes into its
// connection's Inbox, calls serve(), and writes the answers it leaves. The
// inbox cuts whole frames from the bytes and hands each to the station when
// the station's timing mode says (docs/timing.md): at once (instant), at the
// END after its arrival or when its monitoring timer runs out (end_of_scan),
// at the modelled time (model). A datagram port holds each datagram by itself
// (HeldDatagram). Transports keep only what is theirs: sockets, the watchdog,
// the outbox with its scenario delays, pushes.
#pragma once

#include <chrono>
#include <cstdint>
#include <deque>
#include <functional>
#include <optional>
#include <span>
#include <string>
#include <utility>
#include <vector>

#include "station/asio.hpp"

#include "protocol/engine.hpp"
#include "protocol/peer.hpp"
#include "station/station.hpp"

namespace slmp::station {

// Where a held connection's further bytes come from while it waits on the
// clock (server/socket_feed.hpp for a TCP socket): reading goes on meanwhile,
// so a request that arrives during the wait gets its own arrival time.
class Feed {
public:
    virtual ~Feed() = default;
    virtual bool open() const = 0;
    // Appends what can be read now without blocking; false when nothing was
    // (none ready, the end of the stream or an error: the transport's next read reports those).
    virtual bool read_now(std::vector<std::uint8_t>& into) = 0;
    // Calls ready(true) whenever bytes can be read, ready(false) once the feed
    // closed, while ready() returns true; until stop_watching(), after which
    // it calls nothing.
    virtual void watch(std::function<bool(bool open)> ready) = 0;
    virtual void stop_watching() = 0;
};

// The frame shape (3E/4E, binary/ASCII) a request frame starts with; 3E
// binary when unknown. An Ondemand push to a client takes its last request's shape.
struct RequestShape {
    protocol::FrameKind kind = protocol::FrameKind::E3;
    protocol::Codec codec = protocol::Codec::Binary;
};
RequestShape request_shape(std::span<const std::uint8_t> frame);

// What one serve() left for the transport: answers to write, in order, and
// whether the connection ends.
struct Served {
    std::vector<std::pair<std::vector<std::uint8_t>, scenarios::Delivery>> responses;
    bool close = false;
    bool restart = false;   // Remote RESET: the CPU restarts (Station::restart) once the answers are out
    bool reset = false;     // a scenario's "reset": RST instead of FIN
    std::string close_reason;
    bool consumed_a_frame = false;   // the partial-frame watchdog's reference moves
};

// What a stream connection (server/tcp_session.hpp) needs of its received
// bytes, whatever face it speaks: SLMP's Inbox below, or a protocol face's
// (station/face_inbox.hpp). One session class serves them all.
class ConnectionInbox {
public:
    virtual ~ConnectionInbox() = default;
    virtual std::uint64_t connection() const = 0;   // the connection's id (logs, activity)
    // A read just appended bytes to bytes().
    virtual std::vector<std::uint8_t>& bytes() = 0;
    virtual void received() {}
    // Serves the whole requests it can now; what it served leaves bytes().
    virtual StrandTask<> serve() = 0;
    // What serve() left: answers to write, whether to close.
    virtual Served& served() = 0;
    // Whole requests still wait: serve() again once the answers are written, before reading on.
    virtual bool waiting() const { return false; }
    // Bytes received and not served (a request still incomplete): for the watchdog.
    virtual std::size_t pending() const = 0;
    // Ondemand pushes (docs/timing.md) reach the connection in this shape, its
    // last request's; none: its face takes no pushes.
    virtual std::optional<RequestShape> push_shape() const { return std::nullopt; }
};

// One SLMP stream connection's received bytes and how they are served. Lives
// on the connection's strand; in the timed modes that is the station's (the
// transport's listener arranges it), in instant mode serve() hops there.
class Inbox final : public ConnectionInbox {
public:
    // `session`: the connection's protocol state (Station::new_session);
    // `feed`: the connection's further bytes while it waits on the clock;
    // `connections`: the port's open connections (commands per connection).
    Inbox(Station& station, Home home, protocol::Session session, const protocol::Peer& peer,
          protocol::DataCodePolicy policy, Feed* feed, std::function<std::size_t()> connections);

    std::uint64_t connection() const override { return session_.id; }
    std::vector<std::uint8_t>& bytes() override { return bytes_; }
    void received() override;
    // Serves the whole frames it can now, waiting on the clock as the timing
    // mode says.
    StrandTask<> serve() override;
    Served& served() override { return served_; }
    // Whole requests still wait (their END, or a modelled time after answers
    // that must leave first).
    bool waiting() const override { return waiting_; }
    std::size_t pending() const override { return bytes_.size(); }
    // The last request's frame shape, for pushes.
    std::optional<RequestShape> push_shape() const override { return last_shape_; }

private:
    using TimePoint = std::chrono::steady_clock::time_point;
    std::span<const std::uint8_t> unserved() const { return std::span<const std::uint8_t>(bytes_).subspan(consumed_); }
    void begin_frames();
    // Takes the station's answer to the frame at the start of `frame` (`owned`:
    // its bytes already left bytes()); false when the frames of this turn end here.
    bool take(Handled handled, std::span<const std::uint8_t> frame, bool owned);
    void serve_at_once();
    StrandTask<> serve_timed();      // end_of_scan and model: hold_for_clock(), then what it served leaves bytes_
    // A frame for another station or the upstream (take() kept it in
    // relay_): its trip and answer, then the frames after it.
    StrandTask<> serve_relayed();
    StrandTask<> hold_for_clock();
    // One wait on the clock (ScanLoop::until_end_or) while the feed is read.
    StrandTask<> wait(std::optional<std::uint64_t> seen, std::optional<TimePoint> at);
    bool read_ready();                          // from the feed into bytes_, stamped
    TimePoint arrival(std::size_t end) const;   // when the byte before bytes_[end] arrived
    void drop_served();

    Station& station_;
    Home home_;
    protocol::Session session_;
    const protocol::Peer& peer_;
    protocol::DataCodePolicy policy_;
    Feed* feed_;
    bool at_once_;   // Station::serves_at_once()
    std::function<std::size_t()> connections_;
    std::vector<std::uint8_t> bytes_;
    std::size_t consumed_ = 0;   // bytes of bytes_ served in this turn
    // When each read's bytes arrived (CPU time), by stream offset (timed modes only).
    struct Stamp {
        std::uint64_t end;   // stream offset after the read's last byte
        TimePoint at;
    };
    std::deque<Stamp> stamps_;
    std::uint64_t front_ = 0;   // stream offset of bytes_[0]
    Served served_;
    bool waiting_ = false;
    std::optional<Ticket> held_;   // model: a request whose time has not come
    struct PendingRelay {
        Handled handled;   // with its relay, or forward
        std::vector<std::uint8_t> frame;
    };
    std::optional<PendingRelay> relay_;   // a frame that waits for its trip (serve_relayed)
    Relays relays_;                       // this connection's sessions at the stations routes reach
    RequestShape last_shape_;
};

// A datagram port in the end_of_scan and model modes: one datagram, held on
// the virtual clock from its arrival until the station serves it, while the
// port receives the next.
class HeldDatagram {
public:
    // At its arrival: the time is taken and, in model mode, the request
    // decoded and scheduled (the jitter drawn in arrival order).
    HeldDatagram(Station& station, std::span<const std::uint8_t> datagram, protocol::DataCodePolicy policy,
                 const protocol::Session& session);
    std::span<const std::uint8_t> bytes() const { return ticket_.bytes; }
    // Waits for its time; false when the station stopped meanwhile.
    StrandTask<bool> wait();
    // Then serves it.
    Handled serve(protocol::Session& session, const protocol::Peer& peer);

private:
    Station& station_;
    protocol::DataCodePolicy policy_;
    std::chrono::steady_clock::time_point arrival_;
    Ticket ticket_;   // model: decoded and scheduled; end_of_scan: the bytes only
    bool scheduled_ = false;                    // model
    std::optional<Service> end_of_scan_;        // end_of_scan: wait()'s verdict
};

}  // namespace slmp::station
