// The baseline server's sockets and ready file: plain BSD sockets, non-blocking.
#pragma once

#include <cerrno>
#include <cstdint>
#include <cstring>
#include <stdexcept>
#include <string>

namespace slmp::bench::baseline {

// Throws std::runtime_error naming `what` and errno's text.
[[noreturn]] inline void fail(const std::string& what) {
    throw std::runtime_error(what + ": " + std::strerror(errno));
}

// A non-blocking TCP listener (SOCK_STREAM) or UDP socket (SOCK_DGRAM) bound to
// `bind`:`port`; `reuse_port` lets several UDP sockets share the port, one per
// thread. Throws std::invalid_argument for a bind address that is not numeric,
// std::runtime_error when the socket cannot be opened.
int open_socket(const std::string& bind, std::uint16_t port, int type, bool reuse_port);

// The port a socket is bound to (after port 0).
std::uint16_t bound_port(int fd);

// {"tcp":[P],"udp":[P],"threads":N,"pid":N}, written atomically (a temporary
// file renamed), so a reader never sees half of it.
void write_ready_file(const std::string& path, std::uint16_t tcp, std::uint16_t udp, unsigned threads);

}  // namespace slmp::bench::baseline
