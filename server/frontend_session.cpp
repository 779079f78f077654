#include "server/frontend_session.hpp"

#include <spdlog/spdlog.h>

#include "station/log_exception.hpp"

namespace slmp::server {

namespace asio = boost::asio;
using station::StrandTask;
using station::use_strand;

FrontEndSession::FrontEndSession(station::StrandSocket socket, station::Station& station, std::string protocol,
                                 FrontEndHandler handler, const config::PortConfig& port,
                                 std::function<void(StreamSession*)> on_closed)
    : socket_(std::move(socket)),
      station_(station),
      protocol_(std::move(protocol)),
      handler_(std::move(handler)),
      idle_timeout_(port.idle_timeout_ms),
      partial_timeout_(port.partial_frame_timeout_ms),
      deadline_timer_(socket_.get_executor()),
      id_(station.next_session_id()),
      on_closed_(std::move(on_closed)) {
    peer_ = accepted_peer(socket_);
}

void FrontEndSession::start() {
    station_.log().info("{}: {} connected (connection {})", protocol_, peer_.text(), id_);
    last_activity_ = std::chrono::steady_clock::now();
    auto self = shared_from_this();
    std::weak_ptr<FrontEndSession> weak = self;
    station_.activity().opened({id_, peer_, std::chrono::system_clock::now(), 0, [weak](const std::string& why) {
                                    if (auto session = weak.lock()) {
                                        session->close_reason_ = why;
                                        session->close();
                                    }
                                }});
    auto log_crash = station::log_exception(protocol_ + " " + peer_.text() + " session failed", [self] { self->finish(); });
    asio::co_spawn(socket_.get_executor(), serve(), log_crash);
    if (idle_timeout_.count() > 0 || partial_timeout_.count() > 0)
        asio::co_spawn(socket_.get_executor(), watch_deadlines(), log_crash);
}

void FrontEndSession::close() {
    boost::system::error_code ec;
    socket_.shutdown(asio::ip::tcp::socket::shutdown_both, ec);
    socket_.close(ec);
    deadline_timer_.cancel();
}

void FrontEndSession::finish() {
    if (closed_) return;
    closed_ = true;
    close();
    station_.log().info("{}: {} disconnected (connection {}): {}", protocol_, peer_.text(), id_, close_reason_);
    station_.activity().closed(id_, close_reason_);
    on_closed_(this);
}

StrandTask<> FrontEndSession::serve() {
    auto self = shared_from_this();
    std::vector<std::uint8_t> pending;
    std::array<std::uint8_t, 4096> chunk;
    for (;;) {
        boost::system::error_code ec;
        auto n = co_await socket_.async_read_some(asio::buffer(chunk), asio::redirect_error(use_strand, ec));
        if (ec) {
            if (ec != asio::error::eof && ec != asio::error::operation_aborted) close_reason_ = ec.message();
            break;
        }
        last_activity_ = std::chrono::steady_clock::now();
        pending.insert(pending.end(), chunk.begin(), chunk.begin() + static_cast<std::ptrdiff_t>(n));
        // Every whole record now buffered, answered in order, in one write
        // (unless a scenario fault delays one or closes the connection).
        std::string out;
        std::size_t offset = 0;
        bool closing = false, resetting = false;
        while (offset < pending.size()) {
            auto step = handler_(std::span<const std::uint8_t>(pending).subspan(offset), id_, peer_);
            if (step.need_more) break;
            offset += step.consumed;
            if (step.close || step.reset) {
                closing = true;
                resetting = step.reset;
                if (step.reset) socket_.set_option(asio::socket_base::linger(true, 0), ec);
                close_reason_ = std::string("scenario fault: connection ") + (step.reset ? "reset (RST)" : "closed (FIN)");
                break;
            }
            if (step.delay.count() > 0) {
                if (!co_await send(out)) {
                    closing = true;
                    break;
                }
                station::StrandTimer wait(socket_.get_executor(), step.delay);
                co_await wait.async_wait(asio::redirect_error(use_strand, ec));
            }
            out += step.response;
            if (step.consumed == 0) break;   // a handler that takes nothing would loop forever
        }
        if (closing) {
            co_await send(out);
            if (resetting) socket_.close(ec);   // with linger 0 and no shutdown (FIN) first: an RST
            break;
        }
        pending.erase(pending.begin(), pending.begin() + static_cast<std::ptrdiff_t>(offset));
        if (pending.empty()) {
            partial_since_.reset();
        } else if (!partial_since_ || offset > 0) {
            // A request began in this read: the watchdog recomputes its deadline.
            partial_since_ = std::chrono::steady_clock::now();
            if (partial_timeout_.count() > 0) deadline_timer_.cancel();
        }
        if (!co_await send(out)) break;
    }
    finish();
}

StrandTask<bool> FrontEndSession::send(std::string& out) {
    if (out.empty() || closed_) co_return !closed_;
    boost::system::error_code ec;
    co_await asio::async_write(socket_, asio::buffer(out), asio::redirect_error(use_strand, ec));
    out.clear();
    if (ec) {
        close_reason_ = "write failed: " + ec.message();
        co_return false;
    }
    co_return true;
}

StrandTask<> FrontEndSession::watch_deadlines() {
    auto self = shared_from_this();
    using clock = std::chrono::steady_clock;
    while (!closed_) {
        const auto [deadline, partial] = next_deadline(last_activity_, idle_timeout_, partial_since_, partial_timeout_);
        if (clock::now() >= deadline) {
            close_reason_ = partial ? "a started record was not whole " + std::to_string(partial_timeout_.count()) +
                                          " ms after its first byte (partial-frame timeout)"
                                    : "idle for " + std::to_string(idle_timeout_.count()) + " ms (idle timeout)";
            close();
            co_return;
        }
        deadline_timer_.expires_at(deadline);
        boost::system::error_code ec;
        co_await deadline_timer_.async_wait(asio::redirect_error(use_strand, ec));
    }
}

}  // namespace slmp::server
