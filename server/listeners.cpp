#include "server/listeners.hpp"

#include "devicemodel/hex.hpp"
#include "frontends/hostlink/command_table.hpp"
#include "frontends/jw51cm/command_table.hpp"
#include "server/frontend_session.hpp"
#include "station/frontend_call.hpp"

namespace slmp::server {

Listeners::Listeners(const station::Home& home, station::Station& station, const config::ServerConfig& config,
                     const config::FrontEndsConfig& frontends, const boost::asio::ip::address& bind) {
    for (const auto& port : config.ports) {
        try {
            if (port.transport == config::Transport::Tcp)
                tcp_.push_back(std::make_unique<TcpListener>(home, station, port, bind));
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
    if (frontends.hostlink.enabled) listen_hostlink(home, station, config, frontends.hostlink, bind);
    if (frontends.jw51cm.enabled) listen_jw51cm(home, station, config, frontends.jw51cm, bind);
    if (hostlink_ || jw51cm_) {
        station_ = &station;
        station.attach_frontends({hostlink_.get(), jw51cm_.get()});
    }
}

namespace {

std::string as_text(std::span<const std::uint8_t> bytes) { return std::string(bytes.begin(), bytes.end()); }

std::span<const std::uint8_t> as_bytes(const std::string& text) {
    return {reinterpret_cast<const std::uint8_t*>(text.data()), text.size()};
}

FrontEndStep step(std::size_t consumed, std::string response, const station::FrontEndCall::Delivery& delivery) {
    FrontEndStep s{false, consumed, std::move(response)};
    s.delay = delivery.delay;
    s.close = delivery.close;
    s.reset = delivery.reset;
    return s;
}

// One host-link record cut from `pending`, answered and reported (station/frontend_call.hpp).
FrontEndStep hostlink_step(station::Station& station, hostlink::HostLink& link, hostlink::LinkState& state,
                           std::span<const std::uint8_t> pending, std::uint64_t connection, const protocol::Peer& peer) {
    station::FrontEndCall call(station, scenarios::Protocol::HostLink, connection, peer);
    auto result = link.handle(pending, state, call.gate());
    if (result.kind == hostlink::Cut::Kind::NeedMore) return FrontEndStep{true};
    const auto* row = result.command.empty() ? nullptr : hostlink::find_command(result.command);
    auto delivery = call.finish(pending.first(result.consumed), result.command, row != nullptr,
                                row ? row->function : std::string_view(), result.code, as_bytes(result.response));
    return step(result.consumed, std::move(result.response), delivery);
}

// A JW-51CM result reported: the COM (when the request reached it) and the RSLT answered.
station::FrontEndCall::Delivery jw51cm_report(station::FrontEndCall& call, std::span<const std::uint8_t> request,
                                              const jw51cm::ComputerLink::Result& result) {
    constexpr std::size_t kCom = jw51cm::kHeaderBytes + 2;
    const bool has_com = request.size() > kCom;
    const auto* row = has_com ? jw51cm::find_command(result.command) : nullptr;
    auto code = result.response.size() > kCom + 1 ? devicemodel::hex2(result.response[kCom + 1]) : std::string();
    return call.finish(request, has_com ? devicemodel::hex2(result.command) : std::string(), row != nullptr,
                       row ? row->name : std::string_view(), code, result.response);
}

}  // namespace

void Listeners::listen_hostlink(const station::Home& home, station::Station& station,
                                const config::ServerConfig& config, const config::HostLinkConfig& hostlink,
                                const boost::asio::ip::address& bind) {
    if (auto problem = hostlink.options->map.check(station.cpu().memory()); !problem.empty())
        throw config::ConfigError(problem);
    hostlink_ = std::make_unique<hostlink::HostLink>(station.cpu(), *hostlink.options);
    auto* link = hostlink_.get();

    auto port = hostlink.port;
    SessionFactory factory = [&station, link, port](station::StrandSocket socket,
                                                    std::function<void(StreamSession*)> on_closed,
                                                    std::function<std::size_t()>) -> std::shared_ptr<StreamSession> {
        // The connection's own state (its QQMR list) lives in its handler.
        auto state = std::make_shared<hostlink::LinkState>();
        FrontEndHandler handler = [&station, link, state](std::span<const std::uint8_t> pending, std::uint64_t connection,
                                                          const protocol::Peer& peer) {
            return hostlink_step(station, *link, *state, pending, connection, peer);
        };
        return std::make_shared<FrontEndSession>(std::move(socket), station, "host link", std::move(handler), port,
                                                 std::move(on_closed));
    };
    try {
        hostlink_tcp_ = std::make_unique<TcpListener>(home, station, port, bind, std::move(factory));
    } catch (const boost::system::system_error& e) {
        throw config::ConfigError("cannot listen on the host-link TCP port " + config.bind + ":" +
                                  std::to_string(port.port) + ": " + e.code().message() +
                                  "; choose another port (\"hostlink\": {\"tcp_port\": ...} or --hostlink-port) "
                                  "or stop the program using it");
    }
    if (!hostlink.serial_path.empty()) serial_ = std::make_unique<SerialPort>(home, *hostlink_, hostlink.serial_path);
}

void Listeners::listen_jw51cm(const station::Home& home, station::Station& station, const config::ServerConfig& config,
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
        SessionFactory factory = [&station, link, port](station::StrandSocket socket,
                                                        std::function<void(StreamSession*)> on_closed,
                                                        std::function<std::size_t()>) -> std::shared_ptr<StreamSession> {
            FrontEndHandler handler = [&station, link](std::span<const std::uint8_t> pending, std::uint64_t connection,
                                                       const protocol::Peer& peer) {
                station::FrontEndCall call(station, scenarios::Protocol::Jw51cm, connection, peer);
                auto result = link->handle_stream(pending, call.gate());
                if (result.kind == jw51cm::ComputerLink::Result::Kind::NeedMore) return FrontEndStep{true};
                auto delivery = jw51cm_report(call, pending.first(result.consumed), result);
                return step(result.consumed, as_text(result.response), delivery);
            };
            return std::make_shared<FrontEndSession>(std::move(socket), station, "JW-51CM", std::move(handler), port,
                                                     std::move(on_closed));
        };
        try {
            jw51cm_tcp_ = std::make_unique<TcpListener>(home, station, port, bind, std::move(factory));
        } catch (const boost::system::system_error& e) {
            throw fail("TCP", port.port, e);
        }
    }
    if (jw.udp) {
        // One session for the port, as an SLMP UDP port has: requests report it as their connection.
        auto session = station.next_session_id();
        DatagramHandler handler = [&station, link, session](std::span<const std::uint8_t> datagram, const protocol::Peer& peer) {
            station::FrontEndCall call(station, scenarios::Protocol::Jw51cm, session, peer);
            auto result = link->handle_datagram(datagram, call.gate());
            auto delivery = jw51cm_report(call, datagram, result);
            return DatagramAnswer{as_text(result.response), delivery.delay};
        };
        try {
            jw51cm_udp_ = std::make_unique<FrontEndUdpListener>(home, "JW-51CM", jw.udp->port, bind, std::move(handler));
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

Listeners::~Listeners() {
    // The front ends go with the listeners: the station must not reach them after.
    if (station_) station_->frontends() = {};
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
