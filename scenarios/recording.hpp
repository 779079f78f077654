// Recordings of SLMP sessions as JSON lines (docs/scenarios.md "Record &
// replay"): the format and its reader, for replay and slmp-replay; the
// station writes them (station/capture/recording_writer.hpp). The first line describes the recording, then one line per event:
//   {"slmp_recording":1,"started":"2024-05-01T12:00:00.123Z","profile":"R08CPU"}
//   {"t_ms":1.25,"conn":2,"transport":"tcp","peer":"127.0.0.1:50312","event":"open"}
//   {"t_ms":3.5,"conn":2,"transport":"tcp","peer":"127.0.0.1:50312","event":"exchange",
//    "request":"500000ff…","response":"d00000ff…","faults":["slow"]}
//   {"t_ms":9.0,"conn":2,"transport":"tcp","peer":"127.0.0.1:50312","event":"close","why":"closed by the client"}
// Bytes are lower-case hex, exactly as they crossed the wire ("response": null
// when nothing was sent). A request and its response share one line, so a
// recording replays without guessing which answer belongs to which question.
#pragma once

#include <chrono>
#include <cstdint>
#include <filesystem>
#include <fstream>
#include <optional>
#include <span>
#include <string>
#include <vector>

#include "scenarios/scenario.hpp"

namespace slmp::scenarios {

struct RecordedExchange {
    double t_ms = 0;
    std::uint64_t connection = 0;
    Transport transport = Transport::Tcp;
    std::string peer;
    std::vector<std::uint8_t> request;
    std::optional<std::vector<std::uint8_t>> response;
};

struct Recording {
    std::string profile;
    std::vector<RecordedExchange> exchanges;   // in the order they happened
};

// Reads a recording; a bad line is a config::ConfigError naming file and line.
Recording read_recording(const std::filesystem::path& file);

std::string to_hex(std::span<const std::uint8_t> bytes);
std::optional<std::vector<std::uint8_t>> from_hex(std::string_view text);

}  // namespace slmp::scenarios
