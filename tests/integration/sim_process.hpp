// A real slmp-sim process for black-box tests.
//
// SimProcess fork/execs the binary built by this tree (SLMP_SIM_BINARY) with a
// private temporary directory, ephemeral ports and a --ready-file, then waits
// (polling, at most 10 s) until the server has written the ready file with its
// bound ports. On teardown it sends SIGTERM and checks the server exits with
// status 0 within 10 s. The server's stdout/stderr go to files in the temporary
// directory; they are printed when something goes wrong.
//
// run_sim() runs the binary to completion (for --help, bad options, ...) and
// returns its exit status and output.
//
// The proxy run (SLMP_TEST_THROUGH_PROXY=1; docs/testing.md, "Through a
// proxy"): every SimProcess of one station is fronted by a second slmp-sim in
// proxy mode (`--upstream` to the first's TCP port, docs/twin.md), and the
// test's SLMP ports are the proxy's. At the stop both processes' recordings
// must hold the same exchanges, byte for byte: the traffic passed through
// unchanged and the proxy's recording holds every exchange.
#pragma once

#include <fcntl.h>
#include <signal.h>
#include <sys/stat.h>
#include <sys/types.h>
#include <sys/wait.h>
#include <unistd.h>

#include <catch2/catch.hpp>
#include <nlohmann/json.hpp>

#include <algorithm>
#include <chrono>
#include <cstdint>
#include <cstdlib>
#include <filesystem>
#include <cstdio>
#include <fstream>
#include <iterator>
#include <memory>
#include <optional>
#include <sstream>
#include <stdexcept>
#include <string>
#include <thread>
#include <vector>

#include "support/files.hpp"

#ifndef SLMP_SIM_BINARY
#error "SLMP_SIM_BINARY must name the slmp-sim executable under test"
#endif

namespace slmp::test {

// Upper bounds, never waits: a sanitizer's slower binary (scripts/test-tsan.sh
// sets SLMP_TEST_TIME_SCALE=8: a 200-station plant starts in 20–45 s under
// ThreadSanitizer) gets a multiple of them.
inline std::chrono::seconds scaled_bound(long seconds) {
    const char* scale = std::getenv("SLMP_TEST_TIME_SCALE");
    return std::chrono::seconds(seconds * std::max(1L, scale ? std::atol(scale) : 1L));
}
inline const std::chrono::seconds kStartTimeout = scaled_bound(10);
inline const std::chrono::seconds kStopTimeout = scaled_bound(10);

// A directory under $TMPDIR (or /tmp) removed with its contents on destruction.
class TempDir {
public:
    TempDir() {
        const char* base = std::getenv("TMPDIR");
        std::string pattern = std::string(base && *base ? base : "/tmp") + "/slmp-integ-XXXXXX";
        std::vector<char> buffer(pattern.begin(), pattern.end());
        buffer.push_back('\0');
        if (!::mkdtemp(buffer.data())) throw std::runtime_error("mkdtemp failed");
        path_ = buffer.data();
    }
    ~TempDir() {
        std::error_code ec;
        std::filesystem::remove_all(path_, ec);
    }
    TempDir(const TempDir&) = delete;
    TempDir& operator=(const TempDir&) = delete;

    const std::filesystem::path& path() const { return path_; }

    // Writes `text` to a file in this directory and returns its path.
    std::filesystem::path write(const std::string& name, const std::string& text) const {
        auto file = path_ / name;
        std::ofstream(file, std::ios::binary) << text;
        return file;
    }

private:
    std::filesystem::path path_;
};

// A program of this tree's build (`built`, under SLMP_BUILD_DIR), or the same
// program of the build tree $SLMP_BUILD_UNDER_TEST: scripts/test-sanitizers.sh
// runs these tests against its ASan + UBSan slmp-sim, slmp and slmp-replay.
inline std::string under_test(const std::string& built) {
    const char* other = std::getenv("SLMP_BUILD_UNDER_TEST");
    const std::string own = SLMP_BUILD_DIR;
    if (!other || !*other || built.compare(0, own.size(), own) != 0) return built;
    return other + built.substr(own.size());
}

// The slmp-sim under test: as under_test() says, or $SLMP_SIM_UNDER_TEST (the
// ThreadSanitizer build of scripts/test-tsan.sh runs these tests against its own).
inline std::string sim_binary() {
    const char* other = std::getenv("SLMP_SIM_UNDER_TEST");
    return other && *other ? other : under_test(SLMP_SIM_BINARY);
}

namespace detail {

// fork + execv with stdout/stderr redirected to files. Returns the child's pid.
// `binary` defaults to slmp-sim; the CLI tests run the slmp client the same way.
inline pid_t spawn(const std::vector<std::string>& args, const std::filesystem::path& out_file,
                   const std::filesystem::path& err_file, const std::string& binary = sim_binary()) {
    std::vector<std::string> argv_storage;
    argv_storage.push_back(binary);
    argv_storage.insert(argv_storage.end(), args.begin(), args.end());
    std::vector<char*> argv;
    for (auto& a : argv_storage) argv.push_back(a.data());
    argv.push_back(nullptr);

    pid_t pid = ::fork();
    if (pid < 0) throw std::runtime_error("fork failed");
    if (pid == 0) {
        int in = ::open("/dev/null", O_RDONLY);
        int out = ::open(out_file.c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0644);
        int err = ::open(err_file.c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0644);
        if (in < 0 || out < 0 || err < 0) ::_exit(126);
        ::dup2(in, 0);
        ::dup2(out, 1);
        ::dup2(err, 2);
        ::execv(argv[0], argv.data());
        ::_exit(127);
    }
    return pid;
}

// Waits up to `timeout` for `pid`; returns the raw wait status, or nullopt on timeout.
inline std::optional<int> wait_for(pid_t pid, std::chrono::milliseconds timeout) {
    auto deadline = std::chrono::steady_clock::now() + timeout;
    for (;;) {
        int status = 0;
        pid_t r = ::waitpid(pid, &status, WNOHANG);
        if (r == pid) return status;
        if (r < 0) return std::nullopt;
        if (std::chrono::steady_clock::now() >= deadline) return std::nullopt;
        std::this_thread::sleep_for(std::chrono::milliseconds(5));
    }
}

inline std::string describe_status(int status) {
    if (WIFEXITED(status)) return "exit code " + std::to_string(WEXITSTATUS(status));
    if (WIFSIGNALED(status)) return "killed by signal " + std::to_string(WTERMSIG(status));
    return "status " + std::to_string(status);
}

}  // namespace detail

struct RunResult {
    int exit_code = -1;     // -1 when killed by a signal or timed out
    std::string out;
    std::string err;
};

// Runs `binary` with `args` to completion (bounded by `timeout`; killed after it).
inline RunResult run_binary(const std::string& binary, const std::vector<std::string>& args,
                            std::chrono::milliseconds timeout = std::chrono::seconds(10)) {
    TempDir dir;
    auto out_file = dir.path() / "stdout";
    auto err_file = dir.path() / "stderr";
    pid_t pid = detail::spawn(args, out_file, err_file, binary);
    auto status = detail::wait_for(pid, timeout);
    RunResult result;
    if (!status) {
        ::kill(pid, SIGKILL);
        ::waitpid(pid, nullptr, 0);
    } else if (WIFEXITED(*status)) {
        result.exit_code = WEXITSTATUS(*status);
    }
    result.out = read_text(out_file);
    result.err = read_text(err_file);
    return result;
}

// Runs slmp-sim with `args` to completion (bounded by `timeout`; killed after it).
inline RunResult run_sim(const std::vector<std::string>& args,
                         std::chrono::milliseconds timeout = std::chrono::seconds(10)) {
    return run_binary(sim_binary(), args, timeout);
}

// Non-empty lines of `text`.
inline std::vector<std::string> lines_of(const std::string& text) {
    std::vector<std::string> lines;
    std::istringstream in(text);
    for (std::string line; std::getline(in, line);)
        if (line.find_first_not_of(" \t\r") != std::string::npos) lines.push_back(line);
    return lines;
}

struct SimOptions {
    unsigned tcp_ports = 1;                 // how many --tcp-port 0
    unsigned udp_ports = 1;                 // how many --udp-port 0
    std::vector<std::string> args;          // anything else (--idle-timeout 0.3, ...)
    std::string config_json;                // when set, written to a file and passed as --config
    bool default_log_level = false;         // false: --log-level warn (quiet test logs)
    bool plant = false;                     // config_json is a plant: its stations name their ports and binds
};

inline SimOptions with_args(std::vector<std::string> args) {
    SimOptions options;
    options.args = std::move(args);
    return options;
}

// ----------------------------------------------------------- the proxy run --

// SLMP_TEST_THROUGH_PROXY set (and not "0"): SimProcess fronts the simulator
// under test with a proxy slmp-sim.
inline bool through_proxy() {
    const char* value = std::getenv("SLMP_TEST_THROUGH_PROXY");
    return value && *value && std::string(value) != "0";
}

// The options of the simulator under test that a proxy applies in front of
// its upstream too (docs/twin.md, "What still applies in front of the
// upstream": the port's limits), each with its value.
inline std::vector<std::string> port_options_for_proxy(const std::vector<std::string>& args) {
    static const std::vector<std::string> kPortOptions = {"--profile", "-p", "--max-connections",
                                                          "--max-connections-per-address", "--idle-timeout",
                                                          "--partial-frame-timeout", "--max-request-bytes",
                                                          "--data-code"};
    std::vector<std::string> kept;
    for (std::size_t i = 0; i + 1 < args.size(); ++i) {
        if (std::find(kPortOptions.begin(), kPortOptions.end(), args[i]) == kPortOptions.end()) continue;
        kept.insert(kept.end(), {args[i], args[i + 1]});
        ++i;
    }
    return kept;
}

// A one-station configuration the proxy run can front: none that names its
// own ports or serves other protocols (their ports would not pass through).
inline bool config_frontable(const std::string& config_json) {
    if (config_json.empty()) return true;
    auto config = nlohmann::json::parse(config_json, nullptr, false);
    if (config.is_discarded() || !config.is_object()) return false;
    for (const char* key : {"stations", "ports", "tcp_port", "udp_port", "hostlink", "jw51cm", "kind", "shards", "upstream"})
        if (config.contains(key)) return false;
    return true;
}

// What of a configuration the proxy applies in front of its upstream too:
// the profile (its port's limits) and the largest request.
inline nlohmann::json proxy_config(const std::string& config_json) {
    auto proxy = nlohmann::json::object();
    if (config_json.empty()) return proxy;
    auto config = nlohmann::json::parse(config_json, nullptr, false);
    for (const char* key : {"profile", "max_request_bytes"})
        if (config.is_object() && config.contains(key)) proxy[key] = config[key];
    return proxy;
}

// The SLMP exchanges of a recording (docs/scenarios.md, "Record & replay"),
// each "request -> response" (response "null" when none was sent); the
// other protocols' lines are left out.
inline std::vector<std::string> recorded_exchanges(const std::filesystem::path& file) {
    std::vector<std::string> exchanges;
    std::ifstream in(file);
    for (std::string line; std::getline(in, line);) {
        auto entry = nlohmann::json::parse(line, nullptr, false);
        if (entry.is_discarded() || entry.value("event", "") != "exchange" || entry.contains("protocol")) continue;
        exchanges.push_back(entry.value("request", "") + " -> " + entry["response"].dump());
    }
    return exchanges;
}

// Counts of the proxy run, printed when the test program ends.
struct ProxyRunTally {
    unsigned fronted = 0;            // simulators run behind a proxy
    unsigned direct = 0;             // ... and run without one (a plant, a configuration naming its own ports)
    std::uint64_t exchanges = 0;     // exchanges both recordings held alike
    std::uint64_t kept_back = 0;     // bytes that started no frame, dropped by the proxy's port, unanswered
    ~ProxyRunTally() {
        if (fronted || direct)
            std::fprintf(stderr, "proxy run: %u simulator(s) behind a proxy, %u direct; %llu exchange(s) passed through, "
                                 "recorded alike on both sides; %llu unanswered non-frame(s) kept back by the proxy\n",
                         fronted, direct, static_cast<unsigned long long>(exchanges),
                         static_cast<unsigned long long>(kept_back));
    }
};
inline ProxyRunTally proxy_run_tally;

class SimProcess {
public:
    explicit SimProcess(SimOptions options = {}) {
        ready_file_ = dir_.path() / "ready.json";
        // The proxy run fronts a one-station process that the options start
        // whole: a plant or a --config names its own ports and stations.
        const bool fronted = through_proxy() && !options.plant && config_frontable(options.config_json) &&
                             std::find(options.args.begin(), options.args.end(), "--config") == options.args.end();
        if (through_proxy()) ++(fronted ? proxy_run_tally.fronted : proxy_run_tally.direct);
        std::vector<std::string> args;
        if (!options.config_json.empty()) {
            config_file_ = dir_.write("config.json", options.config_json);
            args.insert(args.end(), {"--config", config_file_.string()});
        }
        if (!options.plant) {
            // Behind a proxy the simulator needs a TCP port for the proxy's upstream connection.
            const unsigned tcp_ports = fronted ? std::max(1U, options.tcp_ports) : options.tcp_ports;
            for (unsigned i = 0; i < tcp_ports; ++i) args.insert(args.end(), {"--tcp-port", "0"});
            for (unsigned i = 0; i < options.udp_ports; ++i) args.insert(args.end(), {"--udp-port", "0"});
            args.insert(args.end(), {"--bind", "127.0.0.1"});
        }
        args.insert(args.end(), {"--ready-file", ready_file_.string()});
        if (!options.default_log_level) args.insert(args.end(), {"--log-level", "warn"});
        // The HTTP API on an ephemeral port too, so parallel tests never fight
        // over 8080 — unless the test sets up HTTP itself.
        auto given = [&](const char* option) {
            return std::find(options.args.begin(), options.args.end(), option) != options.args.end();
        };
        if (!given("--no-http") && !given("--http-port") && options.config_json.find("\"http\"") == std::string::npos)
            args.insert(args.end(), {"--http-port", "0"});
        args.insert(args.end(), options.args.begin(), options.args.end());
        if (fronted) {   // the simulator's side of the exchanges, for the check at the stop
            auto given = std::find(options.args.begin(), options.args.end(), "--record");
            if (given != options.args.end() && given + 1 != options.args.end()) {
                target_record_ = *(given + 1);
            } else {
                target_record_ = dir_.path() / "target.jsonl";
                args.insert(args.end(), {"--record", target_record_.string()});
            }
        }
        args_ = args;
        pid_ = detail::spawn(args, dir_.path() / "stdout", dir_.path() / "stderr");
        wait_ready();
        if (!fronted) return;
        try {
            start_proxy(options);
        } catch (...) {   // no destructor runs for a constructor that throws: the simulator goes now
            ::kill(pid_, SIGKILL);
            ::waitpid(pid_, nullptr, 0);
            stopped_ = true;
            throw;
        }
    }

    ~SimProcess() {
        if (pid_ > 0 && !stopped_) {
            int status = stop(SIGTERM);
            CHECK(status == 0);
        }
    }
    SimProcess(const SimProcess&) = delete;
    SimProcess& operator=(const SimProcess&) = delete;

    // Sends `sig` and waits for the exit. Returns the exit code, or -1 when the
    // process did not exit by itself in time (it is then killed) or died by a signal.
    int stop(int sig = SIGTERM) {
        if (stopped_) return exit_code_;
        stopped_ = true;
        if (proxy_pid_ > 0) stop_proxy(sig);
        std::optional<int> status = reaped_;   // stop_proxy() stopped it already
        if (!status) {
            ::kill(pid_, sig);
            status = detail::wait_for(pid_, kStopTimeout);
        }
        if (!status) {
            ::kill(pid_, SIGKILL);
            ::waitpid(pid_, nullptr, 0);
            UNSCOPED_INFO("slmp-sim did not exit within " << kStopTimeout.count() << " s of signal " << sig
                                                          << "\n" << logs());
            exit_code_ = -1;
        } else if (WIFEXITED(*status)) {
            exit_code_ = WEXITSTATUS(*status);
            if (exit_code_ != 0) UNSCOPED_INFO("slmp-sim " << detail::describe_status(*status) << "\n" << logs());
        } else {
            UNSCOPED_INFO("slmp-sim " << detail::describe_status(*status) << "\n" << logs());
            exit_code_ = -1;
        }
        return exit_code_;
    }

    pid_t pid() const { return pid_; }
    std::uint16_t tcp_port(std::size_t i = 0) const { return tcp_ports_.at(i); }
    std::uint16_t udp_port(std::size_t i = 0) const { return udp_ports_.at(i); }
    const std::vector<std::uint16_t>& tcp_ports() const { return tcp_ports_; }
    const std::vector<std::uint16_t>& udp_ports() const { return udp_ports_; }
    // The HTTP API port from the ready file (0 with --no-http).
    std::uint16_t http_port() const { return ready_.value("http", std::uint16_t{0}); }
    const nlohmann::json& ready() const { return ready_; }
    std::string logs() const {
        auto text = "--- slmp-sim stdout ---\n" + read_text(dir_.path() / "stdout") + "--- slmp-sim stderr ---\n" +
                    read_text(dir_.path() / "stderr");
        if (proxy_dir_)
            text += "--- proxy slmp-sim stdout ---\n" + read_text(proxy_dir_->path() / "stdout") +
                    "--- proxy slmp-sim stderr ---\n" + read_text(proxy_dir_->path() / "stderr");
        return text;
    }

private:
    // Waits for `pid`'s ready file; its JSON (FAIL when it exits first or writes none in time).
    nlohmann::json wait_ready(pid_t pid, const std::filesystem::path& ready_file) {
        auto deadline = std::chrono::steady_clock::now() + kStartTimeout;
        for (;;) {
            int status = 0;
            if (::waitpid(pid, &status, WNOHANG) == pid) {
                if (pid == pid_) stopped_ = true;
                else proxy_pid_ = -1;
                FAIL("slmp-sim exited before it was ready (" << detail::describe_status(status) << ")\n"
                                                             << logs());
            }
            std::error_code ec;
            if (std::filesystem::exists(ready_file, ec)) {
                auto text = read_text(ready_file);
                auto json = nlohmann::json::parse(text, nullptr, false);
                if (!json.is_discarded() && json.is_object()) return json;
            }
            if (std::chrono::steady_clock::now() >= deadline) {
                ::kill(pid, SIGKILL);
                ::waitpid(pid, nullptr, 0);
                if (pid == pid_) stopped_ = true;
                else proxy_pid_ = -1;
                FAIL("slmp-sim wrote no valid ready file within " << kStartTimeout.count() << " s\n" << logs());
            }
            std::this_thread::sleep_for(std::chrono::milliseconds(10));
        }
    }

    void wait_ready() {
        ready_ = wait_ready(pid_, ready_file_);
        for (auto& p : ready_.value("tcp", nlohmann::json::array())) tcp_ports_.push_back(p.get<std::uint16_t>());
        for (auto& p : ready_.value("udp", nlohmann::json::array())) udp_ports_.push_back(p.get<std::uint16_t>());
    }

    // The proxy run: a proxy slmp-sim with as many SLMP ports as the test
    // asked for, every one passing its requests to this simulator's first
    // TCP port; from now on the test's SLMP ports are the proxy's (its HTTP
    // API stays this simulator's: the proxy serves none).
    void start_proxy(const SimOptions& options) {
        proxy_dir_ = std::make_unique<TempDir>();
        auto ready_file = proxy_dir_->path() / "ready.json";
        proxy_record_ = proxy_dir_->path() / "proxy.jsonl";
        std::vector<std::string> args{"--upstream", "127.0.0.1:" + std::to_string(tcp_ports_.at(0)), "--record",
                                      proxy_record_.string(), "--ready-file", ready_file.string(), "--no-http",
                                      "--bind", "127.0.0.1", "--log-level", "warn"};
        for (unsigned i = 0; i < options.tcp_ports; ++i) args.insert(args.end(), {"--tcp-port", "0"});
        for (unsigned i = 0; i < options.udp_ports; ++i) args.insert(args.end(), {"--udp-port", "0"});
        if (auto config = proxy_config(options.config_json); !config.empty())
            args.insert(args.end(), {"--config", proxy_dir_->write("config.json", config.dump()).string()});
        auto port_options = port_options_for_proxy(options.args);
        args.insert(args.end(), port_options.begin(), port_options.end());
        proxy_pid_ = detail::spawn(args, proxy_dir_->path() / "stdout", proxy_dir_->path() / "stderr");
        auto ready = wait_ready(proxy_pid_, ready_file);
        tcp_ports_.clear();
        udp_ports_.clear();
        for (auto& p : ready.value("tcp", nlohmann::json::array())) tcp_ports_.push_back(p.get<std::uint16_t>());
        for (auto& p : ready.value("udp", nlohmann::json::array())) udp_ports_.push_back(p.get<std::uint16_t>());
        ready_["tcp"] = ready.value("tcp", nlohmann::json::array());
        ready_["udp"] = ready.value("udp", nlohmann::json::array());
    }

    // Stops the proxy first (its recording is whole once it has exited),
    // then, at a clean stop, checks the two recordings hold the same
    // exchanges: each request the test sent reached the simulator as it was
    // sent, and its answer came back as the simulator gave it. Compared as
    // multisets: the requests of several connections take turns on the
    // proxy's one upstream connection in an order neither side records alike.
    void stop_proxy(int sig) {
        ::kill(proxy_pid_, SIGTERM);
        auto status = detail::wait_for(proxy_pid_, kStopTimeout);
        if (!status) {
            ::kill(proxy_pid_, SIGKILL);
            ::waitpid(proxy_pid_, nullptr, 0);
        }
        proxy_pid_ = -1;
        CHECK((status && WIFEXITED(*status) && WEXITSTATUS(*status) == 0));
        if (sig != SIGTERM) return;
        ::kill(pid_, SIGTERM);   // the simulator's recording is whole once it has exited too
        auto target = detail::wait_for(pid_, kStopTimeout);
        if (!target) return;     // stop() reports it
        reaped_ = *target;
        auto through = recorded_exchanges(proxy_record_);
        auto served = recorded_exchanges(target_record_);
        std::sort(through.begin(), through.end());
        std::sort(served.begin(), served.end());
        std::vector<std::string> only_proxy, only_served;
        std::set_difference(through.begin(), through.end(), served.begin(), served.end(), std::back_inserter(only_proxy));
        std::set_difference(served.begin(), served.end(), through.begin(), through.end(), std::back_inserter(only_served));
        // Bytes that start no frame stay the proxy's port's own business (docs/twin.md, "Proxy"): it
        // answers them as any port does — here with nothing — and passes nothing on.
        const auto kept_back = std::count_if(only_proxy.begin(), only_proxy.end(), [](const std::string& exchange) {
            return exchange.size() >= 8 && exchange.compare(exchange.size() - 8, 8, " -> null") == 0;
        });
        std::erase_if(only_proxy, [](const std::string& exchange) {
            return exchange.size() >= 8 && exchange.compare(exchange.size() - 8, 8, " -> null") == 0;
        });
        INFO("proxy run: the proxy recorded " << through.size() << " exchange(s), the simulator " << served.size()
                                              << (only_proxy.empty() ? "" : "; first only at the proxy: " + only_proxy.front())
                                              << (only_served.empty() ? "" : "; first only at the simulator: " + only_served.front()));
        CHECK(only_proxy.empty());
        CHECK(only_served.empty());
        if (only_proxy.empty() && only_served.empty()) {
            proxy_run_tally.exchanges += served.size();
            proxy_run_tally.kept_back += static_cast<std::uint64_t>(kept_back);
        }
    }

    TempDir dir_;
    std::filesystem::path ready_file_;
    std::filesystem::path config_file_;
    std::vector<std::string> args_;
    pid_t pid_ = -1;
    bool stopped_ = false;
    int exit_code_ = -1;
    nlohmann::json ready_;
    std::vector<std::uint16_t> tcp_ports_;
    std::vector<std::uint16_t> udp_ports_;
    // The proxy run only.
    std::unique_ptr<TempDir> proxy_dir_;
    pid_t proxy_pid_ = -1;
    std::filesystem::path proxy_record_;
    std::filesystem::path target_record_;
    std::optional<int> reaped_;   // the simulator's wait status, when stop_proxy() stopped it
};

}  // namespace slmp::test
