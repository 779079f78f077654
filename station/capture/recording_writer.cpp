#include "station/capture/recording_writer.hpp"

#include <cstdio>
#include <ctime>

#include <nlohmann/json.hpp>

#include "config/config_error.hpp"
#include "scenarios/recording.hpp"

namespace slmp::station {

using nlohmann::json;
using scenarios::to_hex;

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

}  // namespace slmp::station
