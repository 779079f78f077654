#include "server/tcp_session.hpp"

#include <spdlog/spdlog.h>

#include "server/outbox.hpp"
#include "server/timed_input.hpp"
#include "station/log_exception.hpp"
#include "station/scan_loop.hpp"

namespace slmp::server {

namespace asio = boost::asio;
using station::StrandTask;
using station::use_strand;
using protocol::Outcome;

protocol::DataCodePolicy to_policy(config::DataCode code) {
    switch (code) {
        case config::DataCode::Binary: return protocol::DataCodePolicy::Binary;
        case config::DataCode::Ascii: return protocol::DataCodePolicy::Ascii;
        case config::DataCode::Auto: break;
    }
    return protocol::DataCodePolicy::Auto;
}

std::pair<protocol::FrameKind, protocol::Codec> request_shape(std::span<const std::uint8_t> f) {
    using protocol::Codec;
    using protocol::FrameKind;
    if (f.size() >= 2 && f[0] == 0x54 && f[1] == 0x00) return {FrameKind::E4, Codec::Binary};
    if (f.size() >= 4 && f[0] == '5' && f[1] == '4' && f[2] == '0' && f[3] == '0') return {FrameKind::E4, Codec::Ascii};
    if (f.size() >= 4 && f[0] == '5' && f[1] == '0' && f[2] == '0' && f[3] == '0') return {FrameKind::E3, Codec::Ascii};
    return {FrameKind::E3, Codec::Binary};
}

TcpSession::TcpSession(station::StrandSocket socket, station::Home home, station::Station& station,
                       const config::PortConfig& port, std::function<void(StreamSession*)> on_closed,
                       std::function<std::size_t()> connections)
    : socket_(std::move(socket)),
      home_(std::move(home)),
      station_(station),
      policy_(to_policy(port.data_code)),
      idle_timeout_(port.idle_timeout_ms),
      partial_frame_timeout_(port.partial_frame_timeout_ms),
      deadline_timer_(socket_.get_executor()),
      session_(station.new_session(port)),
      on_closed_(std::move(on_closed)),
      connections_(std::move(connections)) {
    peer_ = accepted_peer(socket_);
}

void TcpSession::start() {
    station_.log().info("{} connected (connection {})", peer_.text(), session_.id);
    last_activity_ = std::chrono::steady_clock::now();
    auto self = shared_from_this();
    std::weak_ptr<TcpSession> weak = self;
    station_.activity().opened({session_.id, peer_, std::chrono::system_clock::now(), 0, [weak](const std::string& why) {
                                    if (auto session = weak.lock()) session->close(why);
                                }});
    auto log_crash = station::log_exception(peer_.text() + " session failed", [self] { self->finish("internal error"); });
    asio::co_spawn(socket_.get_executor(), serve(), log_crash);
    if (idle_timeout_.count() > 0 || partial_frame_timeout_.count() > 0)
        asio::co_spawn(socket_.get_executor(), watch_deadlines(), log_crash);
}

void TcpSession::close() { close(std::string()); }

// On the connection's strand: the caller may be the station's (the API, a
// power cut, a Remote RESET, shutdown).
void TcpSession::close(const std::string& why) {
    asio::dispatch(socket_.get_executor(), [self = shared_from_this(), why] {
        if (!why.empty()) self->close_reason_ = why;
        self->close_now();
    });
}

void TcpSession::close_now() {
    boost::system::error_code ec;
    socket_.shutdown(asio::ip::tcp::socket::shutdown_both, ec);
    socket_.close(ec);
    deadline_timer_.cancel();
}

station::PushTarget TcpSession::push_target() {
    std::weak_ptr<TcpSession> weak = shared_from_this();
    return {session_.id, peer_, last_kind_, last_codec_, [weak](std::vector<std::uint8_t> bytes) {
                if (auto session = weak.lock()) session->push(std::move(bytes));
            }};
}

// From the station's strand (an Ondemand push); the outbox is the connection's.
void TcpSession::push(std::vector<std::uint8_t> bytes) {
    asio::dispatch(socket_.get_executor(), [self = shared_from_this(), bytes = std::move(bytes)]() mutable {
        if (!self->outbox_ || self->closed_) return;
        self->outbox_->add(std::move(bytes), {});
        self->push_pending_ = true;
        if (self->sending_) return;   // serve() sends it after the responses it is writing
        boost::system::error_code ec;
        self->socket_.cancel(ec);     // the read returns operation_aborted; serve() sends, then reads again
    });
}

void TcpSession::finish(const std::string& why) {
    if (closed_) return;
    closed_ = true;
    close_now();
    // The station's side of the goodbye: its activity and the listener's count.
    asio::dispatch(home_, [self = shared_from_this(), why] {
        self->station_.log().info("{} disconnected (connection {}): {}", self->peer_.text(), self->session_.id, why);
        self->station_.activity().closed(self->session_.id, why);
        self->on_closed_(self.get());
    });
}

StrandTask<> TcpSession::serve() {
    auto self = shared_from_this();   // keeps the session alive while it serves
    auto* scan = station_.scan_loop();
    const auto mode = scan ? station_.timing_mode() : config::TimingMode::Instant;
    // Bytes received but not yet a whole frame or not yet served; with a
    // timing mode, stamped with their arrival and read on while waiting.
    std::optional<TimedInput> timed;
    if (mode != config::TimingMode::Instant) timed.emplace(socket_, *scan);
    std::vector<std::uint8_t> plain;
    auto& pending = timed ? timed->bytes() : plain;
    Outbox outbox(socket_);   // responses on their way out, as scenarios ask (server/outbox.hpp)
    outbox_ = &outbox;
    std::array<std::uint8_t, 8192> chunk;
    Served served;   // what each read's frames left to do
    bool waiting_frames = false;   // end_of_scan: whole requests still wait for their END
    for (;;) {
        boost::system::error_code ec;
        if (!waiting_frames) {
            outbox.watch_hold();
            auto n = co_await socket_.async_read_some(asio::buffer(chunk), asio::redirect_error(use_strand, ec));
            if (outbox.hold_expired() && ec == asio::error::operation_aborted) ec = {};   // send what a coalescing hold kept
            if (push_pending_ && ec == asio::error::operation_aborted && socket_.is_open()) ec = {};   // an Ondemand push woke the read
            if (ec) {
                if (ec != asio::error::eof && ec != asio::error::operation_aborted) close_reason_ = ec.message();
                break;
            }
            if (n > 0) last_activity_ = std::chrono::steady_clock::now();
            pending.insert(pending.end(), chunk.begin(), chunk.begin() + static_cast<std::ptrdiff_t>(n));
            if (timed) timed->received(n);
        }
        waiting_frames = false;

        // end_of_scan (docs/timing.md): the first whole request waits for the
        // END after its arrival, or until its monitoring timer runs out;
        // what arrives meanwhile is read and served at the same END.
        bool at_end = false;
        std::chrono::steady_clock::time_point served_at{};
        if (timed) served_at = scan->clock().now();   // the scan's clock is the station's: timed connections live there
        if (mode == config::TimingMode::EndOfScan) {
            const auto seen = scan->scans();
            for (;;) {
                const auto first = station_.next_request(pending, policy_, session_);
                if (!first || scan->stopped() || !socket_.is_open()) break;
                if (scan->scans() > seen) {
                    at_end = true;
                    break;
                }
                std::optional<std::chrono::steady_clock::time_point> deadline;
                if (first->timer.count() > 0) deadline = timed->arrival(first->end) + first->timer;
                if (deadline && scan->clock().now() >= *deadline) break;
                co_await timed->wait(seen, deadline);
            }
            served_at = at_end ? scan->end_time(seen + 1) : scan->clock().now();
        }
        if (!socket_.is_open()) break;

        served.clear();
        if (timed) {
            co_await serve_timed_frames(*timed, served, served_at, at_end);
        } else {
            co_await station::on_home(
                home_,
                [&] {
                    begin_frames();
                    while (served.consumed < pending.size() &&
                           serve_frame(std::span<const std::uint8_t>(pending).subspan(served.consumed), nullptr, served)) {
                    }
                },
                use_strand);
        }
        served.queue_responses(outbox);
        waiting_frames = served.waiting;
        ec = served.ec;
        if (served.close) close_reason_ = served.close_reason;
        if (timed) timed->consumed(served.consumed);
        else pending.erase(pending.begin(), pending.begin() + static_cast<std::ptrdiff_t>(served.consumed));
        note_pending(pending.size(), served.consumed > 0);
        if (ec) {
            close_reason_ = "write failed: " + ec.message();
            break;
        }
        if (!socket_.is_open()) break;
        sending_ = true;
        push_pending_ = false;
        const bool at_once = outbox.send_now(ec);
        if (!at_once) co_await outbox.send(ec);
        while (push_pending_ && !ec) {   // pushes queued while it wrote
            push_pending_ = false;
            co_await outbox.send(ec);
        }
        sending_ = false;
        if (!at_once) resume_watchdog();
        if (ec) {
            close_reason_ = "write failed: " + ec.message();
            break;
        }
        if (served.restart) co_await station::on_home(home_, [this] { station_.restart(); }, use_strand);
        if (served.reset) {   // a scenario's "reset": RST instead of FIN (SO_LINGER 0, no shutdown first)
            socket_.set_option(asio::socket_base::linger(true, 0), ec);
            socket_.close(ec);
        }
        if (served.close) break;
    }
    outbox_ = nullptr;
    finish(close_reason_);
}

void TcpSession::Served::queue_responses(Outbox& outbox) {
    for (auto& [response, delivery] : responses) outbox.add(std::move(response), delivery);
    responses.clear();
}

// Serving the frames of one read begins. They all arrived before any was
// answered, so they stood in the port's receive buffer together: the
// commands-per-connection limit counts them (SLMP Reference Manual §3.3; docs/end-codes.md).
void TcpSession::begin_frames() {
    session_.queued_ahead = 0;
    session_.connections = connections_ ? connections_() : 1;
}

// The frame at the start of `input` served by the station, its answer and
// what follows kept in `served`; false when the frames of this read end here.
bool TcpSession::serve_frame(std::span<const std::uint8_t> input, const station::Service* service, Served& served) {
    auto handled = station_.handle(input, policy_, session_, peer_, service);
    auto& outcome = handled.outcome;
    if (outcome.action == Outcome::Action::NeedMore) return false;
    if (outcome.command != 0) std::tie(last_kind_, last_codec_) = request_shape(input);
    served.consumed += outcome.consumed;
    if (outcome.action == Outcome::Action::Respond || outcome.command != 0) ++session_.queued_ahead;   // not skipped garbage
    if (outcome.action == Outcome::Action::Respond) served.responses.emplace_back(std::move(outcome.response), handled.delivery);
    if (outcome.action == Outcome::Action::Close) {
        served.close = true;
        served.reset = handled.reset;
        served.close_reason = outcome.note;
        return false;
    }
    if (outcome.action == Outcome::Action::Restart) {   // Remote RESET: no answer; every connection closes
        served.close = served.restart = true;
        served.close_reason = "Remote RESET: the CPU restarted";
        return false;
    }
    return true;
}

// end_of_scan and model: the frames of one read, each when the clock says.
// Such a connection lives on the station's strand (TcpListener), so this
// touches the station and the outbox alike.
StrandTask<> TcpSession::serve_timed_frames(TimedInput& timed, Served& served,
                                            std::chrono::steady_clock::time_point served_at, bool at_end) {
    auto* scan = station_.scan_loop();
    const auto mode = station_.timing_mode();
    auto& pending = timed.bytes();
    begin_frames();
    while (served.consumed < pending.size()) {
        auto input = std::span<const std::uint8_t>(pending).subspan(served.consumed);
        std::optional<station::Service> service;
        const auto queued = station_.next_request(input, policy_, session_);
        if (!queued && mode == config::TimingMode::EndOfScan && !at_end) break;
        if (queued && queued->start == 0) {
            const auto arrival = timed.arrival(served.consumed + queued->end);
            if (mode == config::TimingMode::EndOfScan) {
                service = station::Station::end_of_scan_service(arrival, queued->timer, served_at, at_end);
                if (!service) {
                    served.waiting = true;   // this one and those behind it wait for END
                    break;
                }
            } else if ((service = station_.model_service(input, policy_, session_, arrival))) {
                // model: executed and answered at the modelled time; the
                // answers before it leave first, and reading goes on.
                if (service->at > scan->clock().now()) {
                    served.queue_responses(*outbox_);
                    sending_ = true;
                    co_await outbox_->send(served.ec);
                    sending_ = false;
                    resume_watchdog();
                }
                while (!served.ec && service->at > scan->clock().now() && socket_.is_open() && !scan->stopped())
                    co_await timed.wait(std::nullopt, service->at);
                if (served.ec || !socket_.is_open()) break;
                input = std::span<const std::uint8_t>(pending).subspan(served.consumed);   // it may have grown
            }
        }
        if (!serve_frame(input, service ? &*service : nullptr, served)) break;
    }
}

void TcpSession::note_pending(std::size_t pending_bytes, bool consumed_a_frame) {
    pending_bytes_ = pending_bytes;
    if (pending_bytes == 0) {
        partial_since_.reset();
        return;
    }
    // The frame now incomplete began in this read when none was pending before or
    // when the one that was pending has just completed; a frame that keeps
    // trickling in keeps its first byte's time, so dribbling cannot extend it.
    if (partial_since_ && !consumed_a_frame) return;
    partial_since_ = std::chrono::steady_clock::now();
    if (partial_frame_timeout_.count() > 0) deadline_timer_.cancel();   // the watchdog recomputes its deadline
}

// While the connection waits on its own write (the client reads slowly) it
// reads nothing, so a frame left unfinished in its buffer is not the client's
// doing: the partial-frame deadline waits (the idle one does not: a client that
// never reads still leaves) and both count again from the write's end.
void TcpSession::resume_watchdog() {
    last_activity_ = std::chrono::steady_clock::now();
    if (partial_since_) partial_since_ = last_activity_;
    deadline_timer_.cancel();
}

StrandTask<> TcpSession::watch_deadlines() {
    auto self = shared_from_this();
    using clock = std::chrono::steady_clock;
    while (!closed_) {
        const auto [deadline, partial] = next_deadline(last_activity_, idle_timeout_, sending_ ? std::nullopt : partial_since_,
                                                       partial_frame_timeout_);
        if (clock::now() >= deadline) {
            if (partial) {
                close_reason_ = "a started frame was not whole " + std::to_string(partial_frame_timeout_.count()) +
                                " ms after its first byte (partial-frame timeout; " + std::to_string(pending_bytes_) +
                                " byte(s) pending)";
                station_.log().warn("{} connection {}: {}", peer_.text(), session_.id, close_reason_);
            } else {
                close_reason_ = "idle for " + std::to_string(idle_timeout_.count()) + " ms (idle timeout)";
            }
            close();   // serve() sees the error and finishes
            co_return;
        }
        deadline_timer_.expires_at(deadline);
        boost::system::error_code ec;
        co_await deadline_timer_.async_wait(asio::redirect_error(use_strand, ec));
    }
}

}  // namespace slmp::server
