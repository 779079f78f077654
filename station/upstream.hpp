// Proxy mode's client side (docs/twin.md, "Proxy"): the one TCP connection a
// station keeps to its upstream — a real PLC or another SLMP server — as a
// real SLMP client keeps it. Opened on first use and kept; one request at a
// time on it (a real CPU's port serves a connection's requests in order, and
// its connection count is small, so the station never opens a second);
// closed after a failure or a timeout, so that a late answer is never taken
// for the next request's, and opened afresh by the next request.
#pragma once

#include <chrono>
#include <cstdint>
#include <deque>
#include <optional>
#include <span>
#include <string>
#include <vector>

#include <spdlog/logger.h>

#include "station/asio.hpp"

#include "config/config.hpp"
#include "protocol/request.hpp"

namespace slmp::station {

// The upstream's answer to one request, or why there is none.
struct UpstreamAnswer {
    std::vector<std::uint8_t> bytes;   // the answer; NotAnAnswer: what came instead
    std::string failure;               // empty: bytes is the answer
    // What the upstream did instead of answering, as --compare tells it apart.
    enum class Failed : std::uint8_t { No, Unreachable, Closed, Silent, NotAnAnswer };
    Failed failed = Failed::No;
    // From the request's turn on the connection to the answer (a connect included).
    std::chrono::microseconds took{0};
};

class Upstream {
public:
    Upstream(const Home& home, config::UpstreamAddress address, std::chrono::milliseconds timeout, spdlog::logger& log);
    ~Upstream();
    Upstream(const Upstream&) = delete;
    Upstream& operator=(const Upstream&) = delete;

    // The upstream's whole answer to `frame` (one request frame as the client
    // sent it; `request`, its decoding here, tells a 1E answer's length), or
    // why there is none (`failure`: unreachable, closed, silent past the
    // timeout, not an answer). Runs on the station's strand; requests wait
    // their turn.
    using Answer = UpstreamAnswer;
    StrandTask<Answer> exchange(std::span<const std::uint8_t> frame, const protocol::Request& request);

    const config::UpstreamAddress& address() const { return address_; }
    std::chrono::milliseconds timeout() const { return timeout_; }
    // At shutdown: the connection closes, waiting requests fail.
    void stop();

private:
    using Socket = StrandSocket;
    StrandTask<std::string> connect();   // empty: connected
    StrandTask<Answer> send_and_receive(std::span<const std::uint8_t> frame, const protocol::Request& request);
    void arm(std::uint64_t turn);   // the timeout of this exchange: closes the socket when it runs out
    void drop();
    void report(const std::string& failure);   // one warning when the upstream fails, one line when it is back

    Home home_;
    config::UpstreamAddress address_;
    std::chrono::milliseconds timeout_;
    spdlog::logger& log_;
    std::optional<Socket> socket_;
    StrandTimer deadline_;
    std::uint64_t turn_ = 0;        // which exchange the deadline belongs to
    bool timed_out_ = false;
    bool busy_ = false;             // an exchange holds the connection
    std::deque<StrandTimer*> waiting_;   // the exchanges waiting for it, first come first served
    std::size_t monitor_words_ = 0;   // 1E: the words this connection's monitor registration (07) names
    bool failing_ = false;          // the last exchange failed (the warning was given)
    bool stopped_ = false;
};

// The bytes a whole answer to `request` takes at the start of `bytes`: 0 while
// it is not whole yet, nullopt when the bytes start no answer (3E/4E: the
// frame's length field; 1E: the command's data, from the request's points, and
// for a monitor (09) the `monitor_words` its registration named).
std::optional<std::size_t> whole_answer(std::span<const std::uint8_t> bytes, const protocol::Request& request,
                                        std::size_t monitor_words);

// The end code of a whole answer to `request`, for the log, metrics and
// recordings (1E: its one-byte code as the number).
protocol::EndCode answer_end_code(std::span<const std::uint8_t> answer, const protocol::Request& request);

}  // namespace slmp::station
