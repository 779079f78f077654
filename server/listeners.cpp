#include "server/listeners.hpp"

namespace slmp::server {

namespace {

// A face's settings as the station serves them: a face configured by the
// station's own keys (Face::own_section false: SLMP) on `config`'s ports,
// when it names any; another as its section or options turned it on.
std::vector<frontends::Settings> served_faces(const config::ServerConfig& config, const config::FrontEndsConfig& frontends) {
    std::vector<frontends::Settings> list;
    for (const auto* face : frontends::all_faces()) {
        if (face->own_section()) {
            if (const auto* settings = frontends.find(face->name())) list.push_back(*settings);
        } else if (!config.ports.empty()) {
            auto settings = face->defaults();
            settings.ports = config.ports;
            list.push_back(std::move(settings));
        }
    }
    return list;
}

}  // namespace

Listeners::Listeners(const station::Home& home, station::Station& station, const config::ServerConfig& config,
                     const config::FrontEndsConfig& frontends, const boost::asio::ip::address& bind, bool shared_loop) {
    for (const auto& settings : served_faces(config, frontends)) listen_face(home, station, config, settings, bind, shared_loop);
    // Node search by broadcast: only a port that serves the node commands answers it (docs/nodes.md).
    if (config.node_search.port != 0 && station.engine().port().node_commands) {
        const auto udp = udp_ports();
        try {
            node_search_ = std::make_unique<NodeSearchListener>(home, station, config.node_search, bind,
                                                                udp.empty() ? config.node_search.port : udp.front());
        } catch (const boost::system::system_error& e) {
            throw config::ConfigError("cannot listen for node search on UDP " +
                                      NodeSearchListener::search_address(bind).to_string() + ":" +
                                      std::to_string(config.node_search.port) + ": " + e.code().message() +
                                      "; choose another \"node_search\" port");
        }
    }
    if (!faces_.empty()) {
        station_ = &station;
        station::Station::FrontEnds units;
        for (const auto& f : faces_) units.push_back(f.unit.get());
        station.attach_frontends(std::move(units));
        for (const auto& f : faces_) f.unit->power_on();   // after the state directory gave back their memory
    }
}

void Listeners::listen_face(const station::Home& home, station::Station& station, const config::ServerConfig& config,
                            const frontends::Settings& settings, const boost::asio::ip::address& bind, bool shared_loop) {
    const auto& face = *settings.face;
    if (auto problem = face.check(station.cpu(), settings); !problem.empty()) throw config::ConfigError(problem);
    auto& served = faces_.emplace_back();
    served.unit = face.make_unit(station.cpu(), settings);
    served.services = std::make_unique<FaceServices>(home, station);
    auto& unit = *served.unit;
    unit.attach(*served.services);
    std::vector<config::PortConfig> ports;
    if (settings.tcp) ports.push_back(*settings.tcp);
    if (settings.udp) ports.push_back(*settings.udp);
    ports.insert(ports.end(), settings.ports.begin(), settings.ports.end());
    for (const auto& port : ports) {
        try {
            if (port.transport == config::Transport::Tcp)
                served.tcp.push_back(std::make_unique<TcpListener>(home, station, unit, port, bind, shared_loop));
            else
                served.udp.push_back(std::make_unique<UdpListener>(home, station, unit, port, bind));
        } catch (const boost::system::system_error& e) {
            throw config::ConfigError("cannot listen on " + face.port_noun(port.transport) + " " + config.bind + ":" +
                                      std::to_string(port.port) + ": " + e.code().message() + "; choose another port (" +
                                      face.port_fix(port.transport) + ") or stop the program using it");
        }
    }
    if (!settings.serial_path.empty()) serial_ = std::make_unique<SerialPort>(home, unit, settings.serial_path);
}

// `face`'s ports, or (empty `face`) those of the faces whose `own_section` is as given.
std::vector<std::uint16_t> Listeners::ports_of(std::string_view face, bool tcp, bool own_section) const {
    std::vector<std::uint16_t> ports;
    for (const auto& f : faces_) {
        const auto& kind = f.unit->face();
        if (face.empty() ? kind.own_section() != own_section : kind.name() != face) continue;
        if (tcp)
            for (const auto& l : f.tcp) ports.push_back(l->port());
        else
            for (const auto& l : f.udp) ports.push_back(l->port());
    }
    return ports;
}

std::vector<std::uint16_t> Listeners::face_tcp_ports(std::string_view face) const { return ports_of(face, true, true); }
std::vector<std::uint16_t> Listeners::face_udp_ports(std::string_view face) const { return ports_of(face, false, true); }
std::vector<std::uint16_t> Listeners::tcp_ports() const { return ports_of({}, true, false); }
std::vector<std::uint16_t> Listeners::udp_ports() const { return ports_of({}, false, false); }

Listeners::~Listeners() {
    // The front ends go with the listeners: the station must not reach them after.
    if (station_) station_->frontends() = {};
}

void Listeners::stop() {
    for (auto& f : faces_) {
        for (auto& l : f.tcp) l->stop();
        for (auto& l : f.udp) l->stop();
        f.services->stop();
    }
    if (serial_) serial_->stop();
    if (node_search_) node_search_->stop();
}

void Listeners::refuse_connections(bool refusing) {
    for (auto& f : faces_)
        for (auto& l : f.tcp) l->set_refusing(refusing);
}

void Listeners::restart_sessions() {
    for (auto& f : faces_) {
        for (auto& l : f.udp) l->restart_session();
        f.unit->power_on();
    }
}

std::vector<station::PushTarget> Listeners::push_targets() {
    std::vector<station::PushTarget> targets;
    for (auto& f : faces_) {
        for (auto& l : f.tcp) l->push_targets(targets);
        for (auto& l : f.udp) l->push_targets(targets);
    }
    return targets;
}

std::string port_list(const std::vector<std::uint16_t>& ports) {
    std::string text;
    for (auto port : ports) text += (text.empty() ? "" : ",") + std::to_string(port);
    return text.empty() ? "-" : text;
}

}  // namespace slmp::server
