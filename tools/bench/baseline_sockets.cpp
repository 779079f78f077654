#include "tools/bench/baseline_sockets.hpp"

#include <netdb.h>
#include <netinet/in.h>
#include <sys/socket.h>
#include <unistd.h>

#include <cerrno>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <memory>
#include <stdexcept>

namespace slmp::bench::baseline {

namespace {

addrinfo* numeric_address(const std::string& bind, std::uint16_t port, int type) {
    addrinfo hints{};
    hints.ai_flags = AI_NUMERICHOST | AI_NUMERICSERV | AI_PASSIVE;
    hints.ai_socktype = type;
    addrinfo* found = nullptr;
    if (::getaddrinfo(bind.c_str(), std::to_string(port).c_str(), &hints, &found) != 0 || !found)
        throw std::invalid_argument("--bind " + bind + " is not a numeric IPv4 or IPv6 address");
    return found;
}

}  // namespace

std::uint16_t bound_port(int fd) {
    sockaddr_storage address{};
    socklen_t size = sizeof address;
    ::getsockname(fd, reinterpret_cast<sockaddr*>(&address), &size);
    if (address.ss_family == AF_INET6) return ntohs(reinterpret_cast<sockaddr_in6*>(&address)->sin6_port);
    return ntohs(reinterpret_cast<sockaddr_in*>(&address)->sin_port);
}

int open_socket(const std::string& bind, std::uint16_t port, int type, bool reuse_port) {
    std::unique_ptr<addrinfo, decltype(&::freeaddrinfo)> address(numeric_address(bind, port, type), ::freeaddrinfo);
    int fd = ::socket(address->ai_family, type | SOCK_NONBLOCK | SOCK_CLOEXEC, 0);
    if (fd < 0) fail("socket");
    int one = 1;
    ::setsockopt(fd, SOL_SOCKET, SO_REUSEADDR, &one, sizeof one);
    if (reuse_port) ::setsockopt(fd, SOL_SOCKET, SO_REUSEPORT, &one, sizeof one);
    std::string where = (type == SOCK_STREAM ? "tcp " : "udp ") + bind + ":" + std::to_string(port);
    if (::bind(fd, address->ai_addr, address->ai_addrlen) != 0) fail("cannot bind " + where);
    if (type == SOCK_STREAM && ::listen(fd, SOMAXCONN) != 0) fail("cannot listen on " + where);
    return fd;
}

void write_ready_file(const std::string& path, std::uint16_t tcp, std::uint16_t udp, unsigned threads) {
    auto temporary = path + ".tmp";
    {
        std::ofstream file(temporary, std::ios::trunc);
        file << "{\"tcp\":[" << tcp << "],\"udp\":[" << udp << "],\"threads\":" << threads << ",\"pid\":" << ::getpid()
             << "}\n";
        if (!file) throw std::runtime_error("cannot write the ready file " + temporary);
    }
    std::filesystem::rename(temporary, path);   // readers never see half a file
}

}  // namespace slmp::bench::baseline
