// One TCP connection: frames are cut from the stream by their length field, so
// a request split over many segments is assembled and several requests in one
// segment are all answered, in order. A watchdog closes silent connections
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
#include "server/stream_session.hpp"
#include "station/station.hpp"

namespace slmp::server {

class Outbox;
class TimedInput;

class TcpSession final : public StreamSession, public std::enable_shared_from_this<TcpSession> {
public:
    // Called on the station's home strand (the listener's accept loop).
    TcpSession(station::StrandSocket socket, station::Home home, station::Station& station,
               const config::PortConfig& port, std::function<void(StreamSession*)> on_closed,
               std::function<std::size_t()> connections);

    void start() override;
    // From any thread: the server at shutdown, the watchdog, the HTTP API or a
    // Remote RESET (`why` is logged).
    void close() override;
    void close(const std::string& why);
    const protocol::Peer& peer() const override { return peer_; }
    // Ondemand: this connection as a push target; its send() queues the bytes
    // behind the responses already on their way and wakes the session's read.
    station::PushTarget push_target();

private:
    // What serving the whole frames of one read left for serve() to do. One
    // per connection, cleared for each read (the responses keep their capacity).
    struct Served {
        std::size_t consumed = 0;   // bytes of the input they took
        std::vector<std::pair<std::vector<std::uint8_t>, scenarios::Delivery>> responses;   // not yet in the outbox
        bool waiting = false;       // end_of_scan: the rest waits for the END
        bool close = false;
        bool restart = false;       // Remote RESET: the CPU restarts once the answers are out
        bool reset = false;         // a scenario's "reset": RST instead of FIN
        std::string close_reason;
        boost::system::error_code ec;   // a write failed while model timing waited

        void clear() {
            responses.clear();
            *this = {0, std::move(responses)};
        }
        void queue_responses(Outbox& outbox);   // into the outbox, in order; none are left here
    };
    station::StrandTask<> serve();
    void begin_frames();
    bool serve_frame(std::span<const std::uint8_t> input, const station::Service* service, Served& served);
    station::StrandTask<> serve_timed_frames(TimedInput& timed, Served& served,
                                             std::chrono::steady_clock::time_point served_at, bool at_end);
    void close_now();
    station::StrandTask<> watch_deadlines();
    void note_pending(std::size_t pending_bytes, bool consumed_a_frame);
    void resume_watchdog();
    void finish(const std::string& why);
    void push(std::vector<std::uint8_t> bytes);

    station::StrandSocket socket_;   // its executor: the connection's own strand, or the station's
    station::Home home_;   // the station's strand
    station::Station& station_;
    protocol::DataCodePolicy policy_;
    std::chrono::milliseconds idle_timeout_;
    std::chrono::milliseconds partial_frame_timeout_;
    std::chrono::steady_clock::time_point last_activity_;
    // When the first byte of the frame still incomplete in the buffer arrived; unset when none is.
    std::optional<std::chrono::steady_clock::time_point> partial_since_;
    std::size_t pending_bytes_ = 0;
    station::StrandTimer deadline_timer_;
    protocol::Session session_;
    protocol::Peer peer_;   // the client, and the simulator's port it reached
    std::string close_reason_ = "closed by the client";
    std::function<void(StreamSession*)> on_closed_;
    std::function<std::size_t()> connections_;   // the port's open connections (commands per connection)
    bool closed_ = false;
    Outbox* outbox_ = nullptr;            // serve()'s, while it runs
    bool push_pending_ = false;                 // a push cancelled the read; send it
    bool sending_ = false;                      // serve() is writing (the watchdog waits meanwhile)
    // On the station's strand: the last request's shape, for pushes.
    protocol::FrameKind last_kind_ = protocol::FrameKind::E3;
    protocol::Codec last_codec_ = protocol::Codec::Binary;
};

protocol::DataCodePolicy to_policy(config::DataCode code);
// The frame shape (3E/4E, binary/ASCII) a request frame starts with; 3E binary when unknown.
std::pair<protocol::FrameKind, protocol::Codec> request_shape(std::span<const std::uint8_t> frame);

}  // namespace slmp::server
