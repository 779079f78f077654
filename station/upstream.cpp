// Proxy mode's client side (upstream.hpp; docs/twin.md, "Proxy").
#include "station/upstream.hpp"

#include <array>

#include "devicemodel/hex.hpp"
#include "protocol/client.hpp"
#include "protocol/frame.hpp"

namespace slmp::station {

namespace asio = boost::asio;
using asio::ip::tcp;

namespace {

constexpr std::size_t kMaxAnswerBytes = 1u << 20;

// A 1E answer (docs/frames.md): subheader | 80 and the end code (5B: and the
// abnormal code), then on 00 the command's data. In binary bytes; ASCII sends
// two characters a byte.
std::optional<std::size_t> whole_answer_1e(std::span<const std::uint8_t> bytes, const protocol::Request& request,
                                           std::size_t monitor_words) {
    const bool ascii = request.header.codec == protocol::Codec::Ascii;
    const std::size_t unit = ascii ? 2 : 1;
    auto byte_at = [&](std::size_t i) -> std::optional<std::uint8_t> {
        if (bytes.size() < (i + 1) * unit) return std::nullopt;
        if (!ascii) return bytes[i];
        const auto hi = devicemodel::hex_digit(bytes[2 * i]);
        const auto lo = devicemodel::hex_digit(bytes[2 * i + 1]);
        if (hi < 0 || lo < 0) return std::nullopt;
        return static_cast<std::uint8_t>(hi << 4 | lo);
    };
    auto whole = [&](std::size_t binary_bytes) -> std::size_t {
        return bytes.size() >= binary_bytes * unit ? binary_bytes * unit : 0;
    };
    auto subheader = byte_at(0);
    if (!subheader) return bytes.size() < unit ? std::optional<std::size_t>(0) : std::nullopt;
    if (*subheader != (request.header.command_1e | 0x80)) return std::nullopt;
    auto end = byte_at(1);
    if (!end) return 0;
    if (*end == 0x5B) return whole(3);
    if (*end != 0x00) return whole(2);
    const auto points = request.operands.devices.empty() ? 0u : request.operands.devices.front().points;
    switch (request.header.command_1e) {
        case 0x00: return whole(2 + (points + 1) / 2);   // bit read: a nibble a point, whole bytes
        case 0x01: return whole(2 + 2 * std::size_t{points});
        case 0x09: return whole(2 + 2 * monitor_words);
        case 0x15: return whole(3);                        // PC type
        case 0x16: {                                       // loopback: its count, then the characters
            auto count = byte_at(2);
            if (!count) return 0;
            return bytes.size() >= (3 * unit + *count) ? 3 * unit + *count : 0;
        }
        default: return whole(2);
    }
}

}  // namespace

std::optional<std::size_t> whole_answer(std::span<const std::uint8_t> bytes, const protocol::Request& request,
                                        std::size_t monitor_words) {
    if (request.header.kind == protocol::FrameKind::E1) return whole_answer_1e(bytes, request, monitor_words);
    const auto scan = protocol::scan_frame(bytes, protocol::Direction::Response, protocol::DataCodePolicy::Auto, kMaxAnswerBytes);
    switch (scan.status) {
        case protocol::FrameScan::Status::NeedMore: return 0;
        case protocol::FrameScan::Status::Complete: return scan.size;
        default: return std::nullopt;
    }
}

protocol::EndCode answer_end_code(std::span<const std::uint8_t> answer, const protocol::Request& request) {
    if (request.header.kind == protocol::FrameKind::E1) {
        const bool ascii = request.header.codec == protocol::Codec::Ascii;
        if (answer.size() < (ascii ? 4u : 2u)) return static_cast<protocol::EndCode>(0xFF);
        auto code = ascii ? devicemodel::parse_hex(answer.subspan(2, 2)) : std::optional<std::uint32_t>(answer[1]);
        return static_cast<protocol::EndCode>(code.value_or(0xFF));
    }
    auto parsed = protocol::client::parse_response(answer);
    return static_cast<protocol::EndCode>(parsed ? parsed->end_code : 0xFFFF);
}

Upstream::Upstream(const Home& home, config::UpstreamAddress address, std::chrono::milliseconds timeout, spdlog::logger& log)
    : home_(home), address_(std::move(address)), timeout_(timeout), log_(log), deadline_(home) {}

Upstream::~Upstream() = default;

void Upstream::stop() {
    stopped_ = true;
    drop();
    deadline_.cancel();
    for (auto* waiter : waiting_) waiter->cancel();
    waiting_.clear();
}

StrandTask<Upstream::Answer> Upstream::exchange(std::span<const std::uint8_t> frame, const protocol::Request& request) {
    // One request at a time on the connection, in arrival order: the one that
    // finishes hands the connection to the first waiting (busy_ stays set).
    if (busy_) {
        StrandTimer turn(home_, StrandTimer::time_point::max());
        waiting_.push_back(&turn);
        boost::system::error_code ec;
        co_await turn.async_wait(asio::redirect_error(use_strand, ec));
    }
    busy_ = true;
    const auto turn_started = std::chrono::steady_clock::now();
    Answer answer;
    if (stopped_) {
        answer.failure = "the station is stopping";
        answer.failed = Answer::Failed::Closed;
    }
    else answer = co_await send_and_receive(frame, request);
    answer.took = std::chrono::duration_cast<std::chrono::microseconds>(std::chrono::steady_clock::now() - turn_started);
    ++turn_;   // a deadline that ran out just as the answer came belongs to no exchange now
    if (!waiting_.empty()) {
        waiting_.front()->cancel();
        waiting_.pop_front();
    } else {
        busy_ = false;
    }
    report(answer.failure);
    co_return answer;
}

StrandTask<Upstream::Answer> Upstream::send_and_receive(std::span<const std::uint8_t> frame, const protocol::Request& request) {
    const auto turn = ++turn_;
    timed_out_ = false;
    arm(turn);
    Answer answer;
    auto failed = [&](Answer::Failed how, std::string why) {
        answer.failure = timed_out_ ? "no answer within " + std::to_string(timeout_.count()) + " ms" : std::move(why);
        answer.failed = timed_out_ ? Answer::Failed::Silent : how;
        drop();   // a late answer must not be taken for the next request's
        return answer;
    };
    if (!socket_) {
        if (auto error = co_await connect(); !error.empty()) {
            deadline_.cancel();
            co_return failed(Answer::Failed::Unreachable, "cannot connect: " + error);
        }
    }
    boost::system::error_code ec;
    co_await asio::async_write(*socket_, asio::buffer(frame.data(), frame.size()), asio::redirect_error(use_strand, ec));
    if (ec) {
        deadline_.cancel();
        co_return failed(Answer::Failed::Closed, "sending failed: " + ec.message());
    }
    std::array<std::uint8_t, 4096> chunk;
    for (;;) {
        auto size = whole_answer(answer.bytes, request, monitor_words_);
        if (!size) {
            deadline_.cancel();
            co_return failed(Answer::Failed::NotAnAnswer, "its answer is no SLMP response to the request (" +
                             devicemodel::bytes_to_hex(std::span<const std::uint8_t>(answer.bytes).first(std::min<std::size_t>(answer.bytes.size(), 16))) + ")");
        }
        if (*size > 0) {
            // Bytes after the answer would be an answer to no request: the next request starts clean.
            if (answer.bytes.size() > *size) {
                log_.warn("upstream {}: {} byte(s) after the answer to request {} dropped; reconnecting", address_.text(),
                          answer.bytes.size() - *size, turn);
                drop();
            }
            answer.bytes.resize(*size);
            break;
        }
        const auto n = co_await socket_->async_read_some(asio::buffer(chunk), asio::redirect_error(use_strand, ec));
        if (ec) {
            deadline_.cancel();
            co_return failed(Answer::Failed::Closed, ec == asio::error::eof ? std::string("it closed the connection without answering")
                                                     : "receiving failed: " + ec.message());
        }
        answer.bytes.insert(answer.bytes.end(), chunk.begin(), chunk.begin() + static_cast<std::ptrdiff_t>(n));
    }
    deadline_.cancel();
    // A 1E monitor answer's length is the registration's (07), which this connection holds.
    const bool ascii = request.header.codec == protocol::Codec::Ascii;
    if (request.header.kind == protocol::FrameKind::E1 && request.header.command_1e == 0x07 &&
        answer.bytes.size() == (ascii ? 4u : 2u) && (ascii ? answer.bytes[2] == '0' && answer.bytes[3] == '0' : answer.bytes[1] == 0))
        monitor_words_ = request.operands.devices.size();
    co_return answer;
}

StrandTask<std::string> Upstream::connect() {
    asio::ip::basic_resolver<tcp, Strand> resolver(home_);
    boost::system::error_code ec;
    auto endpoints = co_await resolver.async_resolve(address_.host, std::to_string(address_.port),
                                                     asio::redirect_error(use_strand, ec));
    if (ec) co_return "cannot resolve " + address_.host + ": " + ec.message();
    socket_.emplace(home_);
    co_await asio::async_connect(*socket_, endpoints, asio::redirect_error(use_strand, ec));
    if (ec || !socket_ || !socket_->is_open()) {
        socket_.reset();
        co_return ec ? ec.message() : std::string("timed out");
    }
    socket_->set_option(tcp::no_delay(true), ec);
    monitor_words_ = 0;   // a new connection has no 1E monitor registration
    log_.info("upstream {}: connected", address_.text());
    co_return std::string();
}

void Upstream::arm(std::uint64_t turn) {
    deadline_.expires_after(timeout_);
    deadline_.async_wait([this, turn](const boost::system::error_code& ec) {
        if (ec || turn != turn_) return;   // the exchange ended first
        timed_out_ = true;
        // Closing ends the pending connect, write or read with an error.
        if (socket_) {
            boost::system::error_code ignored;
            socket_->close(ignored);
        }
    });
}

void Upstream::drop() {
    if (!socket_) return;
    boost::system::error_code ignored;
    socket_->shutdown(tcp::socket::shutdown_both, ignored);
    socket_->close(ignored);
    socket_.reset();
}

void Upstream::report(const std::string& failure) {
    if (!failure.empty() && !failing_) {
        log_.warn("upstream {}: {}; clients get CF71 until it answers again (docs/twin.md, \"Proxy\")", address_.text(), failure);
    } else if (!failure.empty()) {
        log_.debug("upstream {}: {}", address_.text(), failure);
    } else if (failing_) {
        log_.info("upstream {}: answering again", address_.text());
    }
    failing_ = !failure.empty();
}

}  // namespace slmp::station
