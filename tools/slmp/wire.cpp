#include "tools/slmp/wire.hpp"

#include <algorithm>

#include <nlohmann/json.hpp>

#include "devicemodel/hex.hpp"
#include "tools/slmp/errors.hpp"

namespace slmp::cli {

using Kind = Observed::Kind;

namespace {

std::string lower_hex(std::span<const std::uint8_t> bytes) { return devicemodel::bytes_to_hex(bytes, true); }

}  // namespace

WireRecorder::WireRecorder(const std::string& path, const std::string& note) : out_(path) {
    if (!out_) throw UsageError("--record '" + path + "': cannot write the file; check the directory");
    out_ << nlohmann::json{{"slmp_recording", 1}, {"profile", note}}.dump() << '\n';
}

double WireRecorder::now_ms() const {
    return std::chrono::duration<double, std::milli>(Clock::now() - start_).count();
}

void WireRecorder::opened(std::uint64_t connection, const std::string& peer, bool udp) {
    out_ << nlohmann::json{{"t_ms", now_ms()}, {"conn", connection}, {"transport", udp ? "udp" : "tcp"},
                           {"peer", peer}, {"event", "open"}}.dump()
         << '\n';
}

void WireRecorder::exchange(std::uint64_t connection, const std::string& peer, bool udp,
                            std::span<const std::uint8_t> request, const Observed& observed) {
    nlohmann::json line{{"t_ms", now_ms()}, {"conn", connection}, {"transport", udp ? "udp" : "tcp"},
                        {"peer", peer}, {"event", "exchange"}, {"request", lower_hex(request)}};
    line["response"] = observed.kind == Kind::Answer ? nlohmann::json(lower_hex(observed.bytes)) : nlohmann::json();
    out_ << line.dump() << '\n';
}

void WireRecorder::closed(std::uint64_t connection, const std::string& peer, bool udp, const std::string& why) {
    out_ << nlohmann::json{{"t_ms", now_ms()}, {"conn", connection}, {"transport", udp ? "udp" : "tcp"},
                           {"peer", peer}, {"event", "close"}, {"why", why}}.dump()
         << '\n';
    out_.flush();
}

Wire::Wire(const Target& target, std::chrono::milliseconds silence_after, WireRecorder* recorder)
    : target_(target), silence_after_(silence_after), recorder_(recorder) {}

bool Wire::open() {
    if (link_) return true;
    link_ = std::make_unique<Link>(target_.host, target_.port, target_.udp);
    pending_.clear();
    try {
        link_->open(Clock::now() + target_.timeout);
    } catch (const ConnectionError&) {
        link_.reset();
        return false;
    }
    ++connection_;
    if (recorder_) recorder_->opened(connection_, link_->peer(), target_.udp);
    return true;
}

void Wire::close(const std::string& why) {
    if (!link_) return;
    if (recorder_) recorder_->closed(connection_, link_->peer(), target_.udp, why);
    link_.reset();
    pending_.clear();
}

void Wire::record(std::span<const std::uint8_t> request, const Observed& observed) {
    if (recorder_ && link_) recorder_->exchange(connection_, link_->peer(), target_.udp, request, observed);
}

Observed Wire::receive_one(Clock::time_point deadline) {
    for (;;) {
        if (!pending_.empty()) {
            bool garbage = false;
            auto parsed = protocol::client::parse_response(pending_, &garbage);
            if (parsed) {
                Observed answer{Kind::Answer, {pending_.begin(), pending_.begin() + static_cast<long>(parsed->size)},
                                parsed->end_code};
                pending_.erase(pending_.begin(), pending_.begin() + static_cast<long>(parsed->size));
                return answer;
            }
            if (garbage || target_.udp) {   // not SLMP 3E/4E (a 1E answer): the bytes as they came
                Observed raw{Kind::Answer, std::move(pending_), 0xFFFF};
                pending_.clear();
                return raw;
            }
        }
        std::vector<std::uint8_t> bytes;
        auto received = link_->try_receive(deadline, bytes);
        if (received == Link::Received::Silence) {
            // Bytes of an incomplete answer are an answer of their own kind (1E: no length field).
            if (!pending_.empty()) return {Kind::Answer, std::exchange(pending_, {}), 0xFFFF};
            return {Kind::Silence, {}, 0};
        }
        if (received == Link::Received::Closed) return {Kind::Close, {}, 0};
        pending_.insert(pending_.end(), bytes.begin(), bytes.end());
    }
}

Observed Wire::exchange(std::span<const std::uint8_t> request) {
    if (!open()) return {Kind::Close, {}, 0};
    auto start = Clock::now();
    Observed observed;
    ++sent_;
    try {
        link_->send(request, start + target_.timeout);
        observed = receive_one(start + silence_after_);
    } catch (const ConnectionError&) {
        if (target_.udp) throw;   // UDP: nothing listens there
        observed = {Kind::Close, {}, 0};
    }
    elapsed_ = std::chrono::duration_cast<std::chrono::microseconds>(Clock::now() - start);
    record(request, observed);
    if (observed.kind == Kind::Close) close("closed by the server");
    else if (observed.kind == Kind::Silence) close("no answer: reconnecting, so that a late answer is not taken for the next");
    return observed;
}

std::vector<Observed> Wire::burst(const std::vector<std::vector<std::uint8_t>>& requests) {
    std::vector<Observed> outcomes;
    if (!open()) return std::vector<Observed>(requests.size(), {Kind::Close, {}, 0});
    std::vector<std::uint8_t> all;
    for (const auto& r : requests) all.insert(all.end(), r.begin(), r.end());
    sent_ += requests.size();
    auto start = Clock::now();
    try {
        link_->send(all, start + target_.timeout);
        for (const auto& request : requests) {
            auto observed = outcomes.empty() || outcomes.back().kind == Kind::Answer
                                ? receive_one(Clock::now() + silence_after_)
                                : outcomes.back();
            record(request, observed);
            outcomes.push_back(observed);
        }
    } catch (const ConnectionError&) {
        if (target_.udp) throw;
        outcomes.resize(requests.size(), {Kind::Close, {}, 0});
    }
    elapsed_ = std::chrono::duration_cast<std::chrono::microseconds>(Clock::now() - start);
    if (!std::all_of(outcomes.begin(), outcomes.end(), [](const Observed& o) { return o.kind == Kind::Answer; }))
        close("burst done");
    return outcomes;
}

}  // namespace slmp::cli
