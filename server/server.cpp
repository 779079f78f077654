#include "server/server.hpp"

#include <sys/resource.h>
#include <unistd.h>

#include <algorithm>
#include <atomic>
#include <exception>
#include <filesystem>
#include <fstream>
#include <thread>

#include <nlohmann/json.hpp>
#include <spdlog/spdlog.h>

namespace slmp::server {

namespace asio = boost::asio;

namespace {

constexpr std::size_t kStationsLogged = 16;   // start-up lines; the rest are in GET /api/stations

asio::ip::address bind_address(const std::string& text) {
    boost::system::error_code ec;
    auto address = asio::ip::make_address(text, ec);
    if (ec) throw config::ConfigError("bind address '" + text + "' is not an IP address; use e.g. 0.0.0.0 or 127.0.0.1");
    return address;
}

// A thread per core, or --threads.
std::size_t thread_count(const config::PlantConfig& plant) {
    return plant.threads ? plant.threads : std::max(1u, std::thread::hardware_concurrency());
}

// An event loop per thread while there are at least as many stations as
// threads: a loop run by one thread serves a request without waking another
// thread (Asio's shared loop costs two epoll_waits and futex wakes a request,
// docs/plants.md "Threads"). Fewer stations than threads: as many loops as
// stations, the threads spread over them, so a lone busy station still has
// every thread for its connections' reads and writes.
std::vector<std::size_t> threads_per_loop(std::size_t threads, std::size_t stations) {
    const auto loops = std::max<std::size_t>(1, std::min(threads, stations));
    std::vector<std::size_t> per_loop(loops, threads / loops);
    for (std::size_t k = 0; k < threads % loops; ++k) ++per_loop[k];
    return per_loop;
}


// A plant holds two sockets a station and more per client; the soft limit
// (often 1024) would refuse them long before the hard one.
void raise_open_file_limit() {
    rlimit limit{};
    if (getrlimit(RLIMIT_NOFILE, &limit) != 0 || limit.rlim_cur >= limit.rlim_max) return;
    limit.rlim_cur = limit.rlim_max;
    setrlimit(RLIMIT_NOFILE, &limit);
}

}  // namespace

std::vector<std::unique_ptr<Server::Loop>> Server::make_loops(std::size_t threads, std::size_t stations) {
    std::vector<std::unique_ptr<Loop>> loops;
    for (auto n : threads_per_loop(threads, stations)) loops.push_back(std::make_unique<Loop>(n));
    return loops;
}

Server::Loop::Loop(std::size_t threads)
    : threads(threads), io(static_cast<int>(threads)), keep_running(boost::asio::make_work_guard(io)) {}

Server::Served::Served(const station::Home& home, const config::StationConfig& station_config, bool shared_loop)
    : home(home),
      settings(station_config),
      station(home, settings.server),
      listeners(home, station, settings.server, settings.frontends, bind_address(settings.server.bind), shared_loop) {
    station.connect(listeners);
}

Server::Server(const config::PlantConfig& plant)
    : plant_(plant),
      threads_(thread_count(plant_)),
      loops_(make_loops(threads_, plant_.stations.size())),
      main_(asio::make_strand(loops_.back()->io)),
      signals_(main_, SIGINT, SIGTERM),
      snapshot_signal_(main_, SIGUSR1) {
    raise_open_file_limit();
    std::vector<control::ServedStation> served;
    for (std::size_t k = 0; k < plant_.stations.size(); ++k) {
        const auto& station_config = plant_.stations[k];
        try {
            auto& loop = loop_of(k);
            stations_.push_back(std::make_unique<Served>(asio::make_strand(loop.io), station_config, loop.threads > 1));
        } catch (const config::ConfigError& e) {
            if (!plant_.plant) throw;
            throw config::ConfigError("station '" + station_config.server.name + "': " + e.what());
        }
        auto& s = *stations_.back();
        served.push_back({s.settings.server.name, s.station, s.home,
                          control::PortList{s.settings.server.bind, s.listeners.tcp_ports(), s.listeners.udp_ports(), 0}});
    }
    join_networks();
    take_initial_snapshots();
    if (first().http.enabled)
        http_ = std::make_unique<control::HttpServer>(main_, served, first().http,
                                                      bind_address(http_bind()), plant_);
}

// The stations' network modules make one network map (docs/plants.md, "Networks
// and routes"); every station reads it, no one changes it after this.
void Server::join_networks() {
    for (auto& s : stations_) {
        const auto& server = s->settings.server;
        networks_.add(s->station, server.name, server.networks, server.routes);
        if (server.redundant) networks_.add_redundant(s->station, server.name, *server.redundant);
        if (server.multidrop) networks_.add_multidrop(s->station, server.name, *server.multidrop);
    }
    networks_.link();
    for (auto& s : stations_) s->station.join(networks_);
}

// "http": {"bind"}, else the stations' bind address when they share one, else
// every address (a plant on 127.0.1.x answers HTTP on all of them).
std::string Server::http_bind() const {
    if (!first().http.bind.empty()) return first().http.bind;
    for (const auto& station : plant_.stations)
        if (station.server.bind != first().bind) return "0.0.0.0";
    return first().bind;
}

Server::~Server() = default;

// Every station's initial snapshot, on all threads: reading the memory of a
// 1000-station plant was most of its start-up. Nothing runs on the io_context
// yet, and each snapshot touches its own station only.
void Server::take_initial_snapshots() {
    std::vector<std::exception_ptr> errors(stations_.size());
    std::atomic<std::size_t> next{0};
    auto take = [&] {
        for (std::size_t k; (k = next++) < stations_.size();) {
            try {
                stations_[k]->station.take_initial_snapshot();
            } catch (...) {
                errors[k] = std::current_exception();
            }
        }
    };
    std::vector<std::thread> helpers;
    for (std::size_t t = 1; t < std::min(threads_, stations_.size()); ++t) helpers.emplace_back(take);
    take();
    for (auto& helper : helpers) helper.join();
    for (std::size_t k = 0; k < errors.size(); ++k) {
        if (!errors[k]) continue;
        try {
            std::rethrow_exception(errors[k]);
        } catch (const config::ConfigError& e) {
            if (!plant_.plant) throw;
            throw config::ConfigError("station '" + plant_.stations[k].server.name + "': " + e.what());
        }
    }
}

void Server::log_stations() const {
    for (std::size_t k = 0; k < stations_.size() && k < kStationsLogged; ++k) {
        const auto& s = *stations_[k];
        const auto& profile = s.station.cpu().profile();
        auto who = plant_.plant ? "station " + s.settings.server.name + ": " : std::string("slmp-sim 0.1.0: ");
        spdlog::info("{}{} ({}, model code {:04X}) on {} — TCP {} / UDP {}", who, profile.name, profile.type_name,
                     profile.model_code, s.settings.server.bind, port_list(s.listeners.tcp_ports()),
                     port_list(s.listeners.udp_ports()));
        const auto& frontends = s.settings.frontends;
        for (const auto& face : frontends.faces) {
            auto name = face.face->name();
            auto ports = "TCP " + port_list(s.listeners.face_tcp_ports(name));
            if (face.face->has_udp()) ports += " / UDP " + port_list(s.listeners.face_udp_ports(name));
            spdlog::info("{} station: {} on {}", config::kind_name(frontends.kind), face.face->title(), ports);
        }
    }
    if (stations_.size() > kStationsLogged)
        spdlog::info("... and {} more stations (GET /api/stations lists them all)", stations_.size() - kStationsLogged);
    if (plant_.plant)
        spdlog::info("slmp-sim 0.1.0: a plant of {} stations on {} thread(s)", stations_.size(), threads_);
    if (http_)
        spdlog::info("web monitor and HTTP API on http://{}:{}/", http_bind(), http_->port());
}

void Server::run() {
    log_stations();
    bool any_state_directory = false;
    for (auto& s : stations_) {
        s->station.start();
        any_state_directory = any_state_directory || s->station.has_state_directory();
    }
    if (any_state_directory) wait_for_snapshot_signal();
    signals_.async_wait([this](const boost::system::error_code& ec, int signal) {
        if (ec) return;
        spdlog::info("signal {} received; shutting down", signal);
        stop();
    });
    if (http_) http_->set_ready();
    write_ready_file();
    std::vector<std::thread> workers;
    for (auto& loop : loops_)
        for (std::size_t k = 0; k < loop->threads; ++k)
            if (loop != loops_.front() || k > 0) workers.emplace_back([&io = loop->io] { io.run(); });
    loops_.front()->io.run();
    for (auto& worker : workers) worker.join();
    spdlog::info("stopped");
}

void Server::stop() {
    // Each station stops on its own strand; the loops then run out of work.
    for (auto& s : stations_)
        asio::post(s->home, [served = s.get()] {
            served->station.stop();
            served->listeners.stop();
        });
    snapshot_signal_.cancel();
    if (http_) http_->stop();
    signals_.cancel();
    for (auto& loop : loops_) loop->keep_running.reset();
}

// Tests and scripts wait for this file instead of sleeping; it is written
// whole (temporary file, then rename) so a reader never sees half of it.
void Server::write_ready_file() const {
    if (first().ready_file.empty()) return;
    std::filesystem::path path(first().ready_file);
    auto temp = path;
    temp += ".tmp";
    // A port kind with no ports is an empty list (port_list's "-" is for the log line).
    auto ports_of = [](const Served& s) {
        nlohmann::json ready{{"tcp", s.listeners.tcp_ports()}, {"udp", s.listeners.udp_ports()}};
        // A face: its TCP ports, or {"tcp": [...], "udp": [...]} when it has UDP ones too.
        for (const auto& face : s.settings.frontends.faces) {
            std::string name(face.face->name());
            if (face.face->has_udp())
                ready[name] = {{"tcp", s.listeners.face_tcp_ports(name)}, {"udp", s.listeners.face_udp_ports(name)}};
            else
                ready[name] = s.listeners.face_tcp_ports(name);
        }
        if (!s.listeners.serial_device().empty()) ready["serial"] = s.listeners.serial_device();
        return ready;
    };
    auto ready = ports_of(*stations_.front());   // a plant's first station here too, as before plants
    if (plant_.plant) {
        auto list = nlohmann::json::array();
        for (const auto& s : stations_) {
            auto entry = ports_of(*s);
            entry["name"] = s->settings.server.name;
            entry["bind"] = s->settings.server.bind;
            list.push_back(std::move(entry));
        }
        ready["stations"] = std::move(list);
    }
    if (http_) ready["http"] = http_->port();
    ready["threads"] = threads_;
    ready["pid"] = getpid();
    {
        std::ofstream(temp) << ready.dump() << "\n";
    }
    std::filesystem::rename(temp, path);
}

// SIGUSR1 saves a snapshot of every station with a state directory now (for
// scripts that want one before copying the state directory).
void Server::wait_for_snapshot_signal() {
    snapshot_signal_.async_wait([this](const boost::system::error_code& ec, int) {
        if (ec) return;
        for (auto& s : stations_)
            asio::post(s->home, [served = s.get()] {
                if (served->station.has_state_directory() && served->station.save_snapshot("SIGUSR1"))
                    spdlog::info("state directory{}: snapshot saved on SIGUSR1",
                                 served->settings.server.name.empty() ? "" : " of " + served->settings.server.name);
            });
        wait_for_snapshot_signal();
    });
}

}  // namespace slmp::server
