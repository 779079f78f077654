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
#include <fstream>
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

class SimProcess {
public:
    explicit SimProcess(SimOptions options = {}) {
        ready_file_ = dir_.path() / "ready.json";
        std::vector<std::string> args;
        if (!options.config_json.empty()) {
            config_file_ = dir_.write("config.json", options.config_json);
            args.insert(args.end(), {"--config", config_file_.string()});
        }
        if (!options.plant) {
            for (unsigned i = 0; i < options.tcp_ports; ++i) args.insert(args.end(), {"--tcp-port", "0"});
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
        args_ = args;
        pid_ = detail::spawn(args, dir_.path() / "stdout", dir_.path() / "stderr");
        wait_ready();
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
        ::kill(pid_, sig);
        auto status = detail::wait_for(pid_, kStopTimeout);
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
        return "--- slmp-sim stdout ---\n" + read_text(dir_.path() / "stdout") + "--- slmp-sim stderr ---\n" +
               read_text(dir_.path() / "stderr");
    }

private:
    void wait_ready() {
        auto deadline = std::chrono::steady_clock::now() + kStartTimeout;
        for (;;) {
            int status = 0;
            if (::waitpid(pid_, &status, WNOHANG) == pid_) {
                stopped_ = true;
                FAIL("slmp-sim exited before it was ready (" << detail::describe_status(status) << ")\n"
                                                             << logs());
            }
            std::error_code ec;
            if (std::filesystem::exists(ready_file_, ec)) {
                auto text = read_text(ready_file_);
                auto json = nlohmann::json::parse(text, nullptr, false);
                if (!json.is_discarded() && json.is_object()) {
                    ready_ = json;
                    for (auto& p : json.value("tcp", nlohmann::json::array())) tcp_ports_.push_back(p.get<std::uint16_t>());
                    for (auto& p : json.value("udp", nlohmann::json::array())) udp_ports_.push_back(p.get<std::uint16_t>());
                    return;
                }
            }
            if (std::chrono::steady_clock::now() >= deadline) {
                ::kill(pid_, SIGKILL);
                ::waitpid(pid_, nullptr, 0);
                stopped_ = true;
                FAIL("slmp-sim wrote no valid ready file within " << kStartTimeout.count() << " s\n" << logs());
            }
            std::this_thread::sleep_for(std::chrono::milliseconds(10));
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
};

}  // namespace slmp::test
