// One TCP connection: frames are cut from the stream by their length field, so
// a request split over many segments is assembled and several requests in one
// segment are all answered, in order. A watchdog closes silent connections
// (idle timeout) and connections whose started frame stays incomplete
// (partial-frame timeout), so a half-sent header cannot hold a slot for long.
#pragma once

#include <chrono>
#include <functional>
#include <memory>
#include <optional>
#include <string>

#include "station/asio.hpp"

#include "config/config.hpp"
#include "protocol/peer.hpp"
#include "server/stream_session.hpp"
#include "station/station.hpp"

namespace slmp::server {

class Outbox;

class TcpSession final : public StreamSession, public std::enable_shared_from_this<TcpSession> {
public:
    TcpSession(boost::asio::ip::tcp::socket socket, station::Station& station, const config::PortConfig& port,
               std::function<void(StreamSession*)> on_closed, std::function<std::size_t()> connections);

    void start() override;
    void close() override;   // from the server at shutdown, or the watchdog
    void close(const std::string& why);   // from the HTTP API; `why` is logged
    const protocol::Peer& peer() const override { return peer_; }
    // Ondemand: this connection as a push target; its send() queues the bytes
    // behind the responses already on their way and wakes the session's read.
    station::PushTarget push_target();

private:
    boost::asio::awaitable<void> serve();
    boost::asio::awaitable<void> watch_deadlines();
    void note_pending(std::size_t pending_bytes, bool consumed_a_frame);
    void finish(const std::string& why);
    void push(std::vector<std::uint8_t> bytes);

    boost::asio::ip::tcp::socket socket_;
    station::Station& station_;
    protocol::DataCodePolicy policy_;
    std::chrono::milliseconds idle_timeout_;
    std::chrono::milliseconds partial_frame_timeout_;
    std::chrono::steady_clock::time_point last_activity_;
    // When the first byte of the frame still incomplete in the buffer arrived; unset when none is.
    std::optional<std::chrono::steady_clock::time_point> partial_since_;
    std::size_t pending_bytes_ = 0;
    boost::asio::steady_timer deadline_timer_;
    protocol::Session session_;
    protocol::Peer peer_;   // the client, and the simulator's port it reached
    std::string close_reason_ = "closed by the client";
    std::function<void(StreamSession*)> on_closed_;
    std::function<std::size_t()> connections_;   // the port's open connections (commands per connection)
    bool closed_ = false;
    Outbox* outbox_ = nullptr;            // serve()'s, while it runs
    bool push_pending_ = false;                 // a push cancelled the read; send it
    bool sending_ = false;                      // serve() is in outbox.send()
    protocol::FrameKind last_kind_ = protocol::FrameKind::E3;   // the last request's shape, for pushes
    protocol::Codec last_codec_ = protocol::Codec::Binary;
};

protocol::DataCodePolicy to_policy(config::DataCode code);
// The frame shape (3E/4E, binary/ASCII) a request frame starts with; 3E binary when unknown.
std::pair<protocol::FrameKind, protocol::Codec> request_shape(std::span<const std::uint8_t> frame);

}  // namespace slmp::server
