// slmp-sim: a MELSEC CPU that answers SLMP over TCP and UDP.
// Exit codes: 0 clean shutdown, 2 bad options/configuration or a port that
// cannot be had (one line on stderr that names the problem and the fix).
#include <malloc.h>

#include <iostream>
#include <sstream>

#include <spdlog/spdlog.h>

#include "server/check_config.hpp"
#include "server/options.hpp"
#include "server/server.hpp"
#include "station/station_log.hpp"

namespace {

spdlog::level::level_enum log_level(const std::string& text) {
    auto level = spdlog::level::from_str(text);
    // from_str answers "off" for anything it does not know.
    if (level == spdlog::level::off && text != "off")
        throw slmp::config::ConfigError("log level '" + text + "' unknown; use trace, debug, info, warn, error or off");
    return level;
}

}  // namespace

int main(int argc, char** argv) {
    // Device stores of 128 KiB and more come from mmap, as fresh zero pages
    // that cost RAM only once written (docs/plants.md, "Memory"); a fixed
    // threshold keeps glibc from raising it after the first large free.
    mallopt(M_MMAP_THRESHOLD, 128 * 1024);
    try {
        auto cl = slmp::server::parse_command_line(argc, argv);
        if (cl.exit_now) return 0;
        spdlog::set_level(log_level(cl.plant.stations.front().server.log_level));
        if (cl.check_only) {
            for (const auto& station : cl.plant.stations) slmp::server::check_configuration(station);
            std::cout << "slmp-sim: configuration OK\n";
            return 0;
        }
        slmp::station::use_log_format();
        slmp::server::Server server(cl.plant);
        server.run();
        return 0;
    } catch (const std::exception& e) {
        // One line per problem (a program that does not load lists them all).
        std::istringstream lines(e.what());
        for (std::string line; std::getline(lines, line);) std::cerr << "slmp-sim: error: " << line << "\n";
        return 2;
    }
}
