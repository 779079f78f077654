#include "server/listeners.hpp"

#include "station/face_inbox.hpp"

namespace slmp::server {

Listeners::Listeners(const station::Home& home, station::Station& station, const config::ServerConfig& config,
                     const config::FrontEndsConfig& frontends, const boost::asio::ip::address& bind, bool shared_loop) {
    for (const auto& port : config.ports) {
        try {
            if (port.transport == config::Transport::Tcp)
                tcp_.push_back(std::make_unique<TcpListener>(home, station, port, bind, shared_loop));
            else
                udp_.push_back(std::make_unique<UdpListener>(home, station, port, bind));
        } catch (const boost::system::system_error& e) {
            auto transport = port.transport == config::Transport::Tcp ? "TCP" : "UDP";
            throw config::ConfigError(std::string("cannot listen on ") + transport + " " + config.bind + ":" +
                                      std::to_string(port.port) + ": " + e.code().message() +
                                      "; choose another port (--" + (port.transport == config::Transport::Tcp ? "tcp" : "udp") +
                                      "-port) or stop the program using it");
        }
    }
    for (const auto& face : frontends.faces) listen_face(home, station, config, face, bind);
    if (!faces_.empty()) {
        station_ = &station;
        station::Station::FrontEnds units;
        for (const auto& f : faces_) units.push_back(f.unit.get());
        station.attach_frontends(std::move(units));
    }
}

void Listeners::listen_face(const station::Home& home, station::Station& station, const config::ServerConfig& config,
                            const frontends::Settings& settings, const boost::asio::ip::address& bind) {
    const auto& face = *settings.face;
    if (auto problem = face.check(station.cpu(), settings); !problem.empty()) throw config::ConfigError(problem);
    auto& served = faces_.emplace_back();
    served.unit = face.make_unit(station.cpu(), settings);
    auto* unit = served.unit.get();
    auto fail = [&](config::Transport transport, std::uint16_t port, const boost::system::system_error& e) {
        return config::ConfigError("cannot listen on the " + std::string(face.port_name()) + " " +
                                   (transport == config::Transport::Tcp ? "TCP" : "UDP") + " port " + config.bind + ":" +
                                   std::to_string(port) + ": " + e.code().message() + "; choose another port (" +
                                   face.port_fix(transport) + ") or stop the program using it");
    };
    if (settings.tcp) {
        InboxMaker face_inbox = [&station, unit](const protocol::Peer& peer, station::Feed*) {
            return std::make_unique<station::FaceInbox>(station, *unit, peer);
        };
        try {
            served.tcp = std::make_unique<TcpListener>(home, station, *settings.tcp, bind, false, std::move(face_inbox),
                                                       std::string(face.log_name()));
        } catch (const boost::system::system_error& e) {
            throw fail(config::Transport::Tcp, settings.tcp->port, e);
        }
    }
    if (settings.udp) {
        try {
            served.udp = std::make_unique<UdpListener>(home, station, *settings.udp, bind, unit);
        } catch (const boost::system::system_error& e) {
            throw fail(config::Transport::Udp, settings.udp->port, e);
        }
    }
    if (!settings.serial_path.empty()) serial_ = std::make_unique<SerialPort>(home, *unit, settings.serial_path);
}

const Listeners::Served* Listeners::served(std::string_view face) const {
    for (const auto& f : faces_)
        if (f.unit->face().name() == face) return &f;
    return nullptr;
}

std::vector<std::uint16_t> Listeners::face_tcp_ports(std::string_view face) const {
    const auto* f = served(face);
    if (!f || !f->tcp) return {};
    return {f->tcp->port()};
}

std::vector<std::uint16_t> Listeners::face_udp_ports(std::string_view face) const {
    const auto* f = served(face);
    if (!f || !f->udp) return {};
    return {f->udp->port()};
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

Listeners::~Listeners() {
    // The front ends go with the listeners: the station must not reach them after.
    if (station_) station_->frontends() = {};
}

void Listeners::stop() {
    for (auto& l : tcp_) l->stop();
    for (auto& l : udp_) l->stop();
    for (auto& f : faces_) {
        if (f.tcp) f.tcp->stop();
        if (f.udp) f.udp->stop();
    }
    if (serial_) serial_->stop();
}

void Listeners::refuse_connections(bool refusing) {
    for (auto& l : tcp_) l->set_refusing(refusing);
    for (auto& f : faces_)
        if (f.tcp) f.tcp->set_refusing(refusing);
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
