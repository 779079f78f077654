// How the load is generated, and why this way.
//
// All connections run as Asio coroutines on ONE io_context driven by ONE
// thread. The target machine has two cores and a station of the simulator is
// served by one thread; a single-threaded client leaves the server the other
// core, instead of N blocking threads fighting it for CPU, so what we measure
// is the server and the loopback stack rather than our own scheduling. The
// price: when the client thread is saturated its queueing shows up in the
// latencies, so watch the client's CPU (--server-pid reports it) at high
// connection counts.
//
// Each connection is closed-loop: it sends the next request only when a
// response (or a timeout) frees a slot, so latencies do not include the wait a
// request would have had in an open-loop (fixed-rate) arrival model.
#include "tools/bench/run.hpp"

#include <boost/asio/io_context.hpp>
#include <boost/asio/ip/tcp.hpp>
#include <boost/asio/steady_timer.hpp>

#include <map>
#include <optional>
#include <stdexcept>

#include "tools/bench/connection.hpp"
#include "tools/bench/control.hpp"
#include "tools/bench/process_cpu.hpp"
#include "tools/bench/workload.hpp"

namespace slmp::bench {

namespace asio = boost::asio;

namespace {

Clock::duration seconds(double s) {
    return std::chrono::duration_cast<Clock::duration>(std::chrono::duration<double>(s));
}

// Resolves without touching the network (numeric addresses and "localhost").
// Refuses anything but loopback unless --allow-remote: a load generator must
// never hit a real PLC by accident.
asio::ip::address resolve(asio::io_context& io, const Target& target, bool allow_remote) {
    asio::ip::tcp::resolver resolver(io);
    boost::system::error_code ec;
    auto results = resolver.resolve(target.host, std::to_string(target.port), ec);
    if (ec || results.empty()) throw std::invalid_argument("cannot resolve host '" + target.host + "'");
    auto address = results.begin()->endpoint().address();
    if (!address.is_loopback() && !allow_remote)
        throw std::invalid_argument("host " + target.host + " (" + address.to_string() +
                                    ") is not a loopback address; add --allow-remote if you really mean it");
    return address;
}

struct Endpoint {
    asio::ip::address address;
    std::uint16_t port;
};

// Every target's address, each host looked up once (a range is one host).
std::vector<Endpoint> resolve_all(asio::io_context& io, const Options& options) {
    std::map<std::string, asio::ip::address> hosts;
    std::vector<Endpoint> endpoints;
    for (const auto& target : options.targets) {
        auto known = hosts.find(target.host);
        if (known == hosts.end()) known = hosts.emplace(target.host, resolve(io, target, options.allow_remote)).first;
        endpoints.push_back({known->second, target.port});
    }
    return endpoints;
}

std::string describe_target(const Options& options, const std::vector<Endpoint>& endpoints) {
    std::string transport = options.udp ? "udp " : "tcp ";
    if (options.targets_text.empty())
        return transport + endpoints[0].address.to_string() + ":" + std::to_string(endpoints[0].port);
    return transport + options.targets_text + " (" + std::to_string(endpoints.size()) + " targets)";
}

// The server's and our own CPU time at one moment (--server-pid).
struct CpuSample {
    std::optional<double> server_s;
    double client_s = 0;
    Clock::time_point at;
};

CpuSample sample_cpu(pid_t server) {
    return {process_cpu_seconds(server), own_cpu_seconds(), Clock::now()};
}

CpuUse cpu_between(const CpuSample& from, const CpuSample& to) {
    CpuUse use;
    if (!from.server_s || !to.server_s) return use;
    use.measured = true;
    use.server_s = *to.server_s - *from.server_s;
    use.client_s = to.client_s - from.client_s;
    use.wall_s = std::chrono::duration<double>(to.at - from.at).count();
    return use;
}

OperationResult summarize(std::string name, Recorder recorder) {
    OperationResult r;
    r.name = std::move(name);
    r.ok = recorder.latencies_ns.size();
    r.latency = summarize_latency(recorder.latencies_ns);
    recorder.latencies_ns = {};
    r.recorder = std::move(recorder);
    return r;
}

}  // namespace

Results run_benchmark(const Options& options) {
    asio::io_context io(1);
    auto endpoints = resolve_all(io, options);
    Workload workload = make_workload(options);

    auto start = Clock::now();
    auto measure_for = seconds(options.duration);
    RunState state{workload, options.depth,
                   RunControl(start, seconds(options.warmup), measure_for, options.requests, seconds(options.timeout)),
                   std::vector<Recorder>(workload.operations.size()), {}, options.connections, {}};

    // The server's CPU is counted from the end of the warm-up, like the requests.
    CpuSample cpu_start;
    asio::steady_timer cpu_timer(io);
    if (options.server_pid > 0) {
        cpu_timer.expires_at(state.control.measure_start());
        cpu_timer.async_wait([&](boost::system::error_code ec) {
            if (!ec) cpu_start = sample_cpu(options.server_pid);
        });
    }

    // Round-robin: connection i goes to target i mod the number of targets.
    for (unsigned i = 0; i < options.connections; ++i) {
        const Endpoint& to = endpoints[i % endpoints.size()];
        start_connection(io.get_executor(), state, i, options.udp, to.address, to.port);
    }

    // Belt and braces: connections end by themselves within one timeout of the
    // end, but never let a bug turn into a hang.
    asio::steady_timer hard_stop(io);
    if (measure_for.count() > 0) {
        hard_stop.expires_at(state.control.send_until() + 2 * seconds(options.timeout) + std::chrono::seconds(1));
        hard_stop.async_wait([&](boost::system::error_code ec) {
            if (ec) return;
            if (state.fatal.empty()) state.fatal = "connections did not finish in time (stopped)";
            io.stop();
        });
    }
    state.all_done = [&] {
        hard_stop.cancel();
        cpu_timer.cancel();   // only pending when the run ended before its warm-up did
    };
    io.run();

    Results results;
    if (options.server_pid > 0) results.cpu = cpu_between(cpu_start, sample_cpu(options.server_pid));
    results.target = describe_target(options, endpoints);
    results.targets = endpoints.size();
    results.seconds = state.control.measured_seconds();
    results.sent = state.control.measured_sent();
    results.fatal = state.fatal;
    Recorder all;
    for (std::size_t i = 0; i < workload.operations.size(); ++i) {
        all.merge(state.recorders[i]);
        results.operations.push_back(summarize(workload.operations[i].name, std::move(state.recorders[i])));
    }
    results.total = summarize("total", std::move(all));
    return results;
}

}  // namespace slmp::bench
