// Blocking client sockets for slmp-replay, with a deadline on every wait.
// TCP answers are cut into frames by the protocol's response parser, so a
// split or coalesced answer is assembled the way a correct client does it.
#pragma once

#include <chrono>
#include <cstdint>
#include <optional>
#include <span>
#include <string>
#include <vector>

namespace slmp::replay {

using Bytes = std::vector<std::uint8_t>;

class Wire {
public:
    // Opens a TCP connection or a UDP socket to host:port; throws std::runtime_error naming the problem.
    Wire(const std::string& host, std::uint16_t port, bool udp);
    ~Wire();
    Wire(const Wire&) = delete;
    Wire& operator=(const Wire&) = delete;

    bool send(std::span<const std::uint8_t> bytes);
    // One response frame, or nullopt when none came within `timeout`
    // (`why` says: timeout, closed, reset, undecodable).
    std::optional<Bytes> receive(std::chrono::milliseconds timeout, std::string& why);
    // Nothing listens there: a UDP send came back as ICMP port unreachable
    // (a TCP connect fails in the constructor instead).
    bool refused() const { return refused_; }

private:
    int fd_ = -1;
    bool udp_;
    bool refused_ = false;
    Bytes pending_;
};

}  // namespace slmp::replay
