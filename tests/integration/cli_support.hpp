// Running the slmp CLI in tests, and a loopback capture server that records the
// exact request bytes the CLI sends (for commands slmp-sim does not serve yet,
// and for options such as the route and the 4E serial).
//
// The capture server accepts one TCP connection on 127.0.0.1 (ephemeral port)
// in a background thread, records every whole request frame, and answers each
// with end code 0000 + the given data (or an error end code, or nothing at all).
// Assertions happen on the test thread after requests() has joined it.
#pragma once

#include <arpa/inet.h>
#include <netinet/in.h>
#include <poll.h>
#include <sys/socket.h>
#include <unistd.h>

#include <atomic>
#include <string>
#include <thread>
#include <vector>

#include <nlohmann/json.hpp>

#include "protocol/error_response.hpp"
#include "protocol/fields.hpp"
#include "protocol/message.hpp"
#include "sim_process.hpp"
#include "sockets.hpp"

#ifndef SLMP_CLI_BINARY
#error "SLMP_CLI_BINARY must name the slmp executable under test"
#endif

namespace slmp::test {

// Runs `slmp args...` to completion (at most 20 s).
inline RunResult run_cli(const std::vector<std::string>& args) {
    return run_binary(under_test(SLMP_CLI_BINARY), args, std::chrono::seconds(20));
}

// "--host 127.0.0.1 --port N" for a running simulator, plus --udp when asked.
inline std::vector<std::string> target(std::uint16_t port, bool udp = false) {
    std::vector<std::string> args{"--host", "127.0.0.1", "--port", std::to_string(port)};
    if (udp) args.push_back("--udp");
    return args;
}

inline std::vector<std::string> operator+(std::vector<std::string> a, const std::vector<std::string>& b) {
    a.insert(a.end(), b.begin(), b.end());
    return a;
}

// The one JSON line a --json run prints.
inline nlohmann::json json_of(const RunResult& r) {
    INFO("stdout: " << r.out << "\nstderr: " << r.err);
    auto lines = lines_of(r.out);
    REQUIRE(lines.size() == 1);
    auto json = nlohmann::json::parse(lines[0], nullptr, false);
    REQUIRE_FALSE(json.is_discarded());
    return json;
}

class CaptureServer {
public:
    enum class Reply { Ok, EndCode, Silent };

    // `data` is the response data after end code 0000, already in the request's codec.
    explicit CaptureServer(Reply reply = Reply::Ok, Bytes data = {}, std::uint16_t end_code = 0)
        : reply_(reply), data_(std::move(data)), end_code_(end_code) {
        listener_ = ::socket(AF_INET, SOCK_STREAM | SOCK_CLOEXEC, 0);
        int one = 1;
        ::setsockopt(listener_, SOL_SOCKET, SO_REUSEADDR, &one, sizeof one);
        auto addr = loopback(0);
        if (::bind(listener_, reinterpret_cast<sockaddr*>(&addr), sizeof addr) != 0 || ::listen(listener_, 4) != 0)
            throw std::runtime_error("capture server: bind/listen failed");
        socklen_t len = sizeof addr;
        ::getsockname(listener_, reinterpret_cast<sockaddr*>(&addr), &len);
        port_ = ntohs(addr.sin_port);
        thread_ = std::thread([this] { serve(); });
    }
    ~CaptureServer() {
        stop_ = true;
        if (thread_.joinable()) thread_.join();
        ::close(listener_);
    }
    CaptureServer(const CaptureServer&) = delete;
    CaptureServer& operator=(const CaptureServer&) = delete;

    std::uint16_t port() const { return port_; }

    // Every request frame received, once the client has gone (joins the thread).
    const std::vector<Bytes>& requests() {
        if (thread_.joinable()) thread_.join();
        return requests_;
    }

private:
    // Waits up to 10 s for the connection, then serves it until EOF.
    void serve() {
        auto deadline = std::chrono::steady_clock::now() + std::chrono::seconds(10);
        int fd = -1;
        while (fd < 0 && !stop_ && std::chrono::steady_clock::now() < deadline) {
            pollfd p{listener_, POLLIN, 0};
            if (::poll(&p, 1, 50) > 0) fd = ::accept(listener_, nullptr, nullptr);
        }
        if (fd < 0) return;
        Socket connection(fd);
        Bytes pending;
        for (;;) {
            auto scan = protocol::scan_frame(pending, protocol::Direction::Request, protocol::DataCodePolicy::Auto, 1 << 16);
            if (scan.status == protocol::FrameScan::Status::Complete) {
                Bytes frame(pending.begin(), pending.begin() + static_cast<long>(scan.size));
                pending.erase(pending.begin(), pending.begin() + static_cast<long>(scan.size));
                requests_.push_back(frame);
                if (reply_ == Reply::Silent) return;   // like a CPU that resets: no answer, connection dropped
                auto answer = respond(scan.header, frame);
                ::send(fd, answer.data(), answer.size(), MSG_NOSIGNAL);
                continue;
            }
            if (scan.status != protocol::FrameScan::Status::NeedMore) return;
            pollfd p{fd, POLLIN, 0};
            if (::poll(&p, 1, 10000) <= 0) return;
            std::uint8_t buffer[4096];
            auto n = ::recv(fd, buffer, sizeof buffer, 0);
            if (n <= 0) return;
            pending.insert(pending.end(), buffer, buffer + n);
        }
    }

    Bytes respond(const protocol::FrameHeader& header, const Bytes& frame) {
        if (reply_ == Reply::EndCode) {
            // The request's command and subcommand go into the error information.
            protocol::FieldReader r(header.codec, std::span(frame).subspan(header.header_size));
            r.u16("timer");
            auto command = r.u16("command");
            auto subcommand = r.u16("subcommand");
            return protocol::encode_error_response(header, command, subcommand, protocol::end_code(end_code_));
        }
        protocol::FieldWriter w(header.codec);
        w.u16(0);
        w.raw(data_);
        return protocol::encode_frame(protocol::Direction::Response, header.kind, header.codec, header.serial,
                                      header.route, w.bytes());
    }

    Reply reply_;
    Bytes data_;
    std::uint16_t end_code_;
    int listener_ = -1;
    std::uint16_t port_ = 0;
    std::atomic<bool> stop_{false};
    std::thread thread_;
    std::vector<Bytes> requests_;
};

}  // namespace slmp::test
