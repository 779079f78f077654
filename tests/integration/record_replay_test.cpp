// Record a session, replay it as a scenario, run the same client requests,
// get byte-identical responses (docs/scenarios.md "Record & replay").
#include <catch2/catch.hpp>

#include <nlohmann/json.hpp>

#include "scenario_support.hpp"

using namespace slmp::test;
using namespace std::chrono_literals;
namespace client = slmp::protocol::client;

namespace {

// A client session: binary and ASCII, 3E and 4E, reads, a write, an error.
std::vector<Bytes> session() {
    Wire b4{FrameKind::E4, Codec::Binary, 0x0101};
    Wire a4{FrameKind::E4, Codec::Ascii, 0x0202};
    return {
        read_request(kBinary3E, "D100", 3),
        write_request(kBinary3E, "D100", {11, 22, 33}),
        read_request(kBinary3E, "D100", 3),
        read_request(kAscii3E, "D100", 3),
        read_request(b4, "D101", 2),
        read_request(a4, "M0", 1),
        client::read_type_name(kBinary3E.options()),
        read_request(kBinary3E, "D99999", 1),   // out of range: an error response is recorded too
    };
}

std::vector<Bytes> run_session(std::uint16_t port) {
    std::vector<Bytes> responses;
    TcpLink link(port);
    for (const auto& request : session()) responses.push_back(link.exchange(request));
    return responses;
}

}  // namespace

TEST_CASE("record and replay: the replayed simulator answers byte for byte as recorded", "[scenario][replay]") {
    TempDir dir;
    auto recording = dir.path() / "session.jsonl";
    std::vector<Bytes> recorded;
    {
        SimProcess sim(with_args({"--record", recording.string(), "--no-http"}));
        recorded = run_session(sim.tcp_port());
    }
    for (const auto& r : recorded) REQUIRE_FALSE(r.empty());

    auto lines = lines_of(read_text(recording));
    REQUIRE(lines.size() == 1 + 1 + session().size() + 1);   // header, open, exchanges, close
    auto exchange = nlohmann::json::parse(lines[2]);
    CHECK(exchange["event"] == "exchange");
    CHECK(exchange["request"] == "500000ffff03000c00100001040000640000a80300");

    // The replaying simulator starts with other values in D100: the answers
    // still come from the recording.
    dir.write("replay.json", R"({"replay": {"file": "session.jsonl", "on_miss": "end_code", "end_code": "C059"}})");
    SimOptions options;
    options.args = {"--scenario", (dir.path() / "replay.json").string(), "--no-http"};
    options.config_json = R"({"devices": {"D100": [9, 9, 9]}})";
    SimProcess replay(options);
    auto replayed = run_session(replay.tcp_port());
    REQUIRE(replayed.size() == recorded.size());
    for (std::size_t i = 0; i < recorded.size(); ++i) {
        INFO("request " << i << ": " << show(session()[i]));
        CHECK(show(replayed[i]) == show(recorded[i]));
    }
    // A request the recording does not hold gets the chosen end code.
    TcpLink link(replay.tcp_port());
    CHECK(show(link.exchange(read_request(kBinary3E, "D7"))) ==
          show(expected_response(kBinary3E, error_info(kBinary3E, 0x0401, 0x0000), 0xC059)));
}
