#include "scenarios/recording.hpp"

#include <ctime>

#include <nlohmann/json.hpp>

#include "config/config.hpp"
#include "devicemodel/hex.hpp"

namespace slmp::scenarios {

using nlohmann::json;

std::string to_hex(std::span<const std::uint8_t> bytes) { return devicemodel::bytes_to_hex(bytes, /*lower_case=*/true); }

std::optional<std::vector<std::uint8_t>> from_hex(std::string_view text) { return devicemodel::hex_to_bytes(text); }

namespace {

std::string utc_now() {
    auto now = std::chrono::system_clock::now();
    auto t = std::chrono::system_clock::to_time_t(now);
    auto ms = std::chrono::duration_cast<std::chrono::milliseconds>(now.time_since_epoch()).count() % 1000;
    std::tm tm{};
    gmtime_r(&t, &tm);
    char text[64];
    std::snprintf(text, sizeof text, "%04d-%02d-%02dT%02d:%02d:%02d.%03dZ", tm.tm_year + 1900, tm.tm_mon + 1, tm.tm_mday,
                  tm.tm_hour, tm.tm_min, tm.tm_sec, static_cast<int>(ms));
    return text;
}

std::string_view transport_name(Transport t) { return t == Transport::Tcp ? "tcp" : "udp"; }

json event(double t_ms, const RecordedLink& link, const char* what) {
    return json{{"t_ms", t_ms}, {"conn", link.connection}, {"transport", transport_name(link.transport)}, {"peer", link.peer}, {"event", what}};
}

}  // namespace

RecordingWriter::RecordingWriter(const std::filesystem::path& file, const std::string& profile, TimePoint start)
    : out_(file, std::ios::binary | std::ios::trunc), start_(start) {
    if (!out_) throw config::ConfigError(file.string() + ": cannot write the recording; check the path given to --record");
    line(json{{"slmp_recording", 1}, {"started", utc_now()}, {"profile", profile}}.dump());
}

double RecordingWriter::ms(TimePoint at) const {
    return std::chrono::duration<double, std::milli>(at - start_).count();
}

// One line at a time and flushed, so a recording is whole up to the last
// request even when the simulator is killed.
void RecordingWriter::line(const std::string& text) {
    out_ << text << '\n';
    out_.flush();
}

void RecordingWriter::opened(TimePoint at, const RecordedLink& link) {
    line(event(ms(at), link, "open").dump());
}

void RecordingWriter::exchange(TimePoint at, const RecordedLink& link, std::span<const std::uint8_t> request,
                               const std::vector<std::uint8_t>* response, const std::vector<std::string>& faults,
                               const std::string& named) {
    auto e = event(ms(at), link, "exchange");
    e["request"] = to_hex(request);
    e["response"] = response ? json(to_hex(*response)) : json(nullptr);
    if (!faults.empty()) e["faults"] = faults;
    if (!named.empty()) e["named"] = named;
    line(e.dump());
}

void RecordingWriter::pushed(TimePoint at, const RecordedLink& link, const std::vector<std::uint8_t>& frame) {
    auto e = event(ms(at), link, "ondemand");
    e["response"] = to_hex(frame);
    line(e.dump());
}

// An "exchange" line with "protocol": replay and slmp-replay read SLMP lines only.
void RecordingWriter::frontend_exchange(TimePoint at, const RecordedLink& link, std::string_view protocol,
                                        std::string_view command, std::string_view code,
                                        std::span<const std::uint8_t> request, std::span<const std::uint8_t> response,
                                        bool answered, const std::vector<std::string>& faults) {
    auto e = event(ms(at), link, "exchange");
    e["protocol"] = protocol;
    e["command"] = command.empty() ? json(nullptr) : json(command);
    e["code"] = code.empty() ? json(nullptr) : json(code);
    e["request"] = to_hex(request);
    e["response"] = answered ? json(to_hex(response)) : json(nullptr);
    if (!faults.empty()) e["faults"] = faults;
    line(e.dump());
}

void RecordingWriter::closed(TimePoint at, const RecordedLink& link, const std::string& why) {
    auto e = event(ms(at), link, "close");
    e["why"] = why;
    line(e.dump());
}

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
