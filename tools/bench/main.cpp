// slmp-bench: an SLMP load generator, and with --baseline-server the
// cheapest SLMP server to compare a server with. See docs/bench.md.
//
// Exit status: 0 when the run completed without errors, 1 when it completed
// with errors (or no answered request, or could not run), 2 on bad usage.
#include <cstring>
#include <exception>
#include <iostream>

#include "tools/bench/baseline_server.hpp"
#include "tools/bench/options.hpp"
#include "tools/bench/report.hpp"
#include "tools/bench/run.hpp"

int main(int argc, char** argv) {
    using namespace slmp::bench;
    // The baseline server is a mode of its own with its own options.
    for (int i = 1; i < argc; ++i)
        if (std::strcmp(argv[i], "--baseline-server") == 0) return baseline::baseline_main(argc, argv);
    int exit_code = 0;
    auto options = parse_options(argc, argv, exit_code);
    if (!options) return exit_code;
    try {
        Results results = run_benchmark(*options);
        if (options->json) {
            print_json(std::cout, *options, results);
        } else {
            print_table(std::cout, *options, results);
        }
        bool clean = results.fatal.empty() && results.total.ok > 0 && results.total.recorder.error_total() == 0;
        return clean ? 0 : 1;
    } catch (const std::invalid_argument& e) {
        std::cerr << "slmp-bench: " << e.what() << '\n';
        return 2;
    } catch (const std::exception& e) {
        std::cerr << "slmp-bench: " << e.what() << '\n';
        return 1;
    }
}
