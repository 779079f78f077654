#include "server/listeners.hpp"

namespace slmp::server {

Listeners::Listeners(boost::asio::io_context& io, station::Station& station, const config::ServerConfig& config,
                     const boost::asio::ip::address& bind) {
    for (const auto& port : config.ports) {
        try {
            if (port.transport == config::Transport::Tcp)
                tcp_.push_back(std::make_unique<TcpListener>(io, station, port, bind));
            else
                udp_.push_back(std::make_unique<UdpListener>(io, station, port, bind));
        } catch (const boost::system::system_error& e) {
            auto transport = port.transport == config::Transport::Tcp ? "TCP" : "UDP";
            throw config::ConfigError(std::string("cannot listen on ") + transport + " " + config.bind + ":" +
                                      std::to_string(port.port) + ": " + e.code().message() +
                                      "; choose another port (--" + (port.transport == config::Transport::Tcp ? "tcp" : "udp") +
                                      "-port) or stop the program using it");
        }
    }
}

std::vector<std::uint16_t> Listeners::tcp_ports() const {
    std::vector<std::uint16_t> ports;
    for (const auto& l : tcp_) ports.push_back(l->port());
    return ports;
}

std::vector<std::uint16_t> Listeners::udp_ports() const {
    std::vector<std::uint16_t> ports;
    for (const auto& l : udp_) ports.push_back(l->port());
    return ports;
}

void Listeners::stop() {
    for (auto& l : tcp_) l->stop();
    for (auto& l : udp_) l->stop();
}

void Listeners::refuse_connections(bool refusing) {
    for (auto& l : tcp_) l->set_refusing(refusing);
}

void Listeners::restart_sessions() {
    for (auto& l : udp_) l->restart_session();
}

std::vector<station::PushTarget> Listeners::push_targets() {
    std::vector<station::PushTarget> targets;
    for (auto& l : tcp_) l->push_targets(targets);
    for (auto& l : udp_) l->push_targets(targets);
    return targets;
}

std::string port_list(const std::vector<std::uint16_t>& ports) {
    std::string text;
    for (auto port : ports) text += (text.empty() ? "" : ",") + std::to_string(port);
    return text.empty() ? "-" : text;
}

}  // namespace slmp::server
