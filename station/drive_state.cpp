#include "station/drive_state.hpp"

#include <spdlog/spdlog.h>

#include <nlohmann/json.hpp>

#include "config/config_error.hpp"

namespace slmp::station {

using nlohmann::json;

namespace {

constexpr std::string_view kFormat = "slmp-sim drives 1";

}  // namespace

DriveState::DriveState(const std::filesystem::path& dir, devicemodel::DriveSet& drives, std::string profile,
                       spdlog::logger& log)
    : drives_(drives), profile_(std::move(profile)), log_(log), store_(dir, "drives.json") {
    for (const auto& view : drives_.drives())
        if (!view.spec.alias_of) configured_[view.spec.number] = {view.spec.present, view.spec.write_protect};
}

void DriveState::restore() {
    auto bytes = store_.load();
    if (!bytes) return;
    const auto fix = "; move the file away to start with fresh file Nos. and attributes";
    try {
        auto doc = json::parse(bytes->begin(), bytes->end());
        if (doc.at("format").get<std::string>() != kFormat)
            throw config::ConfigError("state directory: " + store_.file().string() + " is not a drives memo" + fix);
        if (doc.at("profile").get<std::string>() != profile_)
            log_.warn("state directory: {} was saved with profile {}; drives this CPU lacks are skipped",
                      store_.file().string(), doc.at("profile").get<std::string>());
        for (const auto& item : doc.at("drives")) {
            devicemodel::DriveMemo memo;
            memo.number = item.at("number").get<std::uint16_t>();
            memo.present = item.at("present").get<bool>();
            memo.write_protect = item.at("write_protect").get<bool>();
            memo.slots = item.at("slots").get<std::map<std::string, std::vector<std::string>>>();
            memo.attributes = item.at("attributes").get<std::map<std::string, std::uint8_t>>();
            // The switches come back unless the configuration moved them since:
            // an edited configuration wins over what a scenario left behind.
            const auto& was = item.at("configured");
            auto now = configured_.find(memo.number);
            bool same = now != configured_.end() && was.at("present").get<bool>() == now->second.first &&
                        was.at("write_protect").get<bool>() == now->second.second;
            drives_.restore(memo, same);
        }
    } catch (const json::exception& e) {
        throw config::ConfigError("state directory: " + store_.file().string() + " cannot be read: " + e.what() + fix);
    }
    log_.info("state directory: file Nos., attributes and drive switches restored from {}", store_.file().string());
}

bool DriveState::save() {
    auto drives = json::array();
    for (const auto& memo : drives_.memos()) {
        auto configured = configured_.count(memo.number) ? configured_.at(memo.number) : std::pair{true, false};
        drives.push_back({{"number", memo.number},
                          {"present", memo.present},
                          {"write_protect", memo.write_protect},
                          {"configured", {{"present", configured.first}, {"write_protect", configured.second}}},
                          {"slots", memo.slots},
                          {"attributes", memo.attributes}});
    }
    auto text = json{{"format", kFormat}, {"profile", profile_}, {"drives", std::move(drives)}}.dump(1);
    try {
        store_.save(std::span(reinterpret_cast<const std::uint8_t*>(text.data()), text.size()));
        return true;
    } catch (const std::exception& e) {
        log_.error("state directory: saving the drives memo failed: {}", e.what());
        return false;
    }
}

}  // namespace slmp::station
