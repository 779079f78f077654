// A TCP connection's further bytes while its inbox waits on the virtual
// clock (station/inbox.hpp): readiness waits on the socket, reads that do not block.
#pragma once

#include <cstdint>
#include <functional>
#include <memory>
#include <vector>

#include "station/asio.hpp"

#include "station/inbox.hpp"

namespace slmp::server {

class SocketFeed final : public station::Feed {
public:
    explicit SocketFeed(station::StrandSocket& socket) : socket_(socket) {}
    ~SocketFeed() override { stop_watching(); }

    bool open() const override { return socket_.is_open(); }
    bool read_now(std::vector<std::uint8_t>& into) override;
    void watch(std::function<bool(bool open)> ready) override;
    void stop_watching() override;

private:
    // Shared with a readiness handler still queued after the watch ended:
    // the generation tells it that it belongs to an old one.
    struct State {
        bool watching = false;
        std::uint64_t generation = 0;
        std::function<bool(bool)> ready;
    };
    static void arm(const std::shared_ptr<State>& state, station::StrandSocket& socket);

    station::StrandSocket& socket_;
    std::shared_ptr<State> state_ = std::make_shared<State>();
};

}  // namespace slmp::server
