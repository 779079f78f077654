#include "server/tcp_session.hpp"

#include <spdlog/spdlog.h>

#include "server/outbox.hpp"
#include "station/log_exception.hpp"
#include "station/scan_loop.hpp"

namespace slmp::server {

namespace asio = boost::asio;
using station::StrandTask;
using station::use_strand;

namespace {

// The client of an accepted connection and the port it reached ("?" when the
// socket no longer knows); also turns Nagle off, as every session answers at once.
protocol::Peer accepted_peer(station::StrandSocket& socket) {
    boost::system::error_code ec;
    protocol::Peer peer;
    peer.transport = protocol::Transport::Tcp;
    if (auto remote = socket.remote_endpoint(ec); ec) {
        peer.address = "?";
    } else {
        peer.address = remote.address().to_string();
        peer.port = remote.port();
        if (remote.address().is_v4()) peer.ipv4 = remote.address().to_v4().to_bytes();
    }
    peer.local_port = socket.local_endpoint(ec).port();
    socket.set_option(boost::asio::ip::tcp::no_delay(true), ec);
    return peer;
}

// When a connection's watchdog fires: `idle` after its last activity, or
// `partial` after the first byte of a request still not whole, whichever is
// first (a zero duration is off). `partial` in the answer says which one.
struct Deadline {
    std::chrono::steady_clock::time_point at = std::chrono::steady_clock::time_point::max();
    bool partial = false;
};
Deadline next_deadline(std::chrono::steady_clock::time_point last_activity, std::chrono::milliseconds idle,
                       std::optional<std::chrono::steady_clock::time_point> partial_since, std::chrono::milliseconds partial) {
    Deadline d;
    if (idle.count() > 0) d.at = last_activity + idle;
    if (partial.count() > 0 && partial_since && *partial_since + partial < d.at) d = {*partial_since + partial, true};
    return d;
}

}  // namespace

protocol::DataCodePolicy to_policy(config::DataCode code) {
    switch (code) {
        case config::DataCode::Binary: return protocol::DataCodePolicy::Binary;
        case config::DataCode::Ascii: return protocol::DataCodePolicy::Ascii;
        case config::DataCode::Auto: break;
    }
    return protocol::DataCodePolicy::Auto;
}

TcpSession::TcpSession(station::StrandSocket socket, station::Home home, station::Station& station,
                       const config::PortConfig& port, std::function<void(TcpSession*)> on_closed,
                       const InboxMaker& make_inbox, std::string face)
    : socket_(std::move(socket)),
      home_(std::move(home)),
      station_(station),
      idle_timeout_(port.idle_timeout_ms),
      partial_frame_timeout_(port.partial_frame_timeout_ms),
      deadline_timer_(socket_.get_executor()),
      face_(std::move(face)),
      on_closed_(std::move(on_closed)) {
    peer_ = accepted_peer(socket_);
    inbox_ = make_inbox(peer_, &feed_);
}

std::string TcpSession::who() const {
    return face_.empty() ? peer_.text() : face_ + ": " + peer_.text();
}

void TcpSession::start() {
    const auto id = inbox_->connection();
    station_.log().info("{} connected (connection {})", who(), id);
    last_activity_ = std::chrono::steady_clock::now();
    auto self = shared_from_this();
    std::weak_ptr<TcpSession> weak = self;
    station_.activity().opened({id, peer_, std::chrono::system_clock::now(), 0, [weak](const std::string& why) {
                                    if (auto session = weak.lock()) session->close(why);
                                }});
    auto log_crash = station::log_exception(who() + " session failed", [self] { self->finish("internal error"); });
    asio::co_spawn(socket_.get_executor(), serve(), log_crash);
    if (idle_timeout_.count() > 0 || partial_frame_timeout_.count() > 0)
        asio::co_spawn(socket_.get_executor(), watch_deadlines(), log_crash);
}

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

std::optional<station::PushTarget> TcpSession::push_target() {
    const auto shape = inbox_->push_shape();
    if (!shape) return std::nullopt;   // its face takes no Ondemand pushes
    std::weak_ptr<TcpSession> weak = shared_from_this();
    return station::PushTarget{inbox_->connection(), peer_, shape->kind, shape->codec, [weak](std::vector<std::uint8_t> bytes) {
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
        const auto id = self->inbox_->connection();
        self->station_.log().info("{} disconnected (connection {}): {}", self->who(), id, why);
        self->station_.activity().closed(id, why);
        self->on_closed_(self.get());
    });
}

StrandTask<> TcpSession::serve() {
    auto self = shared_from_this();   // keeps the session alive while it serves
    Outbox outbox(socket_);   // responses on their way out, as scenarios ask (server/outbox.hpp)
    outbox_ = &outbox;
    std::array<std::uint8_t, 8192> chunk;
    for (;;) {
        boost::system::error_code ec;
        if (!inbox_->waiting()) {   // else whole requests wait still: serve them before reading on
            outbox.watch_hold();
            auto n = co_await socket_.async_read_some(asio::buffer(chunk), asio::redirect_error(use_strand, ec));
            if (outbox.hold_expired() && ec == asio::error::operation_aborted) ec = {};   // send what a coalescing hold kept
            if (push_pending_ && ec == asio::error::operation_aborted && socket_.is_open()) ec = {};   // an Ondemand push woke the read
            if (ec) {
                if (ec != asio::error::eof && ec != asio::error::operation_aborted) close_reason_ = ec.message();
                break;
            }
            if (n > 0) {
                last_activity_ = std::chrono::steady_clock::now();
                inbox_->bytes().insert(inbox_->bytes().end(), chunk.begin(), chunk.begin() + static_cast<std::ptrdiff_t>(n));
                inbox_->received();
            }
        }
        if (!socket_.is_open()) break;
        co_await inbox_->serve();
        if (!socket_.is_open()) break;
        auto& served = inbox_->served();
        for (auto& [response, delivery] : served.responses) outbox.add(std::move(response), delivery);
        if (served.close) close_reason_ = served.close_reason;
        note_pending(inbox_->pending(), served.consumed_a_frame);
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
                station_.log().warn("{} connection {}: {}", who(), inbox_->connection(), close_reason_);
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
