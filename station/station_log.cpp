#include "station/station_log.hpp"

#include <spdlog/pattern_formatter.h>
#include <spdlog/spdlog.h>

namespace slmp::station {

namespace {

// "%*": the logger's name and ": ", or nothing for the unnamed default logger.
// The format lives in the sinks, which every station's logger shares, so the
// name is printed by the format, not set per logger.
class NamePrefix final : public spdlog::custom_flag_formatter {
public:
    void format(const spdlog::details::log_msg& message, const std::tm&, spdlog::memory_buf_t& out) override {
        if (message.logger_name.size() == 0) return;
        out.append(message.logger_name.data(), message.logger_name.data() + message.logger_name.size());
        static constexpr char kSeparator[] = ": ";
        out.append(kSeparator, kSeparator + 2);
    }
    std::unique_ptr<custom_flag_formatter> clone() const override { return std::make_unique<NamePrefix>(); }
};

}  // namespace

void use_log_format() {
    auto formatter = std::make_unique<spdlog::pattern_formatter>();
    formatter->add_flag<NamePrefix>('*').set_pattern("%Y-%m-%d %H:%M:%S.%e %^%-5l%$ %*%v");
    spdlog::set_formatter(std::move(formatter));
}

std::shared_ptr<spdlog::logger> process_logger() { return spdlog::default_logger(); }

std::shared_ptr<spdlog::logger> station_logger(const std::string& name) {
    if (name.empty()) return process_logger();
    // Shares the default logger's sinks (and so their format) and level; not
    // registered, so a plant of many stations does not fill spdlog's registry.
    return spdlog::default_logger()->clone(name);
}

}  // namespace slmp::station
