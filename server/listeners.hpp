// The ports of one station: for each protocol face it serves (frontends/face.hpp:
// SLMP on the station's "ports", the host link, the JW-51CM computer link),
// the face's unit on the CPU's memory and a TcpListener or UdpListener per
// port of the face, bound at construction; each connection gets the inbox the
// unit asks for (station/face_inbox.hpp). They are the station's Transports,
// so a scenario's power cut closes the TCP ports and a restarted CPU gives UDP
// clients fresh sessions.
#pragma once

#include <cstdint>
#include <memory>
#include <string>
#include <vector>

#include "station/asio.hpp"

#include "config/config.hpp"
#include "config/frontend_config.hpp"
#include "frontends/face.hpp"
#include "server/face_services.hpp"
#include "server/node_search.hpp"
#include "server/serial_port.hpp"
#include "server/tcp_listener.hpp"
#include "server/udp_listener.hpp"
#include "station/station.hpp"
#include "station/transports.hpp"

namespace slmp::server {

class Listeners final : public station::Transports {
public:
    // Binds every port of every face the station serves on `bind`: the
    // faces configured by the station's own keys on `config`'s ports (SLMP),
    // the others as `frontends` says. Throws config::ConfigError naming the
    // port and the fix when one cannot be had. `shared_loop`: the home's
    // io_context is run by several threads (server/server.hpp).
    Listeners(const station::Home& home, station::Station& station, const config::ServerConfig& config,
              const config::FrontEndsConfig& frontends, const boost::asio::ip::address& bind, bool shared_loop = false);
    ~Listeners();
    Listeners(const Listeners&) = delete;
    Listeners& operator=(const Listeners&) = delete;

    // The bound ports of the faces on the station's own "ports" (SLMP), also
    // when 0 was asked for.
    std::vector<std::uint16_t> tcp_ports() const;
    std::vector<std::uint16_t> udp_ports() const;
    // A face's bound ports (empty when the station does not serve it, or it has no such port).
    std::vector<std::uint16_t> face_tcp_ports(std::string_view face) const;
    std::vector<std::uint16_t> face_udp_ports(std::string_view face) const;
    std::string serial_device() const { return serial_ ? serial_->device() : std::string(); }   // --serial's /dev/pts/N
    void stop();

    void refuse_connections(bool refusing) override;
    void restart_sessions() override;
    std::vector<station::PushTarget> push_targets() override;

private:
    // One face: its unit, and its TCP/UDP ports and serial line as its settings say.
    struct Served {
        std::unique_ptr<frontends::Unit> unit;
        std::unique_ptr<FaceServices> services;   // what the unit may ask of the station (its clock, connections out)
        std::vector<std::unique_ptr<TcpListener>> tcp;
        std::vector<std::unique_ptr<UdpListener>> udp;
    };
    void listen_face(const station::Home& home, station::Station& station, const config::ServerConfig& config,
                     const frontends::Settings& settings, const boost::asio::ip::address& bind, bool shared_loop);
    std::vector<std::uint16_t> ports_of(std::string_view face, bool tcp, bool own_section) const;

    station::Station* station_ = nullptr;   // whose frontends() name ours (cleared on destruction)
    std::vector<Served> faces_;             // in registration order (frontends/registry.cpp)
    std::unique_ptr<SerialPort> serial_;
    std::unique_ptr<NodeSearchListener> node_search_;   // a node station's broadcast search port, when configured
};

// "5000,5001", or "-" for none (log lines and the ready file).
std::string port_list(const std::vector<std::uint16_t>& ports);

}  // namespace slmp::server
