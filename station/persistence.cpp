#include "station/persistence.hpp"

#include <spdlog/spdlog.h>

#include "station/log_exception.hpp"

#include "devicemodel/snapshot.hpp"

namespace slmp::station {

namespace asio = boost::asio;

Persistence::Persistence(const station::Home& home, devicemodel::Cpu& cpu, const config::PersistenceConfig& config,
                         spdlog::logger& log)
    : cpu_(cpu),
      log_(log),
      store_(config.state_dir),
      units_store_(config.state_dir, "units.bin"),
      interval_(static_cast<std::int64_t>(config.snapshot_interval_s * 1000)),
      restore_all_(config.restore_all),
      timer_(home) {}

void Persistence::restore() {
    auto bytes = store_.load();
    if (!bytes) {
        log_.info("state directory: no snapshot yet at {}; starting with fresh device memory", store_.file().string());
        return;
    }
    auto scope = restore_all_ ? devicemodel::RestoreScope::All : devicemodel::RestoreScope::Latched;
    auto result = devicemodel::restore_snapshot(*bytes, cpu_.memory(), cpu_.profile().name, cpu_.runtime().latch(), scope);
    if (!result.ok)
        throw config::ConfigError("state directory: " + store_.file().string() + " cannot be restored: " + result.error +
                                  "; start with the profile it was saved with, or move the file away to start afresh");
    for (const auto& w : result.warnings) log_.warn("state directory: {}", w);
    log_.info("state directory: restored {} devices from {}", restore_all_ ? "all" : "latched",
              store_.file().string());
}

bool Persistence::save(std::string_view why) {
    try {
        if (before_save) before_save();
        auto started = std::chrono::steady_clock::now();
        store_.save(devicemodel::encode_snapshot(cpu_.memory(), cpu_.profile().name));
        if (units)
            if (auto bytes = units()) units_store_.save(*bytes);
        log_.debug("state directory: snapshot saved ({}) in {} ms", why,
                   std::chrono::duration_cast<std::chrono::milliseconds>(std::chrono::steady_clock::now() - started).count());
        return true;
    } catch (const std::exception& e) {
        log_.error("state directory: snapshot ({}) failed: {}", why, e.what());
        return false;
    }
}

void Persistence::start() {
    if (interval_.count() <= 0) return;
    asio::co_spawn(timer_.get_executor(), every_interval(), log_exception("state directory: interval snapshots stopped"));
}

void Persistence::stop() {
    stopped_ = true;
    timer_.cancel();
}

asio::awaitable<void> Persistence::every_interval() {
    while (!stopped_) {
        timer_.expires_after(interval_);
        boost::system::error_code ec;
        co_await timer_.async_wait(asio::redirect_error(asio::use_awaitable, ec));
        if (ec || stopped_) co_return;
        save("interval");
    }
}

}  // namespace slmp::station
