// One TCP connection to a front end's port (the host link, the JW-51CM
// computer link): requests are cut from the stream by the front end's framer
// (split requests are assembled, coalesced ones answered in order, in one
// write). The idle and partial-request timeouts are the SLMP port's.
#pragma once

#include <chrono>
#include <functional>
#include <memory>
#include <optional>
#include <string>

#include "station/asio.hpp"

#include "config/config.hpp"
#include "server/stream_session.hpp"
#include "station/station.hpp"

namespace slmp::server {

// What the front end made of the front of the stream.
struct FrontEndStep {
    bool need_more = false;      // a request has begun but is not whole
    std::size_t consumed = 0;    // bytes taken (a request, or garbage dropped)
    std::string response;        // bytes to send back (empty: none)
    // A scenario fault's (station/frontend_call.hpp): the answers before this one
    // are sent, then this one waits `delay`; or the connection closes instead.
    std::chrono::microseconds delay{0};
    bool close = false, reset = false;
};
// Called with the bytes buffered so far, the connection's id and peer; owns
// the connection's protocol state.
using FrontEndHandler = std::function<FrontEndStep(std::span<const std::uint8_t> pending, std::uint64_t connection,
                                                   const protocol::Peer& peer)>;

class FrontEndSession final : public StreamSession, public std::enable_shared_from_this<FrontEndSession> {
public:
    // `protocol` names the front end in logs ("host link", "JW-51CM").
    FrontEndSession(station::StrandSocket socket, station::Station& station, std::string protocol,
                    FrontEndHandler handler, const config::PortConfig& port, std::function<void(StreamSession*)> on_closed);

    void start() override;
    void close() override;
    const protocol::Peer& peer() const override { return peer_; }

private:
    station::StrandTask<> serve();
    station::StrandTask<> watch_deadlines();
    station::StrandTask<bool> send(std::string& out);   // false: the write failed
    void finish();

    station::StrandSocket socket_;
    station::Station& station_;
    std::string protocol_;
    FrontEndHandler handler_;
    std::chrono::milliseconds idle_timeout_;
    std::chrono::milliseconds partial_timeout_;
    std::chrono::steady_clock::time_point last_activity_;
    std::optional<std::chrono::steady_clock::time_point> partial_since_;   // a record begun, not yet whole
    station::StrandTimer deadline_timer_;
    std::uint64_t id_;
    protocol::Peer peer_;
    std::string close_reason_ = "closed by the client";
    std::function<void(StreamSession*)> on_closed_;
    bool closed_ = false;
};

}  // namespace slmp::server
