// One request, one response, over TCP or UDP: lets the same test body run on
// both transports.
#pragma once

#include <catch2/catch.hpp>

#include <memory>
#include <string>

#include "frames.hpp"
#include "sockets.hpp"

namespace slmp::test {

class Link {
public:
    virtual ~Link() = default;
    virtual std::string name() const = 0;
    // Sends `request` and returns the bytes of one response frame (empty on timeout/EOF).
    virtual Bytes exchange(const Bytes& request) = 0;
};

class TcpLink : public Link {
public:
    explicit TcpLink(std::uint16_t port) : client_(TcpClient::open(port)) {}
    std::string name() const override { return "TCP"; }
    Bytes exchange(const Bytes& request) override {
        if (!client_.send(request)) return {};
        Bytes frame;
        std::string why;
        if (!client_.response(&frame, kReplyTimeout, &why)) {
            UNSCOPED_INFO("TCP: no response (" << why << "); pending bytes: " << show(client_.pending()));
            return {};
        }
        return frame;
    }
    TcpClient& client() { return client_; }

private:
    TcpClient client_;
};

class UdpLink : public Link {
public:
    explicit UdpLink(std::uint16_t port) : port_(port) {}
    std::string name() const override { return "UDP"; }
    Bytes exchange(const Bytes& request) override {
        if (!client_.send_to(port_, request)) return {};
        auto reply = client_.receive();
        if (!reply) {
            UNSCOPED_INFO("UDP: no response datagram");
            return {};
        }
        return *reply;
    }

    UdpClient& client() { return client_; }

private:
    std::uint16_t port_;
    UdpClient client_;
};

// A request frame built by hand from the manual's layout (§3.1.1), own-station
// route, around `body` = monitoring timer + command + subcommand + data, already
// in the frame's codec. Independent of the project's encoder.
inline Bytes request_frame(const Wire& w, const Bytes& body) {
    Bytes out;
    if (w.codec == Codec::Binary) {
        if (w.kind == FrameKind::E3) out = {0x50, 0x00};
        else out = {0x54, 0x00, std::uint8_t(w.serial & 0xFF), std::uint8_t(w.serial >> 8), 0x00, 0x00};
        Bytes route = {0x00, 0xFF, 0xFF, 0x03, 0x00, std::uint8_t(body.size() & 0xFF), std::uint8_t(body.size() >> 8)};
        out.insert(out.end(), route.begin(), route.end());
    } else {
        std::string head = w.kind == FrameKind::E3 ? "5000" : "5400" + hex_digits(w.serial, 4) + "0000";
        head += "00FF03FF00" + hex_digits(static_cast<std::uint32_t>(body.size()), 4);
        out = text(head);
    }
    out.insert(out.end(), body.begin(), body.end());
    return out;
}

}  // namespace slmp::test
