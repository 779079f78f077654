// How the load is generated, and why this way.
//
// All connections run as Asio coroutines on ONE io_context driven by ONE
// thread. The target machine has two cores and the simulator serves all its
// sessions on one core thread; a single-threaded client leaves it the other
// core, instead of N blocking threads fighting it for CPU, so what we measure
// is the server and the loopback stack rather than our own scheduling. The
// price: when the client thread is saturated its queueing shows up in the
// latencies, so watch the client's CPU (e.g. `time`) at high connection counts.
//
// Each connection is closed-loop: it sends the next request only when a
// response (or a timeout) frees a slot, so latencies do not include the wait a
// request would have had in an open-loop (fixed-rate) arrival model.
#include "tools/bench/run.hpp"

#include <boost/asio/io_context.hpp>
#include <boost/asio/ip/tcp.hpp>
#include <boost/asio/steady_timer.hpp>

#include <stdexcept>

#include "tools/bench/connection.hpp"
#include "tools/bench/control.hpp"
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
asio::ip::address resolve(asio::io_context& io, const Options& options) {
    asio::ip::tcp::resolver resolver(io);
    boost::system::error_code ec;
    auto results = resolver.resolve(options.host, std::to_string(options.port), ec);
    if (ec || results.empty()) throw std::invalid_argument("cannot resolve --host '" + options.host + "'");
    auto address = results.begin()->endpoint().address();
    if (!address.is_loopback() && !options.allow_remote)
        throw std::invalid_argument("--host " + options.host + " (" + address.to_string() +
                                    ") is not a loopback address; add --allow-remote if you really mean it");
    return address;
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
    auto address = resolve(io, options);
    Workload workload = make_workload(options);

    auto start = Clock::now();
    auto measure_for = seconds(options.duration);
    RunState state{workload, options.depth,
                   RunControl(start, seconds(options.warmup), measure_for, options.requests, seconds(options.timeout)),
                   std::vector<Recorder>(workload.operations.size()), {}, options.connections, {}};

    for (unsigned i = 0; i < options.connections; ++i)
        start_connection(io.get_executor(), state, i, options.udp, address, options.port);

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
    state.all_done = [&] { hard_stop.cancel(); };
    io.run();

    Results results;
    results.target = std::string(options.udp ? "udp " : "tcp ") + address.to_string() + ":" +
                     std::to_string(options.port);
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
