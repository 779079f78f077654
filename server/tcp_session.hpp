// One TCP connection, whatever face it speaks: it reads bytes into its inbox,
// which cuts requests from the stream and has the station serve them (a timed
// unit's, SLMP's: when the timing mode says, station/inbox.hpp; another
// face's: at once, station/face_inbox.hpp), and writes the answers. A request
// split over many segments is assembled and several requests in one segment
// are all answered, in order. A watchdog closes silent connections
// (idle timeout) and connections whose started frame stays incomplete
// (partial-frame timeout), so a half-sent header cannot hold a slot for long.
//
// Threads: the connection's own state (socket, outbox, watchdog) lives on its
// socket's executor; what touches the station (serving the frames of a read,
// its activity reports, the listener's bookkeeping) runs on the station's
// home strand. In the instant timing mode the two differ, so connections of
// one station are read and written by several threads (docs/plants.md).
#pragma once

#include <chrono>
#include <functional>
#include <memory>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "station/asio.hpp"

#include "config/config.hpp"
#include "protocol/peer.hpp"
#include "scenarios/faults.hpp"
#include "server/socket_feed.hpp"
#include "station/inbox.hpp"
#include "station/station.hpp"

namespace slmp::server {

class Outbox;

// Makes a connection's inbox once its peer is known (station::connection_inbox);
// `feed` is the connection's further bytes while a timed inbox waits on the clock.
using InboxMaker =
    std::function<std::unique_ptr<station::ConnectionInbox>(const protocol::Peer& peer, station::Feed* feed)>;

class TcpSession final : public std::enable_shared_from_this<TcpSession> {
public:
    // Called on the station's home strand (the listener's accept loop).
    // `face`: the face's log name before its log lines ("host link"; empty: none).
    TcpSession(station::StrandSocket socket, station::Home home, station::Station& station,
               const config::PortConfig& port, std::function<void(TcpSession*)> on_closed, const InboxMaker& make_inbox,
               std::string face = {});

    void start();
    // From any thread: the server at shutdown, the watchdog, the HTTP API or a
    // Remote RESET (`why` is logged).
    void close(const std::string& why = {});
    const protocol::Peer& peer() const { return peer_; }
    // Ondemand: this connection as a push target (none when its inbox takes no pushes);
    // its send() queues the bytes behind the responses already on their way
    // and wakes the session's read.
    std::optional<station::PushTarget> push_target();

private:
    station::StrandTask<> serve();
    void close_now();
    station::StrandTask<> watch_deadlines();
    void note_pending(std::size_t pending_bytes, bool consumed_a_frame);
    void resume_watchdog();
    void finish(const std::string& why);
    void push(std::vector<std::uint8_t> bytes);
    std::string who() const;   // "host link: 127.0.0.1:40000" / "127.0.0.1:40000" for its log lines

    station::StrandSocket socket_;   // its executor: the connection's own strand, or the station's
    station::Home home_;   // the station's strand
    station::Station& station_;
    std::chrono::milliseconds idle_timeout_;
    std::chrono::milliseconds partial_frame_timeout_;
    std::chrono::steady_clock::time_point last_activity_;
    // When the first byte of the frame still incomplete in the buffer arrived; unset when none is.
    std::optional<std::chrono::steady_clock::time_point> partial_since_;
    std::size_t pending_bytes_ = 0;
    station::StrandTimer deadline_timer_;
    std::string face_;
    protocol::Peer peer_;   // the client, and the simulator's port it reached
    std::string close_reason_ = "closed by the client";
    std::function<void(TcpSession*)> on_closed_;
    bool closed_ = false;
    Outbox* outbox_ = nullptr;            // serve()'s, while it runs
    bool push_pending_ = false;                 // a push cancelled the read; send it
    bool sending_ = false;                      // serve() is writing (the watchdog waits meanwhile)
    SocketFeed feed_{socket_};   // the inbox's further bytes while it waits on the clock
    std::unique_ptr<station::ConnectionInbox> inbox_;   // received bytes and how they are served
};

protocol::DataCodePolicy to_policy(config::DataCode code);

}  // namespace slmp::server
