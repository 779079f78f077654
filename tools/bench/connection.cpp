#include "tools/bench/connection.hpp"

#include <boost/asio/co_spawn.hpp>
#include <boost/asio/redirect_error.hpp>
#include <boost/asio/steady_timer.hpp>
#include <boost/asio/use_awaitable.hpp>

#include <cstring>
#include <exception>
#include <iostream>
#include <memory>
#include <vector>

#include "protocol/client.hpp"
#include "tools/bench/transport.hpp"

namespace slmp::bench {

namespace asio = boost::asio;
namespace client = protocol::client;

namespace {

constexpr std::size_t kBufferBytes = 64 * 1024;   // far above the largest response (~3.9 KB)
constexpr auto kReconnectPause = std::chrono::milliseconds(100);

// A request in flight. With 4E the slot index is the serial number.
struct Slot {
    bool busy = false;
    bool measured = false;
    std::size_t op = 0;
    Clock::time_point sent{};
};

class Connection {
public:
    Connection(const asio::any_io_executor& executor, RunState& state, unsigned index, std::unique_ptr<Transport> t)
        : state_(state),
          transport_(std::move(t)),
          watchdog_(executor),
          pause_(executor),
          slots_(state.workload.kind == protocol::FrameKind::E4 ? state.depth : 1),
          next_op_(index % state.workload.operations.size()),
          buffer_(kBufferBytes) {}

    awaitable<void> run();
    awaitable<void> watch();

private:
    awaitable<bool> session();
    awaitable<bool> fill();
    bool complete(const client::Response& response, Clock::time_point now);
    bool consume(Clock::time_point now);
    void fail(Slot& slot, ErrorKind kind, Clock::time_point now);
    void fail_all(ErrorKind kind, Clock::time_point now);
    Slot* oldest();
    Clock::time_point deadline();

    RunState& state_;
    std::unique_ptr<Transport> transport_;
    asio::steady_timer watchdog_;
    asio::steady_timer pause_;
    std::vector<Slot> slots_;
    unsigned in_flight_ = 0;
    std::uint64_t answered_ = 0;        // responses matched since the transport was opened
    std::size_t next_op_;
    std::vector<std::uint8_t> buffer_;
    std::size_t head_ = 0, tail_ = 0;   // unparsed bytes are buffer_[head_, tail_)
    Clock::time_point opening_since_ = Clock::time_point::max();
    bool timed_out_ = false;
    bool done_ = false;
};

// Reconnects until the run is over. The first connect must succeed: if the
// target is not there at all, the run stops with a message instead of
// counting connect failures for the whole duration.
awaitable<void> Connection::run() {
    bool first = true;
    for (;;) {
        auto now = Clock::now();
        if (state_.control.over(now)) break;
        opening_since_ = now;
        timed_out_ = false;
        error_code ec = co_await transport_->open();
        opening_since_ = Clock::time_point::max();
        if (ec) {
            if (first) {
                if (state_.fatal.empty())
                    state_.fatal = "cannot connect: " + (timed_out_ ? std::string("timed out") : ec.message());
                state_.control.stop(Clock::now());
                break;
            }
            // A failed reconnect costs one request of the budget, so --requests stays bounded.
            bool measured = false;
            if (!state_.control.claim(Clock::now(), measured)) break;
            if (measured) {
                state_.recorders[next_op_].error(ErrorKind::Connection);
                state_.control.outcome(Clock::now());
            }
            pause_.expires_after(kReconnectPause);
            co_await pause_.async_wait(asio::redirect_error(asio::use_awaitable, ec));
            continue;
        }
        first = false;
        answered_ = 0;
        bool finished = co_await session();
        transport_->close();
        if (finished) break;
        if (answered_ == 0 && !timed_out_) {   // refused at once (UDP port closed, reset): do not spin
            pause_.expires_after(kReconnectPause);
            co_await pause_.async_wait(asio::redirect_error(asio::use_awaitable, ec));
        }
    }
    done_ = true;
    watchdog_.cancel();
    if (--state_.live == 0 && state_.all_done) state_.all_done();
}

// The request loop on one open transport. True when the run is over and
// nothing is in flight; false when the transport must be reopened.
awaitable<bool> Connection::session() {
    head_ = tail_ = 0;
    if (!co_await fill()) {
        fail_all(timed_out_ ? ErrorKind::Timeout : ErrorKind::Connection, Clock::now());
        co_return false;
    }
    while (in_flight_ > 0) {
        if (tail_ == buffer_.size()) {   // no response is this large: the stream is lost
            fail_all(ErrorKind::Garbage, Clock::now());
            co_return false;
        }
        Received r = co_await transport_->receive(std::span(buffer_).subspan(tail_));
        auto now = Clock::now();
        if (r.error) {
            fail_all(timed_out_ ? ErrorKind::Timeout : ErrorKind::Connection, now);
            co_return false;
        }
        tail_ += r.size;
        if (!consume(now)) co_return false;
        if (!co_await fill()) {
            fail_all(timed_out_ ? ErrorKind::Timeout : ErrorKind::Connection, Clock::now());
            co_return false;
        }
    }
    co_return true;
}

// Sends until `depth` requests are in flight or the run is over.
awaitable<bool> Connection::fill() {
    while (in_flight_ < slots_.size()) {
        bool measured = false;
        auto now = Clock::now();
        if (!state_.control.claim(now, measured)) break;
        std::size_t index = 0;
        while (slots_[index].busy) ++index;
        Slot& slot = slots_[index];
        slot = Slot{true, measured, next_op_, now};
        ++in_flight_;
        next_op_ = (next_op_ + 1) % state_.workload.operations.size();
        const auto& bytes = state_.workload.operations[slot.op].requests[index];
        if (co_await transport_->send(bytes)) co_return false;
    }
    co_return true;
}

// Takes every whole response out of the buffer. False when the stream has to
// be dropped (TCP bytes that are not a response we are waiting for).
bool Connection::consume(Clock::time_point now) {
    bool lost = false;
    while (head_ < tail_) {
        bool garbage = false;
        auto response = client::parse_response(std::span(buffer_).subspan(head_, tail_ - head_), &garbage);
        if (!response) {
            lost = garbage;
            break;
        }
        head_ += response->size;
        if (!complete(*response, now)) {
            lost = true;
            break;
        }
    }
    // A datagram holds exactly one frame: anything left over is not a response.
    if (transport_->datagram() && head_ != tail_) lost = true;
    if (lost) {
        if (Slot* slot = oldest()) fail(*slot, ErrorKind::Garbage, now);
        if (!transport_->datagram()) {
            fail_all(ErrorKind::Connection, now);
            return false;
        }
        head_ = tail_ = 0;
    }
    if (head_ == tail_) {
        head_ = tail_ = 0;
    } else if (head_ > buffer_.size() / 2) {
        std::memmove(buffer_.data(), buffer_.data() + head_, tail_ - head_);
        tail_ -= head_;
        head_ = 0;
    }
    return true;
}

// Matches one response to its request and records the outcome. False when
// nothing in flight matches (wrong frame type or codec, unknown serial).
bool Connection::complete(const client::Response& response, Clock::time_point now) {
    const auto& workload = state_.workload;
    if (response.header.kind != workload.kind || response.header.codec != workload.codec) return false;
    Slot* slot = nullptr;
    if (workload.kind == protocol::FrameKind::E4) {
        if (response.header.serial >= slots_.size() || !slots_[response.header.serial].busy) return false;
        slot = &slots_[response.header.serial];
    } else {
        slot = oldest();   // 3E: one request in flight, answered in order
        if (!slot) return false;
    }
    slot->busy = false;
    --in_flight_;
    ++answered_;
    if (!slot->measured) return true;
    Recorder& recorder = state_.recorders[slot->op];
    if (response.end_code != 0) {
        recorder.error(ErrorKind::EndCode, response.end_code);
    } else if (response.data.size() != workload.operations[slot->op].response_data) {
        recorder.error(ErrorKind::Garbage);
    } else {
        recorder.ok(now - slot->sent);
    }
    state_.control.outcome(now);
    return true;
}

void Connection::fail(Slot& slot, ErrorKind kind, Clock::time_point now) {
    if (!slot.busy) return;
    slot.busy = false;
    --in_flight_;
    if (!slot.measured) return;
    state_.recorders[slot.op].error(kind);
    state_.control.outcome(now);
}

void Connection::fail_all(ErrorKind kind, Clock::time_point now) {
    for (auto& slot : slots_) fail(slot, kind, now);
}

Slot* Connection::oldest() {
    Slot* found = nullptr;
    for (auto& slot : slots_) {
        if (slot.busy && (!found || slot.sent < found->sent)) found = &slot;
    }
    return found;
}

// When the oldest pending thing (a connect, or a request) runs out of time.
Clock::time_point Connection::deadline() {
    Clock::time_point since = opening_since_;
    if (Slot* slot = oldest(); slot && slot->sent < since) since = slot->sent;
    if (since == Clock::time_point::max()) since = Clock::now();
    return since + state_.control.timeout();
}

// The per-request timeout: wakes at the oldest deadline and, if it really has
// passed, closes the transport so the pending operation fails. In steady state
// it wakes about once per --timeout, so it costs nothing measurable.
awaitable<void> Connection::watch() {
    while (!done_) {
        watchdog_.expires_at(deadline());
        error_code ec;
        co_await watchdog_.async_wait(asio::redirect_error(asio::use_awaitable, ec));
        if (done_) break;
        if (deadline() <= Clock::now()) {
            timed_out_ = true;
            transport_->close();
        }
    }
}

void report_crash(std::exception_ptr e) {
    if (!e) return;
    try {
        std::rethrow_exception(e);
    } catch (const std::exception& ex) {
        std::cerr << "slmp-bench: connection failed: " << ex.what() << '\n';
    }
}

}  // namespace

void start_connection(const asio::any_io_executor& executor, RunState& state, unsigned index, bool udp,
                      const asio::ip::address& address, std::uint16_t port) {
    auto connection =
        std::make_shared<Connection>(executor, state, index, make_transport(executor, udp, address, port));
    asio::co_spawn(
        executor, [connection]() -> awaitable<void> { co_await connection->watch(); }, report_crash);
    asio::co_spawn(
        executor, [connection]() -> awaitable<void> { co_await connection->run(); }, report_crash);
}

}  // namespace slmp::bench
