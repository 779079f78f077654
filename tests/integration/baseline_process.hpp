// `slmp-bench --baseline-server` as a real process for black-box tests: free
// ports, a ready file (waited for, at most 10 s, as SimProcess does), SIGTERM
// at the end and exit status 0 checked. Its output goes to files in a
// temporary directory, printed when something goes wrong.
#pragma once

#include "sim_process.hpp"

#ifndef SLMP_BENCH_BINARY
#error "SLMP_BENCH_BINARY must name the slmp-bench executable under test"
#endif

namespace slmp::test {

class BaselineProcess {
public:
    explicit BaselineProcess(unsigned threads = 2) {
        ready_file_ = dir_.path() / "ready.json";
        pid_ = detail::spawn({"--baseline-server", "--threads", std::to_string(threads), "--tcp-port", "0", "--udp-port",
                              "0", "--ready-file", ready_file_.string()},
                             dir_.path() / "stdout", dir_.path() / "stderr", SLMP_BENCH_BINARY);
        auto deadline = std::chrono::steady_clock::now() + kStartTimeout;
        for (;;) {
            int status = 0;
            if (::waitpid(pid_, &status, WNOHANG) == pid_) {
                pid_ = -1;
                FAIL("the baseline server exited before it was ready (" << detail::describe_status(status) << ")\n"
                                                                         << logs());
            }
            auto ready = nlohmann::json::parse(read_text(ready_file_), nullptr, false);
            if (!ready.is_discarded() && ready.is_object()) {
                tcp_port_ = ready["tcp"][0].get<std::uint16_t>();
                udp_port_ = ready["udp"][0].get<std::uint16_t>();
                CHECK(ready["threads"] == threads);
                CHECK(ready["pid"] == pid_);
                return;
            }
            if (std::chrono::steady_clock::now() >= deadline) {
                ::kill(pid_, SIGKILL);
                ::waitpid(pid_, nullptr, 0);
                pid_ = -1;
                FAIL("the baseline server wrote no ready file within " << kStartTimeout.count() << " s\n" << logs());
            }
            std::this_thread::sleep_for(std::chrono::milliseconds(10));
        }
    }
    ~BaselineProcess() {
        if (pid_ <= 0) return;
        ::kill(pid_, SIGTERM);
        auto status = detail::wait_for(pid_, kStopTimeout);
        if (!status) {
            ::kill(pid_, SIGKILL);
            ::waitpid(pid_, nullptr, 0);
        }
        INFO(logs());
        CHECK((status && WIFEXITED(*status) && WEXITSTATUS(*status) == 0));
    }
    BaselineProcess(const BaselineProcess&) = delete;
    BaselineProcess& operator=(const BaselineProcess&) = delete;

    pid_t pid() const { return pid_; }
    std::uint16_t tcp_port() const { return tcp_port_; }
    std::uint16_t udp_port() const { return udp_port_; }
    std::string logs() const {
        return "--- baseline stdout ---\n" + read_text(dir_.path() / "stdout") + "--- baseline stderr ---\n" +
               read_text(dir_.path() / "stderr");
    }

private:
    TempDir dir_;
    std::filesystem::path ready_file_;
    pid_t pid_ = -1;
    std::uint16_t tcp_port_ = 0, udp_port_ = 0;
};

// Runs slmp-bench (the load generator) to completion.
inline RunResult run_bench(const std::vector<std::string>& args) {
    return run_binary(SLMP_BENCH_BINARY, args, std::chrono::seconds(30));
}

}  // namespace slmp::test
