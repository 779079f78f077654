#include "tools/bench/options.hpp"

#include <boost/program_options.hpp>

#include <iostream>
#include <sstream>
#include <stdexcept>

#include "tools/bench/process_cpu.hpp"

namespace slmp::bench {

namespace po = boost::program_options;

namespace {

std::vector<std::string> split_list(const std::string& text) {
    std::vector<std::string> items;
    std::stringstream in(text);
    std::string item;
    while (std::getline(in, item, ',')) {
        if (!item.empty()) items.push_back(item);
    }
    return items;
}

// Returns an error message, or an empty string when the options are usable.
std::string validate(const Options& o) {
    if (o.connections < 1 || o.connections > 1024) return "--connections must be 1..1024";
    if (o.depth < 1 || o.depth > 1024) return "--depth must be 1..1024";
    if (o.depth > 1 && !o.e4)
        return "--depth above 1 needs --4e: only 4E serial numbers tie a response to its request";
    if (o.duration < 0 || o.warmup < 0) return "--duration and --warmup must not be negative";
    if (o.timeout <= 0) return "--timeout must be positive";
    if (o.mix.empty()) return "--mix is empty";
    if (o.requests == 0 && o.duration == 0) return "give --duration above 0 or --requests";
    if (o.server_pid < 0) return "--server-pid must be a process id";
    if (o.server_pid > 0 && !process_cpu_seconds(o.server_pid))
        return "--server-pid " + std::to_string(o.server_pid) + ": no such process (cannot read /proc/" +
               std::to_string(o.server_pid) + "/stat)";
    return {};
}

}  // namespace

std::optional<Options> parse_options(int argc, char** argv, int& exit_code) {
    Options o;
    std::string mix = "read1";
    int server_pid = 0;
    po::options_description desc(
        "slmp-bench: SLMP load generator (see docs/bench.md)\n"
        "Usage: slmp-bench [options]\n\nOptions");
    // clang-format off
    desc.add_options()
        ("help,h", "show this help")
        ("host", po::value(&o.host)->default_value(o.host), "server address (loopback unless --allow-remote)")
        ("port", po::value(&o.port)->default_value(o.port), "server port")
        ("targets", po::value(&o.targets_text),
            "servers to spread the connections over, round-robin, instead of --host/--port: "
            "host:first-last (a plant's ports) and/or a comma list host:p1,host:p2")
        ("udp", po::bool_switch(&o.udp), "use UDP instead of TCP")
        ("ascii", po::bool_switch(&o.ascii), "ASCII data code instead of binary")
        ("4e", po::bool_switch(&o.e4), "4E frames with serial numbers instead of 3E")
        ("connections,c", po::value(&o.connections)->default_value(o.connections), "connections (UDP: sockets)")
        ("depth,d", po::value(&o.depth)->default_value(o.depth), "requests in flight per connection (>1 needs --4e)")
        ("duration", po::value(&o.duration)->default_value(o.duration), "seconds to measure (after warm-up)")
        ("requests,n", po::value(&o.requests), "stop after this many measured requests instead of after --duration")
        ("warmup", po::value(&o.warmup)->default_value(o.warmup), "seconds of load before measuring")
        ("timeout", po::value(&o.timeout)->default_value(o.timeout), "seconds before a request counts as timed out")
        ("mix", po::value(&mix)->default_value(mix),
            "comma list, used in turn: read1, read960, write1, write960, readbits")
        ("device", po::value(&o.device), "start device for every operation (default D0; M0 for readbits)")
        ("octal-xy", po::bool_switch(&o.octal_xy), "X/Y numbered in octal, as on an iQ-F (FX5): --device X10 is bit 8")
        ("server-pid", po::value(&server_pid),
            "report this process's CPU time (/proc/PID/stat) during the run and per request")
        ("json", po::bool_switch(&o.json), "print one JSON object instead of the table")
        ("allow-remote", po::bool_switch(&o.allow_remote), "permit a target that is not a loopback address")
        ("baseline-server", "run the baseline server instead (slmp-bench --baseline-server --help)");
    // clang-format on

    po::variables_map vm;
    try {
        po::store(po::parse_command_line(argc, argv, desc), vm);
        po::notify(vm);
    } catch (const po::error& e) {
        std::cerr << "slmp-bench: " << e.what() << "\n(try --help)\n";
        exit_code = 2;
        return std::nullopt;
    }
    if (vm.count("help")) {
        std::cout << desc << '\n';
        exit_code = 0;
        return std::nullopt;
    }
    o.mix = split_list(mix);
    o.server_pid = vm.count("server-pid") && server_pid <= 0 ? -1 : server_pid;
    if (vm.count("targets")) {
        if (!vm["host"].defaulted() || !vm["port"].defaulted()) {
            std::cerr << "slmp-bench: --targets replaces --host and --port; give one or the other\n";
            exit_code = 2;
            return std::nullopt;
        }
        try {
            o.targets = parse_targets(o.targets_text);
        } catch (const std::invalid_argument& e) {
            std::cerr << "slmp-bench: " << e.what() << '\n';
            exit_code = 2;
            return std::nullopt;
        }
    } else {
        o.targets = {{o.host, o.port}};
    }
    // --requests alone replaces the time limit; both together stop at whichever comes first.
    if (o.requests > 0 && vm["duration"].defaulted()) o.duration = 0;
    if (auto error = validate(o); !error.empty()) {
        std::cerr << "slmp-bench: " << error << '\n';
        exit_code = 2;
        return std::nullopt;
    }
    return o;
}

}  // namespace slmp::bench
