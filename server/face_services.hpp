// What a station offers the protocol faces' units beyond serving requests
// (frontends/face.hpp, StationServices): a wait on the station's clock and
// connections out of it over TCP or UDP, all on the station's strand. The
// JW-51CM's SEND/RECEIVE uses them; the face knows no sockets.
#pragma once

#include <memory>
#include <vector>

#include "station/asio.hpp"

#include "frontends/face.hpp"
#include "station/station.hpp"

namespace slmp::server {

struct OutgoingSockets;   // one connection out's sockets (face_services.cpp)

class FaceServices final : public frontends::StationServices {
public:
    FaceServices(station::Home home, station::Station& station) : home_(std::move(home)), station_(station) {}
    void after(std::chrono::milliseconds timer, std::function<bool()> wanted, std::function<void()> then) override;
    std::unique_ptr<frontends::Outgoing> connect(protocol::Transport transport, const std::string& address,
                                                 std::uint16_t port) override;
    // Shutdown: every connection out closes (a pending read would keep the
    // event loop running) and no wait calls its unit any more.
    void stop();

private:
    station::Home home_;
    station::Station& station_;
    std::shared_ptr<bool> stopped_ = std::make_shared<bool>(false);
    std::vector<std::weak_ptr<OutgoingSockets>> links_;   // to close at stop()
};

}  // namespace slmp::server
