// Blocking loopback sockets for black-box tests, with bounded waits.
//
// Every wait has an upper bound (kReplyTimeout unless told otherwise), so a
// server that never answers fails a test instead of hanging it. Sends use
// MSG_NOSIGNAL so a server that closed the connection cannot kill the test
// process with SIGPIPE.
#pragma once

#include <arpa/inet.h>
#include <netinet/in.h>
#include <netinet/tcp.h>
#include <poll.h>
#include <sys/socket.h>
#include <unistd.h>

#include <cerrno>
#include <chrono>
#include <cstdint>
#include <cstring>
#include <optional>
#include <span>
#include <stdexcept>
#include <string>
#include <thread>
#include <vector>

#include "protocol/client.hpp"

namespace slmp::test {

using Bytes = std::vector<std::uint8_t>;
inline constexpr std::chrono::milliseconds kReplyTimeout{5000};

// The outcome of waiting for bytes.
enum class RecvStatus { Data, Eof, Timeout, Error };

struct RecvResult {
    RecvStatus status = RecvStatus::Timeout;
    Bytes data;
    int error = 0;   // errno for Error
};

inline int remaining_ms(std::chrono::steady_clock::time_point deadline) {
    auto left = std::chrono::duration_cast<std::chrono::milliseconds>(deadline - std::chrono::steady_clock::now());
    return left.count() < 0 ? 0 : static_cast<int>(left.count());
}

// 127.0.0.1:port, or `address`:port (a plant's stations on 127.0.1.x).
inline sockaddr_in loopback(std::uint16_t port, const char* address = nullptr) {
    sockaddr_in addr{};
    addr.sin_family = AF_INET;
    addr.sin_port = htons(port);
    addr.sin_addr.s_addr = htonl(INADDR_LOOPBACK);
    if (address && ::inet_pton(AF_INET, address, &addr.sin_addr) != 1)
        throw std::runtime_error(std::string("not an IPv4 address: ") + address);
    return addr;
}

class Socket {
public:
    Socket() = default;
    explicit Socket(int fd) : fd_(fd) {}
    ~Socket() { close(); }
    Socket(Socket&& other) noexcept : fd_(other.fd_) { other.fd_ = -1; }
    Socket& operator=(Socket&& other) noexcept {
        if (this != &other) {
            close();
            fd_ = other.fd_;
            other.fd_ = -1;
        }
        return *this;
    }
    void close() {
        if (fd_ >= 0) ::close(fd_);
        fd_ = -1;
    }
    int fd() const { return fd_; }
    bool valid() const { return fd_ >= 0; }

protected:
    int fd_ = -1;
};

class TcpClient : public Socket {
public:
    // Connects to 127.0.0.1:port, from `source` when given (any 127.x.y.z: on
    // Linux all of 127/8 is loopback, so tests can be several client addresses).
    // `receive_buffer` > 0: SO_RCVBUF, set before connect() (shrinking it later
    // would shrink a window already advertised, which the kernel meets with
    // drops and retransmission backoff). Returns nullopt and sets `error`
    // (errno) on failure.
    static std::optional<TcpClient> connect(std::uint16_t port, int* error = nullptr, const char* source = nullptr,
                                            const char* destination = nullptr, int receive_buffer = 0) {
        int fd = ::socket(AF_INET, SOCK_STREAM | SOCK_CLOEXEC, 0);
        if (fd < 0) throw std::runtime_error("socket() failed");
        int one = 1;
        ::setsockopt(fd, IPPROTO_TCP, TCP_NODELAY, &one, sizeof one);
        if (receive_buffer > 0) ::setsockopt(fd, SOL_SOCKET, SO_RCVBUF, &receive_buffer, sizeof receive_buffer);
        if (source) {
            sockaddr_in from{};
            from.sin_family = AF_INET;
            if (::inet_pton(AF_INET, source, &from.sin_addr) != 1 ||
                ::bind(fd, reinterpret_cast<sockaddr*>(&from), sizeof from) != 0) {
                ::close(fd);
                throw std::runtime_error(std::string("cannot bind the client to ") + source);
            }
        }
        auto addr = loopback(port, destination);
        if (::connect(fd, reinterpret_cast<sockaddr*>(&addr), sizeof addr) != 0) {
            if (error) *error = errno;
            ::close(fd);
            return std::nullopt;
        }
        if (error) *error = 0;
        return TcpClient(fd);
    }

    // Connects or throws (for tests where connecting is not what is tested).
    static TcpClient open(std::uint16_t port, const char* destination = nullptr, int receive_buffer = 0) {
        int error = 0;
        auto client = connect(port, &error, nullptr, destination, receive_buffer);
        if (!client) throw std::runtime_error("connect to port " + std::to_string(port) + " failed: " + std::strerror(error));
        return std::move(*client);
    }

    // Sends everything; false when the peer is gone.
    bool send(std::span<const std::uint8_t> bytes) {
        std::size_t sent = 0;
        while (sent < bytes.size()) {
            auto n = ::send(fd_, bytes.data() + sent, bytes.size() - sent, MSG_NOSIGNAL);
            if (n < 0) {
                if (errno == EINTR) continue;
                return false;
            }
            sent += static_cast<std::size_t>(n);
        }
        return true;
    }
    bool send(const std::string& text) {
        return send(std::span(reinterpret_cast<const std::uint8_t*>(text.data()), text.size()));
    }

    // Waits for some bytes (whatever one read() gives), EOF, an error, or the deadline.
    RecvResult recv_some(std::chrono::milliseconds timeout = kReplyTimeout) {
        auto deadline = std::chrono::steady_clock::now() + timeout;
        for (;;) {
            pollfd p{fd_, POLLIN, 0};
            int r = ::poll(&p, 1, remaining_ms(deadline));
            if (r < 0 && errno == EINTR) continue;
            if (r < 0) return {RecvStatus::Error, {}, errno};
            if (r == 0) return {RecvStatus::Timeout, {}, 0};
            std::uint8_t buffer[65536];
            auto n = ::recv(fd_, buffer, sizeof buffer, 0);
            if (n > 0) return {RecvStatus::Data, Bytes(buffer, buffer + n), 0};
            if (n == 0) return {RecvStatus::Eof, {}, 0};
            if (errno == EINTR) continue;
            return {RecvStatus::Error, {}, errno};
        }
    }

    // The next whole response frame. Bytes after it stay buffered for the next call.
    // nullopt on timeout, EOF or undecodable bytes; `why` says which.
    std::optional<protocol::client::Response> response(Bytes* frame_bytes = nullptr,
                                                       std::chrono::milliseconds timeout = kReplyTimeout,
                                                       std::string* why = nullptr) {
        auto deadline = std::chrono::steady_clock::now() + timeout;
        for (;;) {
            bool garbage = false;
            auto r = protocol::client::parse_response(pending_, &garbage);
            if (r) {
                if (frame_bytes) frame_bytes->assign(pending_.begin(), pending_.begin() + static_cast<long>(r->size));
                pending_.erase(pending_.begin(), pending_.begin() + static_cast<long>(r->size));
                return r;
            }
            if (garbage) {
                if (why) *why = "undecodable response bytes";
                return std::nullopt;
            }
            auto got = recv_some(std::chrono::milliseconds(remaining_ms(deadline)));
            if (got.status != RecvStatus::Data) {
                if (why) *why = got.status == RecvStatus::Eof ? "EOF" : got.status == RecvStatus::Timeout ? "timeout" : "error";
                return std::nullopt;
            }
            pending_.insert(pending_.end(), got.data.begin(), got.data.end());
        }
    }

    // Exactly `count` bytes (or fewer on EOF/timeout), taken from the buffer first.
    Bytes read_exactly(std::size_t count, std::chrono::milliseconds timeout = kReplyTimeout) {
        auto deadline = std::chrono::steady_clock::now() + timeout;
        while (pending_.size() < count) {
            auto got = recv_some(std::chrono::milliseconds(remaining_ms(deadline)));
            if (got.status != RecvStatus::Data) break;
            pending_.insert(pending_.end(), got.data.begin(), got.data.end());
        }
        auto n = std::min(count, pending_.size());
        Bytes out(pending_.begin(), pending_.begin() + static_cast<long>(n));
        pending_.erase(pending_.begin(), pending_.begin() + static_cast<long>(n));
        return out;
    }

    // Waits for the server to close the connection: true on EOF or a reset.
    // Any data that arrives first is appended to `unexpected`.
    bool wait_closed(std::chrono::milliseconds timeout, Bytes* unexpected = nullptr) {
        auto deadline = std::chrono::steady_clock::now() + timeout;
        for (;;) {
            auto got = recv_some(std::chrono::milliseconds(remaining_ms(deadline)));
            if (got.status == RecvStatus::Eof) return true;
            if (got.status == RecvStatus::Error) return got.error == ECONNRESET || got.error == EPIPE;
            if (got.status == RecvStatus::Timeout) return false;
            if (unexpected) unexpected->insert(unexpected->end(), got.data.begin(), got.data.end());
        }
    }

    const Bytes& pending() const { return pending_; }

private:
    using Socket::Socket;
    Bytes pending_;
};

class UdpClient : public Socket {
public:
    // A socket bound to 127.0.0.1 on an ephemeral port.
    UdpClient() {
        fd_ = ::socket(AF_INET, SOCK_DGRAM | SOCK_CLOEXEC, 0);
        if (fd_ < 0) throw std::runtime_error("socket() failed");
        auto addr = loopback(0);
        if (::bind(fd_, reinterpret_cast<sockaddr*>(&addr), sizeof addr) != 0) throw std::runtime_error("bind failed");
    }

    std::uint16_t local_port() const {
        sockaddr_in addr{};
        socklen_t len = sizeof addr;
        ::getsockname(fd_, reinterpret_cast<sockaddr*>(&addr), &len);
        return ntohs(addr.sin_port);
    }

    bool send_to(std::uint16_t port, std::span<const std::uint8_t> bytes, const char* destination = nullptr) {
        auto addr = loopback(port, destination);
        auto n = ::sendto(fd_, bytes.data(), bytes.size(), 0, reinterpret_cast<sockaddr*>(&addr), sizeof addr);
        return n == static_cast<long>(bytes.size());
    }
    bool send_to(std::uint16_t port, const std::string& text) {
        return send_to(port, std::span(reinterpret_cast<const std::uint8_t*>(text.data()), text.size()));
    }

    // One datagram, or nullopt on timeout. `from_port` gets the sender's port.
    std::optional<Bytes> receive(std::chrono::milliseconds timeout = kReplyTimeout, std::uint16_t* from_port = nullptr) {
        auto deadline = std::chrono::steady_clock::now() + timeout;
        for (;;) {
            pollfd p{fd_, POLLIN, 0};
            int r = ::poll(&p, 1, remaining_ms(deadline));
            if (r < 0 && errno == EINTR) continue;
            if (r <= 0) return std::nullopt;
            std::uint8_t buffer[65536];
            sockaddr_in from{};
            socklen_t len = sizeof from;
            auto n = ::recvfrom(fd_, buffer, sizeof buffer, 0, reinterpret_cast<sockaddr*>(&from), &len);
            if (n < 0) {
                if (errno == EINTR) continue;
                return std::nullopt;
            }
            if (from_port) *from_port = ntohs(from.sin_port);
            return Bytes(buffer, buffer + n);
        }
    }
};

// Retries connect() until it succeeds or `timeout` passes (for a listener that reopens).
inline std::optional<TcpClient> connect_with_retry(std::uint16_t port, std::chrono::milliseconds timeout) {
    auto deadline = std::chrono::steady_clock::now() + timeout;
    for (;;) {
        if (auto c = TcpClient::connect(port)) return c;
        if (std::chrono::steady_clock::now() >= deadline) return std::nullopt;
        std::this_thread::sleep_for(std::chrono::milliseconds(20));
    }
}

}  // namespace slmp::test
