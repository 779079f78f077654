#include "server/server.hpp"

#include <unistd.h>

#include <filesystem>
#include <fstream>

#include <nlohmann/json.hpp>
#include <spdlog/spdlog.h>

namespace slmp::server {

namespace asio = boost::asio;

namespace {

asio::ip::address bind_address(const std::string& text) {
    boost::system::error_code ec;
    auto address = asio::ip::make_address(text, ec);
    if (ec) throw config::ConfigError("bind address '" + text + "' is not an IP address; use e.g. 0.0.0.0 or 127.0.0.1");
    return address;
}

}  // namespace

Server::Server(const config::ServerConfig& config, const config::FrontEndsConfig& frontends)
    : config_(config),
      frontends_(frontends),
      station_(io_, config),
      listeners_(io_, station_, config_, frontends_, bind_address(config_.bind)) {
    station_.connect(listeners_);
    if (config_.http.enabled) {
        control::PortList ports{config_.bind, listeners_.tcp_ports(), listeners_.udp_ports(), 0};
        auto http_bind = config_.http.bind.empty() ? bind_address(config_.bind) : bind_address(config_.http.bind);
        http_ = std::make_unique<control::HttpServer>(io_, station_, config_.http, http_bind, std::move(ports));
    }
}

void Server::run() {
    const auto& profile = station_.cpu().profile();
    spdlog::info("slmp-sim 0.1.0: {} ({}, model code {:04X}) on {} — TCP {} / UDP {}", profile.name, profile.type_name,
                 profile.model_code, config_.bind, port_list(listeners_.tcp_ports()), port_list(listeners_.udp_ports()));
    if (frontends_.hostlink.enabled)
        spdlog::info("{} station: Ladder Motion host link on TCP {}", config::kind_name(frontends_.kind),
                     port_list(listeners_.hostlink_ports()));
    if (frontends_.jw51cm.enabled)
        spdlog::info("{} station: JW-51CM computer link on TCP {} / UDP {}", config::kind_name(frontends_.kind),
                     port_list(listeners_.jw51cm_tcp_ports()), port_list(listeners_.jw51cm_udp_ports()));
    if (http_)
        spdlog::info("web monitor and HTTP API on http://{}:{}/", config_.http.bind.empty() ? config_.bind : config_.http.bind,
                     http_->port());
    station_.start();
    if (station_.has_state_directory()) wait_for_snapshot_signal();
    signals_.async_wait([this](const boost::system::error_code& ec, int signal) {
        if (ec) return;
        spdlog::info("signal {} received; shutting down", signal);
        stop();
    });
    write_ready_file();
    io_.run();
    spdlog::info("stopped");
}

void Server::stop() {
    station_.stop();
    snapshot_signal_.cancel();
    listeners_.stop();
    if (http_) http_->stop();
    signals_.cancel();
}

// Tests and scripts wait for this file instead of sleeping; it is written
// whole (temporary file, then rename) so a reader never sees half of it.
void Server::write_ready_file() const {
    if (config_.ready_file.empty()) return;
    std::filesystem::path path(config_.ready_file);
    auto temp = path;
    temp += ".tmp";
    {
        // A port kind with no ports is an empty list (port_list's "-" is for the log line).
        nlohmann::json ready{{"tcp", listeners_.tcp_ports()}, {"udp", listeners_.udp_ports()}};
        if (frontends_.hostlink.enabled) ready["hostlink"] = listeners_.hostlink_ports();
        if (!listeners_.serial_device().empty()) ready["serial"] = listeners_.serial_device();
        if (frontends_.jw51cm.enabled)
            ready["jw51cm"] = {{"tcp", listeners_.jw51cm_tcp_ports()}, {"udp", listeners_.jw51cm_udp_ports()}};
        if (http_) ready["http"] = http_->port();
        ready["pid"] = getpid();
        std::ofstream(temp) << ready.dump() << "\n";
    }
    std::filesystem::rename(temp, path);
}

// SIGUSR1 saves a snapshot now (for scripts that want one before copying the
// state directory).
void Server::wait_for_snapshot_signal() {
    snapshot_signal_.async_wait([this](const boost::system::error_code& ec, int) {
        if (ec) return;
        if (station_.save_snapshot("SIGUSR1")) spdlog::info("state directory: snapshot saved on SIGUSR1");
        wait_for_snapshot_signal();
    });
}

}  // namespace slmp::server
