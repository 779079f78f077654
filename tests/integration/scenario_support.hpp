// Starting the real slmp-sim with scenario files, for the scenario
// integration tests (docs/scenarios.md).
#pragma once

#include <chrono>
#include <memory>
#include <string>
#include <thread>
#include <vector>

#include "frames.hpp"
#include "sim_process.hpp"
#include "link.hpp"
#include "protocol/client_commands.hpp"
#include "sockets.hpp"

namespace slmp::test {

// A simulator running the scenarios given as JSON text (written to files in
// `dir`), with the HTTP API off so tests never share a port.
struct ScenarioSim {
    explicit ScenarioSim(std::vector<std::string> scenario_json, std::vector<std::string> extra = {},
                         std::string config_json = {}) {
        SimOptions options;
        for (std::size_t i = 0; i < scenario_json.size(); ++i) {
            auto file = dir.write("scenario" + std::to_string(i) + ".json", scenario_json[i]);
            options.args.insert(options.args.end(), {"--scenario", file.string()});
        }
        options.args.push_back("--no-http");
        options.args.insert(options.args.end(), extra.begin(), extra.end());
        options.config_json = std::move(config_json);
        sim = std::make_unique<SimProcess>(options);
    }
    TempDir dir;
    std::unique_ptr<SimProcess> sim;
};

inline const Wire kBinary3E{FrameKind::E3, Codec::Binary, 0};
inline const Wire kAscii3E{FrameKind::E3, Codec::Ascii, 0};

// 0401 word read of `points` words from `start` (e.g. "D100").
inline Bytes read_request(const Wire& w, const std::string& start, std::uint16_t points = 1) {
    return protocol::client::read_words(w.options(), addr(start), points);
}
inline Bytes write_request(const Wire& w, const std::string& start, std::vector<std::uint16_t> values) {
    return protocol::client::write_words(w.options(), addr(start), values);
}

// One word read over a connection; nullopt when no response arrived.
inline std::optional<std::uint16_t> read_word(TcpClient& client, const std::string& device) {
    if (!client.send(read_request(kBinary3E, device))) return std::nullopt;
    auto r = client.response();
    if (!r || r->end_code != 0 || r->data.size() != 2) return std::nullopt;
    return static_cast<std::uint16_t>(r->data[0] | r->data[1] << 8);
}

// Polls `device` until it equals `want` (the scenario runs on the simulator's
// clock, so the test waits for it rather than sleeping a fixed time).
inline bool wait_for_word(TcpClient& client, const std::string& device, std::uint16_t want,
                          std::chrono::milliseconds limit = std::chrono::seconds(10)) {
    auto deadline = std::chrono::steady_clock::now() + limit;
    while (std::chrono::steady_clock::now() < deadline) {
        if (read_word(client, device) == want) return true;
        std::this_thread::sleep_for(std::chrono::milliseconds(20));
    }
    return false;
}

inline std::chrono::milliseconds since(std::chrono::steady_clock::time_point start) {
    return std::chrono::duration_cast<std::chrono::milliseconds>(std::chrono::steady_clock::now() - start);
}

}  // namespace slmp::test
