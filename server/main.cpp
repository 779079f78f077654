// slmp-sim: a MELSEC CPU that answers SLMP over TCP and UDP.
// Exit codes: 0 clean shutdown, 2 bad options/configuration or a port that
// cannot be had (one line on stderr that names the problem and the fix).
#include <iostream>

#include <spdlog/spdlog.h>

#include "server/check_config.hpp"
#include "server/options.hpp"
#include "server/server.hpp"

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
    try {
        auto cl = slmp::server::parse_command_line(argc, argv);
        if (cl.exit_now) return 0;
        spdlog::set_level(log_level(cl.config.log_level));
        if (cl.check_only) {
            slmp::server::check_configuration(cl.config, cl.frontends);
            std::cout << "slmp-sim: configuration OK\n";
            return 0;
        }
        spdlog::set_pattern("%Y-%m-%d %H:%M:%S.%e %^%-5l%$ %v");
        slmp::server::Server server(cl.config, cl.frontends);
        server.run();
        return 0;
    } catch (const slmp::config::ConfigError& e) {
        std::cerr << "slmp-sim: error: " << e.what() << "\n";
        return 2;
    } catch (const std::exception& e) {
        std::cerr << "slmp-sim: error: " << e.what() << "\n";
        return 2;
    }
}
