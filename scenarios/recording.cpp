#include "scenarios/recording.hpp"

#include <ctime>

#include <nlohmann/json.hpp>

#include "config/config.hpp"
#include "devicemodel/hex.hpp"

namespace slmp::scenarios {

using nlohmann::json;

std::string to_hex(std::span<const std::uint8_t> bytes) { return devicemodel::bytes_to_hex(bytes, /*lower_case=*/true); }

std::optional<std::vector<std::uint8_t>> from_hex(std::string_view text) { return devicemodel::hex_to_bytes(text); }

Recording read_recording(const std::filesystem::path& file) {
    std::ifstream in(file, std::ios::binary);
    if (!in) throw config::ConfigError(file.string() + ": cannot open the recording; check the path");
    Recording r;
    std::string text;
    std::size_t number = 0;
    auto fail = [&](const std::string& problem, const std::string& fix) {
        throw config::ConfigError(file.string() + ":" + std::to_string(number) + ": " + problem + "; " + fix);
    };
    while (std::getline(in, text)) {
        ++number;
        if (text.find_first_not_of(" \t\r") == std::string::npos) continue;
        auto j = json::parse(text, nullptr, false);
        if (j.is_discarded() || !j.is_object()) fail("not a JSON object", "each line of a recording is one JSON object");
        if (number == 1) {
            if (!j.contains("slmp_recording")) fail("not an slmp-sim recording (no \"slmp_recording\" header)", "record with slmp-sim --record FILE");
            r.profile = j.value("profile", "");
            continue;
        }
        if (j.value("event", "") != "exchange") continue;
        if (j.value("protocol", "slmp") != "slmp") continue;   // a front end's exchange: not replayed
        RecordedExchange e;
        e.t_ms = j.value("t_ms", 0.0);
        e.connection = j.value("conn", std::uint64_t{0});
        e.transport = j.value("transport", "tcp") == "udp" ? Transport::Udp : Transport::Tcp;
        e.peer = j.value("peer", "");
        auto request = j.contains("request") && j["request"].is_string() ? from_hex(j["request"].get<std::string>()) : std::nullopt;
        if (!request || request->empty()) fail("\"request\" is missing or not hex", "write the request bytes as hex");
        e.request = std::move(*request);
        if (j.contains("response") && !j["response"].is_null()) {
            auto response = j["response"].is_string() ? from_hex(j["response"].get<std::string>()) : std::nullopt;
            if (!response) fail("\"response\" is not hex", "write the response bytes as hex, or null for no response");
            e.response = std::move(*response);
        }
        r.exchanges.push_back(std::move(e));
    }
    if (number == 0) fail("the file is empty", "record with slmp-sim --record FILE");
    return r;
}

}  // namespace slmp::scenarios
