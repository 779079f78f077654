#include "tools/slmp/client.hpp"

#include <algorithm>
#include <cstdio>

#include "devicemodel/hex.hpp"
#include "protocol/end_code.hpp"
#include "tools/slmp/errors.hpp"

namespace slmp::cli {

using protocol::FrameKind;
using protocol::client::Response;

using devicemodel::hex4;

namespace {

std::string hex2(unsigned value) { return devicemodel::hex_text(value & 0xFF, 2); }

}  // namespace

std::string explain_end_code(std::uint16_t code, const std::optional<protocol::client::ErrorInfo>& info) {
    std::string text = hex4(code) + ": " + std::string(protocol::describe(protocol::end_code(code)));
    if (info) {
        text += " (command " + hex4(info->command) + "/" + hex4(info->subcommand) + ", answered by network " +
                hex2(info->route.network) + " station " + hex2(info->route.station) + " module I/O " +
                hex4(info->route.module_io) + " multidrop " + hex2(info->route.multidrop) + ")";
    }
    return text;
}

Client::Client(const Target& target, const protocol::client::FrameOptions& frame, std::optional<std::string> password)
    : target_(target), frame_(frame), password_(std::move(password)), link_(target.host, target.port, target.udp) {}

bool Client::answers_our_request(const Response& response, std::uint16_t serial) const {
    // Only 4E frames carry a serial number; 3E responses are taken in order.
    if (frame_.kind != FrameKind::E4) return response.header.kind == FrameKind::E3;
    return response.header.kind == FrameKind::E4 && response.header.serial == serial;
}

Response Client::receive_response(std::uint16_t serial, Clock::time_point deadline) {
    for (;;) {
        bool garbage = false;
        if (!pending_.empty()) {
            auto parsed = protocol::client::parse_response(pending_, &garbage);
            if (garbage)
                throw ConnectionError("the answer from " + link_.peer() + " is not an SLMP response frame");
            if (parsed) {
                pending_.erase(pending_.begin(), pending_.begin() + static_cast<long>(parsed->size));
                if (link_.datagram()) pending_.clear();   // one frame per datagram
                if (answers_our_request(*parsed, serial)) return *parsed;
                // UDP: a late answer to an earlier request; TCP 4E: not ours either.
                if (!link_.datagram())
                    throw ConnectionError("the response from " + link_.peer() +
                                          " does not match the request (wrong frame type or serial number)");
                continue;
            }
            if (link_.datagram()) {   // an incomplete datagram will never be completed
                pending_.clear();
                throw ConnectionError("the datagram from " + link_.peer() + " holds an incomplete SLMP response");
            }
        }
        auto bytes = link_.receive(deadline);
        pending_.insert(pending_.end(), bytes.begin(), bytes.end());
    }
}

Response Client::next_push(Clock::time_point deadline) {
    if (!open_) {
        link_.open(deadline);
        open_ = true;
    }
    for (;;) {
        bool garbage = false;
        if (!pending_.empty()) {
            auto parsed = protocol::client::parse_response(pending_, &garbage);
            if (garbage) throw ConnectionError("the bytes from " + link_.peer() + " are not an SLMP frame");
            if (parsed) {
                pending_.erase(pending_.begin(), pending_.begin() + static_cast<long>(parsed->size));
                return *parsed;
            }
        }
        auto bytes = link_.receive(deadline);
        pending_.insert(pending_.end(), bytes.begin(), bytes.end());
    }
}

std::optional<Response> Client::round_trip(std::span<const std::uint8_t> request, bool silence_ok) {
    auto deadline = Clock::now() + target_.timeout;
    if (!open_) {
        link_.open(deadline);
        open_ = true;
        // --password: unlock on this connection first (the lock state belongs to the connection).
        if (password_) exchange(protocol::client::unlock(frame_, *password_));
    }
    // The serial the request was built with (the unlock above may have used one since).
    auto serial = protocol::scan_frame(request, protocol::Direction::Request, protocol::DataCodePolicy::Auto, 1u << 20)
                      .header.serial;
    link_.send(request, deadline);
    std::optional<Response> response;
    try {
        response = receive_response(serial, deadline);
    } catch (const ConnectionError&) {
        if (!silence_ok) throw;
        open_ = false;   // Remote RESET: the CPU restarts, answers nothing and drops TCP
    }
    // The next request gets the next serial number (4E), as a pipelining client would.
    if (frame_.kind == FrameKind::E4) frame_.serial = static_cast<std::uint16_t>(std::max(serial, frame_.serial) + 1);
    if (response && response->end_code != 0) {
        auto info = protocol::client::decode_error_info(*response);
        throw EndCodeError(response->end_code, info, explain_end_code(response->end_code, info));
    }
    return response;
}

Response Client::exchange(std::span<const std::uint8_t> request) { return *round_trip(request, false); }

std::optional<Response> Client::exchange_allow_silence(std::span<const std::uint8_t> request) {
    return round_trip(request, true);
}

}  // namespace slmp::cli
