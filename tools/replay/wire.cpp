#include "tools/replay/wire.hpp"

#include <netdb.h>
#include <netinet/in.h>
#include <netinet/tcp.h>
#include <poll.h>
#include <sys/socket.h>
#include <unistd.h>

#include <cerrno>
#include <cstring>
#include <stdexcept>

#include "protocol/client.hpp"

namespace slmp::replay {

Wire::Wire(const std::string& host, std::uint16_t port, bool udp) : udp_(udp) {
    addrinfo hints{};
    hints.ai_family = AF_UNSPEC;
    hints.ai_socktype = udp ? SOCK_DGRAM : SOCK_STREAM;
    addrinfo* found = nullptr;
    if (int rc = ::getaddrinfo(host.c_str(), std::to_string(port).c_str(), &hints, &found); rc != 0)
        throw std::runtime_error("cannot resolve '" + host + "': " + ::gai_strerror(rc));
    std::string error = "no address";
    for (auto* a = found; a && fd_ < 0; a = a->ai_next) {
        fd_ = ::socket(a->ai_family, a->ai_socktype | SOCK_CLOEXEC, a->ai_protocol);
        if (fd_ < 0) continue;
        if (::connect(fd_, a->ai_addr, a->ai_addrlen) == 0) break;
        error = std::strerror(errno);
        ::close(fd_);
        fd_ = -1;
    }
    ::freeaddrinfo(found);
    if (fd_ < 0) throw std::runtime_error("cannot connect to " + host + ":" + std::to_string(port) + ": " + error);
    int one = 1;
    if (!udp) ::setsockopt(fd_, IPPROTO_TCP, TCP_NODELAY, &one, sizeof one);
}

Wire::~Wire() {
    if (fd_ >= 0) ::close(fd_);
}

bool Wire::send(std::span<const std::uint8_t> bytes) {
    std::size_t sent = 0;
    while (sent < bytes.size()) {
        auto n = ::send(fd_, bytes.data() + sent, bytes.size() - sent, MSG_NOSIGNAL);
        if (n < 0 && errno == EINTR) continue;
        if (n < 0) return false;
        sent += static_cast<std::size_t>(n);
    }
    return true;
}

std::optional<Bytes> Wire::receive(std::chrono::milliseconds timeout, std::string& why) {
    auto deadline = std::chrono::steady_clock::now() + timeout;
    for (;;) {
        if (!pending_.empty()) {
            if (udp_) {   // one datagram is one answer, whatever it holds
                Bytes out;
                out.swap(pending_);
                return out;
            }
            bool garbage = false;
            if (auto r = protocol::client::parse_response(pending_, &garbage)) {
                Bytes out(pending_.begin(), pending_.begin() + static_cast<long>(r->size));
                pending_.erase(pending_.begin(), pending_.begin() + static_cast<long>(r->size));
                return out;
            }
            if (garbage) {   // not a response frame: hand back everything so the report shows it
                why = "undecodable bytes";
                Bytes out;
                out.swap(pending_);
                return out;
            }
        }
        auto left = std::chrono::duration_cast<std::chrono::milliseconds>(deadline - std::chrono::steady_clock::now());
        if (left.count() <= 0) {
            why = "timeout";
            return std::nullopt;
        }
        pollfd p{fd_, POLLIN, 0};
        int r = ::poll(&p, 1, static_cast<int>(left.count()));
        if (r < 0 && errno == EINTR) continue;
        if (r <= 0) continue;
        std::uint8_t buffer[65536];
        auto n = ::recv(fd_, buffer, sizeof buffer, 0);
        if (n > 0) {
            pending_.insert(pending_.end(), buffer, buffer + n);
            continue;
        }
        if (n < 0 && errno == EINTR) continue;
        refused_ = n < 0 && errno == ECONNREFUSED;
        why = n == 0 ? "connection closed" : errno == ECONNRESET ? "connection reset" : std::strerror(errno);
        return std::nullopt;
    }
}

}  // namespace slmp::replay
