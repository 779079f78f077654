// The ports of one station: a TcpListener or UdpListener per configured SLMP
// port, and the host-link port when the station serves Host Link (its
// HostLink front end answers on the same CPU memory), bound at construction. They are the station's Transports, so a
// scenario's power cut closes the TCP ports and a restarted CPU gives UDP
// clients fresh sessions.
#pragma once

#include <cstdint>
#include <memory>
#include <string>
#include <vector>

#include "station/asio.hpp"

#include "config/config.hpp"
#include "config/frontend_config.hpp"
#include "frontends/hostlink/host_link.hpp"
#include "frontends/jw51cm/computer_link.hpp"
#include "server/frontend_udp_listener.hpp"
#include "server/serial_port.hpp"
#include "server/tcp_listener.hpp"
#include "server/udp_listener.hpp"
#include "station/station.hpp"
#include "station/transports.hpp"

namespace slmp::server {

class Listeners final : public station::Transports {
public:
    // Binds every port of `config` on `bind`; throws config::ConfigError naming
    // the port and the fix when one cannot be had.
    Listeners(const station::Home& home, station::Station& station, const config::ServerConfig& config,
              const config::FrontEndsConfig& frontends, const boost::asio::ip::address& bind);
    ~Listeners();
    Listeners(const Listeners&) = delete;
    Listeners& operator=(const Listeners&) = delete;

    std::vector<std::uint16_t> tcp_ports() const;   // bound ports, also when 0 was asked for
    std::vector<std::uint16_t> udp_ports() const;
    std::vector<std::uint16_t> hostlink_ports() const;   // empty when the station serves no Host Link
    std::string serial_device() const { return serial_ ? serial_->device() : std::string(); }   // --serial's /dev/pts/N
    std::vector<std::uint16_t> jw51cm_tcp_ports() const;   // empty when it has no JW-51CM TCP port
    std::vector<std::uint16_t> jw51cm_udp_ports() const;
    void stop();

    void refuse_connections(bool refusing) override;
    void restart_sessions() override;
    std::vector<station::PushTarget> push_targets() override;

private:
    void listen_hostlink(const station::Home& home, station::Station& station, const config::ServerConfig& config,
                         const config::HostLinkConfig& hostlink, const boost::asio::ip::address& bind);
    void listen_jw51cm(const station::Home& home, station::Station& station, const config::ServerConfig& config,
                       const config::Jw51cmConfig& jw, const boost::asio::ip::address& bind);

    station::Station* station_ = nullptr;   // whose frontends() name ours (cleared on destruction)
    std::vector<std::unique_ptr<TcpListener>> tcp_;
    std::vector<std::unique_ptr<UdpListener>> udp_;
    std::unique_ptr<hostlink::HostLink> hostlink_;
    std::unique_ptr<TcpListener> hostlink_tcp_;
    std::unique_ptr<SerialPort> serial_;
    std::unique_ptr<jw51cm::ComputerLink> jw51cm_;
    std::unique_ptr<TcpListener> jw51cm_tcp_;
    std::unique_ptr<FrontEndUdpListener> jw51cm_udp_;
};

// "5000,5001", or "-" for none (log lines and the ready file).
std::string port_list(const std::vector<std::uint16_t>& ports);

}  // namespace slmp::server
