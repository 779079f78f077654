#include "station/station_log.hpp"

#include <spdlog/spdlog.h>

namespace slmp::station {

std::shared_ptr<spdlog::logger> station_logger(const std::string& name) {
    if (name.empty()) return spdlog::default_logger();
    // A clone shares the default logger's sinks and level; not registered, so
    // a plant of many stations does not fill spdlog's registry.
    auto logger = spdlog::default_logger()->clone(name);
    logger->set_pattern(std::string(kLogLineHead) + "%n: %v");
    return logger;
}

}  // namespace slmp::station
