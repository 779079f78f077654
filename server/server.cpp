#include "server/server.hpp"

#include <unistd.h>

#include <filesystem>
#include <fstream>

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

std::string port_list(const auto& listeners) {
    std::string text;
    for (const auto& l : listeners) text += (text.empty() ? "" : ",") + std::to_string(l->port());
    return text.empty() ? "-" : text;
}

}  // namespace

Server::Server(const config::ServerConfig& config)
    : config_(config), core_(config::resolve_profile(config), protocol::EngineOptions{config.max_request_bytes}) {
    config::apply_initial_values(core_.cpu, config_);
    auto address = bind_address(config_.bind);
    for (const auto& port : config_.ports) {
        try {
            if (port.transport == config::Transport::Tcp)
                tcp_.push_back(std::make_unique<TcpListener>(io_, core_, port, address));
            else
                udp_.push_back(std::make_unique<UdpListener>(io_, core_, port, address));
        } catch (const boost::system::system_error& e) {
            auto transport = port.transport == config::Transport::Tcp ? "TCP" : "UDP";
            throw config::ConfigError(std::string("cannot listen on ") + transport + " " + config_.bind + ":" +
                                      std::to_string(port.port) + ": " + e.code().message() +
                                      "; choose another port (--" + (port.transport == config::Transport::Tcp ? "tcp" : "udp") +
                                      "-port) or stop the program using it");
        }
    }
}

void Server::run() {
    const auto& profile = core_.cpu.profile();
    spdlog::info("slmp-sim 0.1.0: {} ({}, model code {:04X}) on {} — TCP {} / UDP {}", profile.name, profile.type_name,
                 profile.model_code, config_.bind, port_list(tcp_), port_list(udp_));
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
    for (auto& l : tcp_) l->stop();
    for (auto& l : udp_) l->stop();
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
        std::ofstream out(temp);
        out << "{\"tcp\":[" << port_list(tcp_) << "],\"udp\":[" << port_list(udp_) << "],\"pid\":" << getpid() << "}\n";
    }
    std::filesystem::rename(temp, path);
}

}  // namespace slmp::server
