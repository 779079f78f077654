// The command line of `slmp-bench --baseline-server` (docs/bench.md).
#include <boost/program_options.hpp>

#include <algorithm>
#include <iostream>
#include <stdexcept>
#include <thread>

#include "tools/bench/baseline_server.hpp"

namespace slmp::bench::baseline {

namespace po = boost::program_options;

int baseline_main(int argc, char** argv) {
    ServerOptions o;
    o.threads = std::max(1u, std::thread::hardware_concurrency());
    po::options_description desc(
        "slmp-bench --baseline-server: the cheapest server that answers slmp-bench's requests\n"
        "correctly (3E/4E, binary/ASCII, TCP and UDP; fixed answers, no device memory),\n"
        "to measure this machine's ceiling next to slmp-sim (see docs/bench.md)\n"
        "Usage: slmp-bench --baseline-server [options]\n\nOptions");
    // clang-format off
    desc.add_options()
        ("help,h", "show this help")
        ("baseline-server", "run the baseline server (this mode)")
        ("threads", po::value(&o.threads)->default_value(o.threads), "threads serving the sockets")
        ("bind", po::value(&o.bind)->default_value(o.bind), "listen address (numeric IPv4 or IPv6)")
        ("tcp-port", po::value(&o.tcp_port)->default_value(o.tcp_port), "TCP port; 0 = any free port")
        ("udp-port", po::value(&o.udp_port)->default_value(o.udp_port), "UDP port; 0 = any free port")
        ("ready-file", po::value(&o.ready_file),
            "written once listening: {\"tcp\":[P],\"udp\":[P],\"threads\":N,\"pid\":N}");
    // clang-format on
    po::variables_map vm;
    try {
        po::store(po::parse_command_line(argc, argv, desc), vm);
        po::notify(vm);
    } catch (const po::error& e) {
        std::cerr << "slmp-bench: " << e.what() << "\n(try --baseline-server --help)\n";
        return 2;
    }
    if (vm.count("help")) {
        std::cout << desc << '\n';
        return 0;
    }
    if (o.threads < 1 || o.threads > 256) {
        std::cerr << "slmp-bench: --threads must be 1..256\n";
        return 2;
    }
    try {
        return serve(o);
    } catch (const std::invalid_argument& e) {
        std::cerr << "slmp-bench: " << e.what() << '\n';
        return 2;
    }
}

}  // namespace slmp::bench::baseline
