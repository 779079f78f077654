#include "station/inbox.hpp"

#include "station/scan_loop.hpp"

namespace slmp::station {

using protocol::Outcome;
using TimePoint = std::chrono::steady_clock::time_point;

namespace {

// Where an end_of_scan wait ended: at the END after it began (`served_at`:
// that END's time), or not (its deadline passed or it no longer waits: now).
struct EndOfScanWait {
    bool at_end = false;
    TimePoint served_at;
};

// end_of_scan (docs/timing.md): a whole request waits for the END after its
// arrival, or until its monitoring timer runs out (`deadline`; none: the END
// alone), whichever comes first — the one wait of a stream's first request
// (Inbox) and of a datagram (HeldDatagram), while `waiting()` holds (the
// connection open, the station running). `wait_once` waits on the clock once,
// for the END after `seen` or the deadline.
StrandTask<EndOfScanWait> wait_for_end(ScanLoop& scan, std::optional<TimePoint> deadline, std::function<bool()> waiting,
                                       std::function<StrandTask<>(std::uint64_t seen)> wait_once) {
    const auto seen = scan.scans();
    while (waiting()) {
        if (scan.scans() > seen) co_return EndOfScanWait{true, scan.end_time(seen + 1)};
        if (deadline && scan.clock().now() >= *deadline) break;
        co_await wait_once(seen);
    }
    co_return EndOfScanWait{false, scan.clock().now()};
}

}  // namespace

RequestShape request_shape(std::span<const std::uint8_t> f) {
    using protocol::Codec;
    using protocol::FrameKind;
    if (f.size() >= 2 && f[0] == 0x54 && f[1] == 0x00) return {FrameKind::E4, Codec::Binary};
    if (f.size() >= 4 && f[0] == '5' && f[1] == '4' && f[2] == '0' && f[3] == '0') return {FrameKind::E4, Codec::Ascii};
    if (f.size() >= 4 && f[0] == '5' && f[1] == '0' && f[2] == '0' && f[3] == '0') return {FrameKind::E3, Codec::Ascii};
    return {FrameKind::E3, Codec::Binary};
}

Inbox::Inbox(Station& station, Home home, protocol::Session session, const protocol::Peer& peer,
             protocol::DataCodePolicy policy, Feed* feed, std::function<std::size_t()> connections)
    : station_(station),
      home_(std::move(home)),
      session_(std::move(session)),
      peer_(peer),
      policy_(policy),
      feed_(feed),
      at_once_(station.serves_at_once()),
      connections_(std::move(connections)) {}

void Inbox::received() {
    if (at_once_) return;   // arrival times matter only to the clock
    const auto end = front_ + bytes_.size();
    if (!stamps_.empty() && stamps_.back().end == end) return;
    stamps_.push_back({end, station_.scan_loop()->clock().now()});
}

// Not a coroutine itself: the instant path costs no coroutine frame of its
// own, only on_home's hop (the usual case, a request at a time).
StrandTask<> Inbox::serve() {
    served_.responses.clear();   // keeps its capacity
    served_ = {std::move(served_.responses)};
    waiting_ = false;
    if (relay_) return serve_relayed();
    if (at_once_) return on_home(home_, [this] { serve_at_once(); }, use_strand);
    return serve_timed();
}

// The answers before it have left (waiting_ made the transport write them
// first); the connection waits for this one as for its own CPU's.
StrandTask<> Inbox::serve_relayed() {
    auto pending = std::move(*relay_);
    relay_.reset();
    auto handled = co_await station_.pass_on(std::move(pending.handled), pending.frame, policy_, relays_, session_, peer_);
    handled.outcome.consumed = pending.frame.size();
    const bool go_on = take(std::move(handled), pending.frame, true);
    if (go_on && !bytes_.empty()) {   // the frames behind it
        if (at_once_) co_await on_home(home_, [this] { serve_at_once(); }, use_strand);
        else co_await serve_timed();
    }
    served_.consumed_a_frame = true;
}

// On the station's strand; the connection waits for it meanwhile, so its bytes are this step's.
void Inbox::serve_at_once() {
    begin_frames();
    while (consumed_ < bytes_.size()) {
        const auto input = unserved();
        if (!take(station_.handle(input, policy_, session_, peer_), input, false)) break;
    }
    drop_served();
}

// Serving the frames of one read begins. They all arrived before any was
// answered, so they stood in the port's receive buffer together: the
// commands-per-connection limit counts them (SLMP Reference Manual §3.3; docs/end-codes.md).
void Inbox::begin_frames() {
    session_.queued_ahead = 0;
    session_.connections = connections_ ? connections_() : 1;
}

bool Inbox::take(Handled handled, std::span<const std::uint8_t> frame, bool owned) {
    auto& outcome = handled.outcome;
    if (handled.relay || handled.forward) {   // another station or the upstream serves it: serve() carries it there next (serve_relayed)
        const auto size = outcome.consumed;
        relay_ = PendingRelay{std::move(handled), std::vector<std::uint8_t>(frame.begin(), frame.begin() + static_cast<std::ptrdiff_t>(size))};
        if (!owned) consumed_ += size;
        waiting_ = true;
        return false;
    }
    if (outcome.action == Outcome::Action::NeedMore) return false;
    if (outcome.command != 0) last_shape_ = request_shape(frame);
    if (!owned) consumed_ += outcome.consumed;
    if (outcome.action == Outcome::Action::Respond || outcome.command != 0) ++session_.queued_ahead;   // not skipped garbage
    if (outcome.action == Outcome::Action::Respond) served_.responses.emplace_back(std::move(outcome.response), handled.delivery);
    if (outcome.action == Outcome::Action::Close) {
        served_.close = true;
        served_.reset = handled.reset;
        served_.close_reason = outcome.note;
        return false;
    }
    if (outcome.action == Outcome::Action::Restart) {   // Remote RESET: no answer; every connection closes
        served_.close = served_.restart = true;
        served_.close_reason = "Remote RESET: the CPU restarted";
        return false;
    }
    return true;
}

// end_of_scan and model (docs/timing.md). The connection lives on the
// station's strand, so this touches the station directly.
StrandTask<> Inbox::serve_timed() {
    co_await hold_for_clock();
    drop_served();
}

StrandTask<> Inbox::hold_for_clock() {
    auto& scan = *station_.scan_loop();
    const bool end_of_scan = station_.timing_mode() == config::TimingMode::EndOfScan;
    // end_of_scan: the first whole request waits for the END after its
    // arrival, or until its monitoring timer runs out; what arrives meanwhile
    // is read and served at the same END.
    bool at_end = false;
    auto served_at = scan.clock().now();
    if (end_of_scan) {
        if (const auto first = station_.next_request(unserved(), policy_)) {
            std::optional<TimePoint> deadline;
            if (first->timer.count() > 0) deadline = arrival(consumed_ + first->end) + first->timer;
            const auto waited = co_await wait_for_end(
                scan, deadline, [this, &scan] { return !scan.stopped() && feed_->open(); },
                [this, deadline](std::uint64_t seen) { return wait(seen, deadline); });   // reading the connection on meanwhile
            at_end = waited.at_end;
            served_at = waited.served_at;
        }
    }
    if (!feed_->open()) co_return;
    if (!held_) begin_frames();   // a held request resumes the turn it was scheduled in
    for (;;) {
        if (held_) {
            // model: executed and answered at the modelled time; the answers
            // before it leave first, and reading goes on meanwhile.
            const auto& service = held_->service;
            if (service && service->at > scan.clock().now()) {
                if (!served_.responses.empty()) {
                    waiting_ = true;
                    co_return;
                }
                while (service->at > scan.clock().now() && feed_->open() && !scan.stopped())
                    co_await wait(std::nullopt, service->at);
                if (!feed_->open()) co_return;
            }
            auto ticket = std::move(*held_);
            held_.reset();
            if (!take(station_.handle(ticket, session_, peer_), ticket.bytes, true)) co_return;
            continue;
        }
        if (consumed_ >= bytes_.size()) co_return;
        const auto input = unserved();
        const auto queued = station_.next_request(input, policy_);
        if (!queued && end_of_scan && !at_end) co_return;
        std::optional<Service> service;
        if (queued && queued->start == 0) {
            const auto at = arrival(consumed_ + queued->end);
            if (end_of_scan) {
                service = Station::end_of_scan_service(at, queued->timer, served_at, at_end);
                if (!service) {   // this one and those behind it wait for the END
                    waiting_ = true;
                    co_return;
                }
            } else if (!queued->too_large) {
                held_ = station_.schedule(std::vector<std::uint8_t>(input.begin(), input.begin() + static_cast<std::ptrdiff_t>(queued->end)),
                                          policy_, session_, at);
                consumed_ += queued->end;
                continue;
            }
        }
        if (!take(station_.handle(input, policy_, session_, peer_, service ? &*service : nullptr), input, false)) co_return;
    }
}

StrandTask<> Inbox::wait(std::optional<std::uint64_t> seen, std::optional<TimePoint> at) {
    auto& scan = *station_.scan_loop();
    feed_->watch([this, &scan](bool open) {
        if (open && !read_ready()) return false;   // the end of the stream or an error: the next read reports it
        scan.nudge();   // a new request may have a shorter deadline; a closed feed ends the wait
        return open;
    });
    co_await scan.until_end_or(seen, at);
    feed_->stop_watching();
    // What arrived up to now belongs to this wake (an END serves it).
    if (feed_->open()) read_ready();
}

bool Inbox::read_ready() {
    if (!feed_->read_now(bytes_)) return false;
    received();
    return true;
}

Inbox::TimePoint Inbox::arrival(std::size_t end) const {
    const auto last = front_ + end;   // the stream offset one past the request's last byte
    for (const auto& stamp : stamps_)
        if (stamp.end >= last) return stamp.at;
    return station_.scan_loop()->clock().now();
}

void Inbox::drop_served() {
    served_.consumed_a_frame = consumed_ > 0;
    bytes_.erase(bytes_.begin(), bytes_.begin() + static_cast<std::ptrdiff_t>(consumed_));
    front_ += consumed_;
    consumed_ = 0;
    while (!stamps_.empty() && stamps_.front().end <= front_) stamps_.pop_front();
}

HeldDatagram::HeldDatagram(Station& station, std::span<const std::uint8_t> datagram, protocol::DataCodePolicy policy,
                           const protocol::Session& session)
    : station_(station), policy_(policy), arrival_(station.scan_loop()->clock().now()) {
    std::vector<std::uint8_t> bytes(datagram.begin(), datagram.end());
    scheduled_ = station.timing_mode() == config::TimingMode::Model;
    if (scheduled_) ticket_ = station.schedule(std::move(bytes), policy, session, arrival_);
    else ticket_.bytes = std::move(bytes);
}

StrandTask<bool> HeldDatagram::wait() {
    auto& scan = *station_.scan_loop();
    if (scheduled_) {
        const auto& service = ticket_.service;
        while (service && scan.clock().now() < service->at && !scan.stopped()) co_await scan.until_end_or(std::nullopt, service->at);
        co_return !scan.stopped();
    }
    // end_of_scan: the END after the arrival, or the monitoring timer first.
    const auto queued = station_.next_request(ticket_.bytes, policy_);
    if (queued && queued->start == 0) {
        std::optional<TimePoint> deadline;
        if (queued->timer.count() > 0) deadline = arrival_ + queued->timer;
        const auto waited = co_await wait_for_end(scan, deadline, [&scan] { return !scan.stopped(); },
                                                  [&scan, deadline](std::uint64_t seen) { return scan.until_end_or(seen, deadline); });
        end_of_scan_ = Station::end_of_scan_service(arrival_, queued->timer, waited.served_at, waited.at_end);
    }
    co_return !scan.stopped();
}

Handled HeldDatagram::serve(protocol::Session& session, const protocol::Peer& peer) {
    if (scheduled_) return station_.handle(ticket_, session, peer);
    return station_.handle(ticket_.bytes, policy_, session, peer, end_of_scan_ ? &*end_of_scan_ : nullptr);
}

}  // namespace slmp::station
