// The JSON-lines recording (--record FILE) as the station writes it, line by
// line as connections open, exchange and close; the format is
// scenarios/recording.hpp's, which reads it back for replay.
#pragma once

#include <filesystem>
#include <fstream>
#include <string>

#include "station/capture/recorder.hpp"

namespace slmp::station {

class RecordingWriter : public Recorder {
public:
    // Truncates `file`; throws config::ConfigError when it cannot be written.
    RecordingWriter(const std::filesystem::path& file, const std::string& profile, TimePoint start);

    void opened(TimePoint at, const RecordedLink& link) override;
    // {"event":"ondemand","response":"d000..."}: replay skips it (no request to match).
    void pushed(TimePoint at, const RecordedLink& link, const std::vector<std::uint8_t>& frame) override;
    void exchange(TimePoint at, const RecordedLink& link, std::span<const std::uint8_t> request,
                  const std::vector<std::uint8_t>* response, const std::vector<std::string>& faults,
                  const std::string& named) override;
    void closed(TimePoint at, const RecordedLink& link, const std::string& why) override;
    void frontend_exchange(TimePoint at, const RecordedLink& link, std::string_view protocol, std::string_view command,
                           std::string_view code, std::span<const std::uint8_t> request,
                           std::span<const std::uint8_t> response, bool answered,
                           const std::vector<std::string>& faults) override;

private:
    void line(const std::string& text);
    double ms(TimePoint at) const;

    std::ofstream out_;
    TimePoint start_;
};

}  // namespace slmp::station
