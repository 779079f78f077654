// One busy station served by several threads (docs/plants.md, "Threads"):
// its TCP connections read and write on strands of their own while every
// request is served whole on the station's strand. Many clients hammer one
// station at once; a torn 960-word block, a lost write or a miscounted
// request fails the test. The sanitizer job runs it too; under
// ThreadSanitizer (scripts/test-tsan.sh) a data race fails it as well.
#include <catch2/catch.hpp>

#include <atomic>
#include <string>
#include <thread>
#include <vector>

#include <nlohmann/json.hpp>

#include "frames.hpp"
#include "http_client.hpp"
#include "link.hpp"
#include "sim_process.hpp"
#include "sockets.hpp"

using namespace slmp::test;
namespace client = slmp::protocol::client;

namespace {

constexpr int kClients = 8;
constexpr int kRounds = 150;
constexpr std::uint16_t kBlockWords = 960;   // the batch limit: the largest request a client can make

// What one client saw; judged on the main thread (Catch2 assertions are not thread-safe).
struct Seen {
    int failed_exchanges = 0;   // no response, or an end code other than 0000
    int torn_blocks = 0;        // a 960-word read mixing two writers' values
    int lost_writes = 0;        // its own word read back with another value
    std::string first_problem;
};

std::vector<std::uint16_t> words_of(const client::Response& response, std::size_t count) {
    auto reader = response.reader();
    std::vector<std::uint16_t> words;
    for (std::size_t k = 0; k < count; ++k) words.push_back(reader.u16("word"));
    return words;
}

// Client `c`: in each round writes its own word D(100 + c) and the shared
// block D5000–D5959 (every word the same value, unique to the client and
// round), then reads both back.
Seen hammer(std::uint16_t port, int c, const Wire& wire) {
    Seen seen;
    auto note = [&](int& counter, const std::string& what) {
        ++counter;
        if (seen.first_problem.empty()) seen.first_problem = "client " + std::to_string(c) + ": " + what;
    };
    TcpLink link(port);
    const auto opts = wire.options();
    const auto own = addr("D" + std::to_string(100 + c));
    const auto block = addr("D5000");
    auto exchange = [&](const Bytes& request) -> std::optional<client::Response> {
        auto bytes = link.exchange(request);
        auto response = client::parse_response(bytes);
        if (!response || response->end_code != 0) {
            note(seen.failed_exchanges, "no answer or an error to a request: " + show(bytes));
            return std::nullopt;
        }
        return response;
    };
    for (int round = 1; round <= kRounds; ++round) {
        const auto mine = static_cast<std::uint16_t>(round);
        const auto stamp = static_cast<std::uint16_t>((c << 12) | round);
        std::vector<std::uint16_t> one{mine};
        std::vector<std::uint16_t> whole(kBlockWords, stamp);
        if (!exchange(client::write_words(opts, own, one))) break;
        if (!exchange(client::write_words(opts, block, whole))) break;
        auto back = exchange(client::read_words(opts, own, 1));
        auto shared = exchange(client::read_words(opts, block, kBlockWords));
        if (!back || !shared) break;
        if (words_of(*back, 1)[0] != mine) note(seen.lost_writes, "D" + std::to_string(100 + c) + " lost round " + std::to_string(round));
        auto values = words_of(*shared, kBlockWords);
        for (auto v : values)
            if (v != values.front()) {
                note(seen.torn_blocks, "a torn block: " + std::to_string(values.front()) + " and " + std::to_string(v));
                break;
            }
    }
    return seen;
}

}  // namespace

TEST_CASE("threads: one station's connections on several threads keep every request whole and lose no write",
          "[threads]") {
    // More threads than this machine's cores: the most interleaving.
    SimProcess sim(with_args({"--threads", "4"}));
    CHECK(sim.ready()["threads"] == 4);
    const std::vector<Wire> wires = {{FrameKind::E3, Codec::Binary, 0}, {FrameKind::E4, Codec::Ascii, 0x0101}};
    std::vector<Seen> seen(kClients);
    {
        std::vector<std::thread> clients;
        for (int c = 0; c < kClients; ++c)
            clients.emplace_back([&, c] { seen[c] = hammer(sim.tcp_port(), c, wires[c % wires.size()]); });
        for (auto& t : clients) t.join();
    }
    for (int c = 0; c < kClients; ++c) {
        INFO(seen[c].first_problem);
        CHECK(seen[c].failed_exchanges == 0);
        CHECK(seen[c].torn_blocks == 0);
        CHECK(seen[c].lost_writes == 0);
    }

    // Each client's last value stands, and the station counted every request once.
    TcpLink link(sim.tcp_port());
    const Wire w{FrameKind::E3, Codec::Binary, 0};
    auto finals = client::parse_response(link.exchange(client::read_words(w.options(), addr("D100"), kClients)));
    REQUIRE(finals);
    auto reader = finals->reader();
    for (int c = 0; c < kClients; ++c) CHECK(reader.u16("word") == kRounds);
    auto stations = nlohmann::json::parse(http_get(sim.http_port(), "/api/stations").body);
    CHECK(stations[0]["requests"] == kClients * kRounds * 4 + 1);
}
