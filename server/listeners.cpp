#include "server/listeners.hpp"

#include "server/frontend_session.hpp"

namespace slmp::server {

Listeners::Listeners(boost::asio::io_context& io, station::Station& station, const config::ServerConfig& config,
                     const config::FrontEndsConfig& frontends, const boost::asio::ip::address& bind) {
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
    if (frontends.hostlink.enabled) listen_hostlink(io, station, config, frontends.hostlink, bind);
    if (frontends.jw51cm.enabled) listen_jw51cm(io, station, config, frontends.jw51cm, bind);
}

namespace {

std::string as_text(std::span<const std::uint8_t> bytes) { return std::string(bytes.begin(), bytes.end()); }

}  // namespace

void Listeners::listen_hostlink(boost::asio::io_context& io, station::Station& station,
                                const config::ServerConfig& config, const config::HostLinkConfig& hostlink,
                                const boost::asio::ip::address& bind) {
    if (auto problem = hostlink.options->map.check(station.cpu().memory()); !problem.empty())
        throw config::ConfigError(problem);
    hostlink_ = std::make_unique<hostlink::HostLink>(station.cpu(), *hostlink.options);
    auto* link = hostlink_.get();
    auto port = hostlink.port;
    SessionFactory factory = [&station, link, port](boost::asio::ip::tcp::socket socket,
                                                    std::function<void(StreamSession*)> on_closed,
                                                    std::function<std::size_t()>) -> std::shared_ptr<StreamSession> {
        // The connection's own state (its QQMR list) lives in its handler.
        auto state = std::make_shared<hostlink::LinkState>();
        FrontEndHandler handler = [link, state](std::span<const std::uint8_t> pending) {
            auto result = link->handle(pending, *state);
            return FrontEndStep{result.kind == hostlink::Cut::Kind::NeedMore, result.consumed, result.response};
        };
        return std::make_shared<FrontEndSession>(std::move(socket), station, "host link", std::move(handler), port,
                                                 std::move(on_closed));
    };
    try {
        hostlink_tcp_ = std::make_unique<TcpListener>(io, station, port, bind, std::move(factory));
    } catch (const boost::system::system_error& e) {
        throw config::ConfigError("cannot listen on the host-link TCP port " + config.bind + ":" +
                                  std::to_string(port.port) + ": " + e.code().message() +
                                  "; choose another port (\"hostlink\": {\"tcp_port\": ...} or --hostlink-port) "
                                  "or stop the program using it");
    }
    if (!hostlink.serial_path.empty()) serial_ = std::make_unique<SerialPort>(io, *hostlink_, hostlink.serial_path);
}

void Listeners::listen_jw51cm(boost::asio::io_context& io, station::Station& station, const config::ServerConfig& config,
                              const config::Jw51cmConfig& jw, const boost::asio::ip::address& bind) {
    jw51cm_ = std::make_unique<jw51cm::ComputerLink>(station.cpu(), *jw.options);
    if (auto problem = jw51cm_->map().check(station.cpu().memory()); !problem.empty()) throw config::ConfigError(problem);
    auto* link = jw51cm_.get();
    auto fail = [&](const char* transport, std::uint16_t port, const boost::system::system_error& e) {
        return config::ConfigError(std::string("cannot listen on the JW-51CM ") + transport + " port " + config.bind + ":" +
                                   std::to_string(port) + ": " + e.code().message() + "; choose another port (\"jw51cm\": {\"" +
                                   (transport[0] == 'T' ? "tcp" : "udp") + "_port\": ...}) or stop the program using it");
    };
    if (jw.tcp) {
        auto port = *jw.tcp;
        SessionFactory factory = [&station, link, port](boost::asio::ip::tcp::socket socket,
                                                        std::function<void(StreamSession*)> on_closed,
                                                        std::function<std::size_t()>) -> std::shared_ptr<StreamSession> {
            FrontEndHandler handler = [link](std::span<const std::uint8_t> pending) {
                auto result = link->handle_stream(pending);
                return FrontEndStep{result.kind == jw51cm::ComputerLink::Result::Kind::NeedMore, result.consumed,
                                    as_text(result.response)};
            };
            return std::make_shared<FrontEndSession>(std::move(socket), station, "JW-51CM", std::move(handler), port,
                                                     std::move(on_closed));
        };
        try {
            jw51cm_tcp_ = std::make_unique<TcpListener>(io, station, port, bind, std::move(factory));
        } catch (const boost::system::system_error& e) {
            throw fail("TCP", port.port, e);
        }
    }
    if (jw.udp) {
        try {
            jw51cm_udp_ = std::make_unique<FrontEndUdpListener>(io, "JW-51CM", jw.udp->port, bind,
                                                                [link](std::span<const std::uint8_t> datagram) {
                                                                    return as_text(link->handle_datagram(datagram).response);
                                                                });
        } catch (const boost::system::system_error& e) {
            throw fail("UDP", jw.udp->port, e);
        }
    }
}

std::vector<std::uint16_t> Listeners::jw51cm_tcp_ports() const {
    if (!jw51cm_tcp_) return {};
    return {jw51cm_tcp_->port()};
}

std::vector<std::uint16_t> Listeners::jw51cm_udp_ports() const {
    if (!jw51cm_udp_) return {};
    return {jw51cm_udp_->port()};
}

std::vector<std::uint16_t> Listeners::hostlink_ports() const {
    if (!hostlink_tcp_) return {};
    return {hostlink_tcp_->port()};
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
    if (hostlink_tcp_) hostlink_tcp_->stop();
    if (serial_) serial_->stop();
    if (jw51cm_tcp_) jw51cm_tcp_->stop();
    if (jw51cm_udp_) jw51cm_udp_->stop();
}

void Listeners::refuse_connections(bool refusing) {
    for (auto& l : tcp_) l->set_refusing(refusing);
    if (hostlink_tcp_) hostlink_tcp_->set_refusing(refusing);
    if (jw51cm_tcp_) jw51cm_tcp_->set_refusing(refusing);
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
