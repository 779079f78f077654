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
    auto scenarios = load_scenarios();   // their initial state joins config_ first
    config::apply_initial_values(core_.cpu, config_);
    config::attach_hardware(core_.cpu, config_);
    for (const auto& cpu : config_.cpus) {
        auto profile = config::resolve_profile(cpu);
        core_.other_cpus.push_back(std::make_unique<devicemodel::Cpu>(std::move(profile.cpu)));
        config::apply_initial_values(*core_.other_cpus.back(), cpu.devices);
        core_.engine.add_cpu(cpu.number, *core_.other_cpus.back(), std::move(profile.port));
    }
    start_cpu_runtime();
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
    start_scenarios(std::move(scenarios));
    if (config_.http.enabled) {
        http::PortList ports{config_.bind, {}, {}, 0};
        for (const auto& l : tcp_) ports.tcp.push_back(l->port());
        for (const auto& l : udp_) ports.udp.push_back(l->port());
        auto http_bind = config_.http.bind.empty() ? address : bind_address(config_.http.bind);
        http_ = std::make_unique<http::HttpServer>(io_, core_, config_.http, http_bind, std::move(ports));
    }
}

void Server::run() {
    const auto& profile = core_.cpu.profile();
    spdlog::info("slmp-sim 0.1.0: {} ({}, model code {:04X}) on {} — TCP {} / UDP {}", profile.name, profile.type_name,
                 profile.model_code, config_.bind, port_list(tcp_), port_list(udp_));
    if (http_)
        spdlog::info("web monitor and HTTP API on http://{}:{}/", config_.http.bind.empty() ? config_.bind : config_.http.bind,
                     http_->port());
    scan_->start();
    if (persistence_) {
        persistence_->start();
        wait_for_snapshot_signal();
    }
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
    scan_->stop();
    core_.scenario.log_summary();
    if (persistence_) {
        persistence_->stop();
        persistence_->save("shutdown");
        snapshot_signal_.cancel();
    }
    for (auto& l : tcp_) l->stop();
    for (auto& l : udp_) l->stop();
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
        std::ofstream out(temp);
        out << "{\"tcp\":[" << port_list(tcp_) << "],\"udp\":[" << port_list(udp_) << "]";
        if (http_) out << ",\"http\":" << http_->port();
        out << ",\"pid\":" << getpid() << "}\n";
    }
    std::filesystem::rename(temp, path);
}

void Server::start_cpu_runtime() {
    auto& cpu = core_.cpu;
    cpu.runtime().configure(config::checked_runtime_config(config_.cpu, cpu.profile()), cpu.memory());
    // Device clears (Remote RUN clear modes, latch clear, reset) re-apply the
    // configured initial values, as the CPU's "device initial value" parameter does.
    cpu.runtime().set_initial_values([this](devicemodel::DeviceMemory&) { config::apply_initial_values(core_.cpu, config_.devices); });
    std::vector<devicemodel::Cpu*> cpus{&cpu};
    for (auto& other : core_.other_cpus) cpus.push_back(other.get());
    scan_ = std::make_unique<ScanLoop>(io_, std::move(cpus), cpu.runtime().config().scan_time, config_.clock_speed);
    if (!config_.persistence.state_dir.empty()) {
        persistence_ = std::make_unique<Persistence>(io_, cpu, config_.persistence);
        persistence_->restore();
    }
    core_.on_restart = [this] { restart_station(); };
}

// Remote RESET (slmp-labels-remote-misc.md §5.6): the CPU has restarted; as on
// the real station every TCP connection drops and UDP sessions start afresh.
void Server::restart_station() {
    spdlog::info("Remote RESET: CPU restarted; closing every connection");
    std::vector<std::uint64_t> ids;
    for (const auto& [id, _] : core_.activity.connections()) ids.push_back(id);
    for (auto id : ids) core_.activity.close(id, "Remote RESET: the CPU restarted");
    for (auto& l : udp_) l->restart_session();
}

// SIGUSR1 saves a snapshot now (for scripts that want one before copying the
// state directory).
void Server::wait_for_snapshot_signal() {
    snapshot_signal_.async_wait([this](const boost::system::error_code& ec, int) {
        if (ec) return;
        if (persistence_->save("SIGUSR1")) spdlog::info("state directory: snapshot saved on SIGUSR1");
        wait_for_snapshot_signal();
    });
}

}  // namespace slmp::server
