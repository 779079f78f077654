#include "tools/bench/baseline_server.hpp"

#include <netinet/in.h>
#include <netinet/tcp.h>
#include <pthread.h>
#include <signal.h>
#include <sys/epoll.h>
#include <sys/eventfd.h>
#include <sys/socket.h>
#include <unistd.h>

#include <cerrno>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <iostream>
#include <memory>
#include <span>
#include <stdexcept>
#include <thread>
#include <vector>

#include "tools/bench/baseline_answer.hpp"
#include "tools/bench/baseline_sockets.hpp"

namespace slmp::bench::baseline {

namespace {

// Room for two of the largest requests, so a whole one always fits after a partial one.
constexpr std::size_t kInputBytes = 2 * kMaxRequestBytes;
constexpr std::size_t kDatagramBytes = 65536;
constexpr int kEventsPerWait = 256;
// Datagrams taken per wake-up before the thread looks at its other sockets again.
constexpr int kDatagramsPerWake = 64;

// What an epoll event is about: the kind in the high half of its data, the fd in the low.
enum class Kind : std::uint32_t { Stop, Listener, Udp, Tcp };
std::uint64_t tag(Kind kind, int fd) { return (static_cast<std::uint64_t>(kind) << 32) | static_cast<std::uint32_t>(fd); }

struct Connection {
    std::vector<std::uint8_t> in = std::vector<std::uint8_t>(kInputBytes);
    std::size_t filled = 0;
    std::vector<std::uint8_t> out;   // answers not yet sent are out[sent, size)
    std::size_t sent = 0;
};

class Worker;

// The sockets every worker may need: the listener's accepted connections are
// dealt to all of them.
struct Shared {
    std::vector<std::unique_ptr<Worker>> workers;
    unsigned next_worker = 0;   // only thread 0 accepts
};

class Worker {
public:
    Worker() : epoll_(::epoll_create1(EPOLL_CLOEXEC)) {
        if (epoll_ < 0) fail("epoll_create1");
    }
    ~Worker() { ::close(epoll_); }

    // Level-triggered. epoll_ctl is safe from any thread, which is how thread 0
    // hands an accepted connection to another worker.
    void watch(int fd, Kind kind, std::uint32_t events = EPOLLIN) {
        epoll_event event{};
        event.events = events;
        event.data.u64 = tag(kind, fd);
        if (::epoll_ctl(epoll_, EPOLL_CTL_ADD, fd, &event) != 0) fail("epoll_ctl");
    }

    void run(Shared& shared);

private:
    void accept_all(int listener, Shared& shared);
    void on_connection(int fd);
    bool take_requests(int fd, Connection& c);
    bool flush(int fd, Connection& c);
    void on_datagrams(int fd);
    void set_interest(int fd, std::uint32_t events);
    void drop(int fd);
    Connection& connection(int fd);

    int epoll_;
    // By fd. Made on a connection's first event, by the thread that owns it, so
    // no connection state is ever touched by two threads.
    std::vector<std::unique_ptr<Connection>> connections_;
    std::vector<std::uint8_t> datagram_ = std::vector<std::uint8_t>(kDatagramBytes);
    std::vector<std::uint8_t> datagram_out_;
};

void Worker::run(Shared& shared) {
    epoll_event events[kEventsPerWait];
    for (;;) {
        int n = ::epoll_wait(epoll_, events, kEventsPerWait, -1);
        if (n < 0) {
            if (errno == EINTR) continue;
            fail("epoll_wait");
        }
        for (int i = 0; i < n; ++i) {
            auto kind = static_cast<Kind>(events[i].data.u64 >> 32);
            int fd = static_cast<int>(events[i].data.u64 & 0xFFFFFFFFu);
            switch (kind) {
            case Kind::Stop: return;
            case Kind::Listener: accept_all(fd, shared); break;
            case Kind::Udp: on_datagrams(fd); break;
            case Kind::Tcp: on_connection(fd); break;
            }
        }
    }
}

void Worker::accept_all(int listener, Shared& shared) {
    for (;;) {
        int fd = ::accept4(listener, nullptr, nullptr, SOCK_NONBLOCK | SOCK_CLOEXEC);
        if (fd < 0) {
            if (errno == EINTR || errno == ECONNABORTED) continue;
            return;   // EAGAIN: all taken; EMFILE and the like: the client sees its connect hang
        }
        int one = 1;
        ::setsockopt(fd, IPPROTO_TCP, TCP_NODELAY, &one, sizeof one);
        auto& worker = *shared.workers[shared.next_worker++ % shared.workers.size()];
        worker.watch(fd, Kind::Tcp);
    }
}

Connection& Worker::connection(int fd) {
    auto index = static_cast<std::size_t>(fd);
    if (index >= connections_.size()) connections_.resize(index + 1);
    if (!connections_[index]) connections_[index] = std::make_unique<Connection>();
    return *connections_[index];
}

void Worker::drop(int fd) {
    connections_[static_cast<std::size_t>(fd)].reset();
    ::close(fd);   // also takes it out of the epoll set
}

void Worker::set_interest(int fd, std::uint32_t events) {
    epoll_event event{};
    event.events = events;
    event.data.u64 = tag(Kind::Tcp, fd);
    ::epoll_ctl(epoll_, EPOLL_CTL_MOD, fd, &event);
}

void Worker::on_connection(int fd) {
    Connection& c = connection(fd);
    if (c.sent < c.out.size()) {   // waiting to send: EPOLLOUT (or an error) is what woke us
        if (!flush(fd, c)) return drop(fd);
        if (c.sent == c.out.size()) set_interest(fd, EPOLLIN);
        return;
    }
    // EPOLLIN, EPOLLHUP or EPOLLERR woke us: recv says which.
    ssize_t n = ::recv(fd, c.in.data() + c.filled, c.in.size() - c.filled, 0);
    if (n < 0 && (errno == EAGAIN || errno == EINTR)) return;
    if (n <= 0) return drop(fd);
    c.filled += static_cast<std::size_t>(n);
    if (!take_requests(fd, c)) return drop(fd);
}

// Answers every whole request in the buffer with one send. While an answer
// cannot be sent whole, the connection waits for EPOLLOUT and reads nothing:
// a client that does not read its answers stops being served, not the server.
bool Worker::take_requests(int fd, Connection& c) {
    std::size_t head = 0;
    for (;;) {
        auto answered = answer_request(std::span(c.in).subspan(head, c.filled - head), c.out);
        if (answered.status == Answered::Status::Invalid) return false;
        if (answered.status == Answered::Status::NeedMore) break;
        head += answered.size;
    }
    if (head > 0) {
        std::memmove(c.in.data(), c.in.data() + head, c.filled - head);
        c.filled -= head;
    }
    if (c.out.empty()) return true;
    if (!flush(fd, c)) return false;
    if (c.sent < c.out.size()) set_interest(fd, EPOLLOUT);
    return true;
}

// Sends what it can; true unless the connection is broken. Clears `out` once all went.
bool Worker::flush(int fd, Connection& c) {
    while (c.sent < c.out.size()) {
        ssize_t n = ::send(fd, c.out.data() + c.sent, c.out.size() - c.sent, MSG_NOSIGNAL | MSG_DONTWAIT);
        if (n < 0) {
            if (errno == EINTR) continue;
            return errno == EAGAIN;
        }
        c.sent += static_cast<std::size_t>(n);
    }
    c.out.clear();
    c.sent = 0;
    return true;
}

// One datagram is one request; anything else in it (or a part of one) is dropped.
void Worker::on_datagrams(int fd) {
    for (int i = 0; i < kDatagramsPerWake; ++i) {
        sockaddr_storage peer{};
        socklen_t peer_size = sizeof peer;
        ssize_t n = ::recvfrom(fd, datagram_.data(), datagram_.size(), MSG_DONTWAIT,
                               reinterpret_cast<sockaddr*>(&peer), &peer_size);
        if (n < 0) return;   // EAGAIN: none left (level-triggered, so more wake us again)
        datagram_out_.clear();
        auto answered = answer_request(std::span(datagram_).first(static_cast<std::size_t>(n)), datagram_out_);
        if (answered.status != Answered::Status::Done || answered.size != static_cast<std::size_t>(n)) continue;
        ::sendto(fd, datagram_out_.data(), datagram_out_.size(), MSG_DONTWAIT, reinterpret_cast<sockaddr*>(&peer),
                 peer_size);
    }
}

}  // namespace

int serve(const ServerOptions& options) {
    // SIGINT and SIGTERM are taken by sigwait() below, in this thread only:
    // blocked before the workers start, so they inherit the mask.
    sigset_t stop_signals;
    sigemptyset(&stop_signals);
    sigaddset(&stop_signals, SIGINT);
    sigaddset(&stop_signals, SIGTERM);
    pthread_sigmask(SIG_BLOCK, &stop_signals, nullptr);

    std::vector<int> sockets;
    Shared shared;
    int stop = -1;
    try {
        int listener = open_socket(options.bind, options.tcp_port, SOCK_STREAM, false);
        sockets.push_back(listener);
        std::uint16_t tcp_port = bound_port(listener);
        std::uint16_t udp_port = options.udp_port;
        stop = ::eventfd(0, EFD_CLOEXEC | EFD_NONBLOCK);
        if (stop < 0) fail("eventfd");
        for (unsigned k = 0; k < options.threads; ++k) {
            auto worker = std::make_unique<Worker>();
            int udp = open_socket(options.bind, udp_port, SOCK_DGRAM, true);
            sockets.push_back(udp);
            udp_port = bound_port(udp);   // the first fixes port 0; the others share it
            worker->watch(udp, Kind::Udp);
            worker->watch(stop, Kind::Stop);   // never read: it wakes every worker for good
            shared.workers.push_back(std::move(worker));
        }
        shared.workers[0]->watch(listener, Kind::Listener);
        std::cerr << "slmp-bench baseline server: tcp " << options.bind << ":" << tcp_port << ", udp " << options.bind
                  << ":" << udp_port << ", " << options.threads << " thread(s), pid " << ::getpid() << '\n';
        if (!options.ready_file.empty()) write_ready_file(options.ready_file, tcp_port, udp_port, options.threads);
    } catch (const std::invalid_argument&) {
        throw;
    } catch (const std::exception& e) {
        std::cerr << "slmp-bench: baseline server: " << e.what() << '\n';
        return 1;
    }

    std::vector<std::thread> threads;
    for (auto& worker : shared.workers)
        threads.emplace_back([&shared, w = worker.get()] {
            try {
                w->run(shared);
            } catch (const std::exception& e) {
                std::cerr << "slmp-bench: baseline server: " << e.what() << '\n';
                std::_Exit(1);
            }
        });
    int signal = 0;
    sigwait(&stop_signals, &signal);
    std::uint64_t one = 1;
    if (::write(stop, &one, sizeof one) < 0) std::_Exit(1);
    for (auto& t : threads) t.join();
    shared.workers.clear();   // closes the epoll sets; connections close with the process
    for (int fd : sockets) ::close(fd);
    ::close(stop);
    return 0;
}

}  // namespace slmp::bench::baseline
