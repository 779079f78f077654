// The CLI's view of a PLC: send one request, get its response back, and turn
// anything but end code 0000 into an EndCodeError whose message says what the
// code means. Requests come from protocol/client*.hpp only.
#pragma once

#include <chrono>
#include <cstdint>
#include <optional>
#include <span>
#include <vector>

#include "protocol/client_commands.hpp"
#include "tools/slmp/link.hpp"

namespace slmp::cli {

struct Target {
    std::string host = "127.0.0.1";
    std::uint16_t port = 5000;
    bool udp = false;
    std::chrono::milliseconds timeout{3000};
};

class Client {
public:
    // `password`: sent with Remote Unlock (1630) right after connecting, before the first request.
    Client(const Target& target, const protocol::client::FrameOptions& frame,
           std::optional<std::string> password = std::nullopt);

    // The frame options for the next request (4E: carries the next serial number).
    const protocol::client::FrameOptions& frame() const { return frame_; }

    // Sends `request` (built with frame()) and returns its response. Throws
    // ConnectionError, or EndCodeError when the end code is not 0000.
    protocol::client::Response exchange(std::span<const std::uint8_t> request);
    // The same, but a timeout or a closed connection returns nullopt: for Remote
    // RESET, which a real CPU answers with silence when it succeeds.
    std::optional<protocol::client::Response> exchange_allow_silence(std::span<const std::uint8_t> request);

    Link& link() { return link_; }
    // Ondemand: the next frame the station sends unasked, a 2101 push
    // (docs/timing.md). Connects first when needed; throws ConnectionError
    // when none comes before `deadline` or the bytes are no response frame.
    protocol::client::Response next_push(Clock::time_point deadline);

private:
    std::optional<protocol::client::Response> round_trip(std::span<const std::uint8_t> request, bool silence_ok);
    protocol::client::Response receive_response(std::uint16_t serial, Clock::time_point deadline);
    bool answers_our_request(const protocol::client::Response& response, std::uint16_t serial) const;

    Target target_;
    protocol::client::FrameOptions frame_;
    std::optional<std::string> password_;
    Link link_;
    bool open_ = false;
    std::vector<std::uint8_t> pending_;   // TCP bytes after the last whole frame
};

// "C059: command or subcommand not supported (command 0401/0000, network 00, ...)"
std::string explain_end_code(std::uint16_t code, const std::optional<protocol::client::ErrorInfo>& info);

}  // namespace slmp::cli
