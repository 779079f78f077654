// A plant split over processes (docs/plants.md, "Shards"): four `--shard K/4`
// processes of one 1000-station file serve disjoint sets of stations whose
// union is the plant, the same ones on every start, each answering SLMP; every
// shard's GET /api/plant gives the same map of the whole plant.
#include <catch2/catch.hpp>

#include <map>
#include <memory>
#include <optional>
#include <set>

#include "frames.hpp"
#include "http_client.hpp"
#include "sim_process.hpp"
#include "sockets.hpp"

using namespace slmp::test;

namespace {

// Each test case on an address of its own, so the fixed ports 21001-22000
// clash with no other test, nor with the other case when ctest runs both at once.
constexpr const char* kAddress = "127.83.17.1";
constexpr const char* kRestartAddress = "127.83.17.2";
constexpr unsigned kStations = 1000;
constexpr unsigned kShards = 4;

std::string plant_file(const std::string& address) {
    return R"({"bind": ")" + address + R"(", "http": {"port": 0, "bind": "127.0.0.1"}, "threads": 1,
        "shards": 4, "stations": [{"template": {"profile": "R08CPU"}, "count": 1000, "name": "press-{i:04}",
                                   "tcp_port": "21000+i"}]})";
}

std::string press(unsigned i) {
    auto digits = std::to_string(i);
    return "press-" + std::string(4 - digits.size(), '0') + digits;
}

std::unique_ptr<SimProcess> start_shard(const std::string& shard, const std::string& address = kAddress) {
    SimOptions options;
    options.plant = true;
    options.config_json = plant_file(address);
    options.args = {"--shard", shard};
    return std::make_unique<SimProcess>(options);
}

// The stations a shard's ready file lists, in order.
std::vector<std::string> served(const SimProcess& sim) {
    std::vector<std::string> names;
    for (const auto& station : sim.ready()["stations"]) names.push_back(station["name"]);
    return names;
}

// 3E binary read of D100 (one word) and its answer, 0.
const Bytes kReadD100 = hex("500000FFFF03000C00100001040000640000A80100");
const Bytes kD100IsZero = hex("D00000FFFF0300040000000000");

}  // namespace

TEST_CASE("shards: 4 processes of a 1000-station file serve disjoint sets whose union is the plant, /api/plant agrees",
          "[plant][shard]") {
    std::vector<std::unique_ptr<SimProcess>> shards;
    for (unsigned k = 0; k < kShards; ++k) shards.push_back(start_shard(std::to_string(k) + "/4"));

    std::map<std::string, unsigned> shard_of;   // station -> the shard whose ready file lists it
    for (unsigned k = 0; k < kShards; ++k) {
        auto names = served(*shards[k]);
        CHECK(names.size() > kStations / kShards / 2);   // every shard has a share
        for (const auto& name : names) CHECK(shard_of.emplace(name, k).second);   // no station on two shards
    }
    REQUIRE(shard_of.size() == kStations);   // the union is the plant
    for (unsigned i = 1; i <= kStations; ++i) CHECK(shard_of.count(press(i)));

    // Every shard's map of the plant is the same and says who serves what.
    std::optional<nlohmann::json> first_map;
    for (unsigned k = 0; k < kShards; ++k) {
        auto answer = http_get(shards[k]->http_port(), "/api/plant");
        REQUIRE(answer.status == 200);
        auto map = answer.json();
        CHECK(map["shard"] == k);
        CHECK(map["shards"] == kShards);
        CHECK(map["station_count"] == kStations);
        map.erase("shard");
        if (!first_map) first_map = map;
        CHECK(map == *first_map);
    }
    const auto& stations = (*first_map)["stations"];
    REQUIRE(stations.size() == kStations);
    for (unsigned i = 1; i <= kStations; ++i) {
        const auto& entry = stations[i - 1];   // the file's order
        CHECK(entry["name"] == press(i));
        CHECK(entry["shard"] == shard_of[press(i)]);
        CHECK(entry["host"] == kAddress);
        CHECK(entry["tcp"] == nlohmann::json::array({21000 + i}));
    }
    auto one = http_get(shards[3]->http_port(), "/api/plant/stations/press-0421").json();
    CHECK(one == stations[420]);
    CHECK(http_get(shards[3]->http_port(), "/api/plant/stations/press-9999").status == 404);

    // Every station answers on its port, served by its shard.
    for (unsigned i = 1; i <= kStations; ++i) {
        INFO(press(i) << " on shard " << shard_of[press(i)]);
        auto client = TcpClient::open(static_cast<std::uint16_t>(21000 + i), kAddress);
        REQUIRE(client.send(kReadD100));
        Bytes frame;
        std::string why;
        REQUIRE(client.response(&frame, kReplyTimeout, &why));
        CHECK(frame == kD100IsZero);
    }

    // The overview of a shard, a page at a time: its own stations, in the file's order.
    auto mine = served(*shards[1]);
    auto page = http_get(shards[1]->http_port(), "/api/stations?offset=5&limit=10");
    REQUIRE(page.status == 200);
    CHECK(page.headers["x-total-count"] == std::to_string(mine.size()));
    REQUIRE(page.json().size() == 10);
    for (std::size_t n = 0; n < 10; ++n) CHECK(page.json()[n]["name"] == mine[5 + n]);
    auto filtered = http_get(shards[1]->http_port(), "/api/stations?filter=" + mine[7] + "&limit=1").json();
    REQUIRE(filtered.size() == 1);
    CHECK(filtered[0]["name"] == mine[7]);
    CHECK(http_get(shards[1]->http_port(), "/api/stations?limit=ten").status == 400);

    // /metrics by profile: one series set for the shard's R08CPUs, which all RUN.
    auto metrics = http_get(shards[1]->http_port(), "/metrics?by=profile").body;
    auto count = std::to_string(mine.size());
    CHECK_THAT(metrics, Catch::Contains("slmp_stations{profile=\"R08CPU\",state=\"RUN\"} " + count + "\n"));
    CHECK_THAT(metrics, Catch::Contains("slmp_info{profile=\"R08CPU\",type_name=\"R08CPU\"} " + count + "\n"));
    CHECK_THAT(metrics, Catch::Contains("slmp_connections_accepted_total{profile=\"R08CPU\"} " + count + "\n"));
    CHECK_THAT(metrics, !Catch::Contains("station=\""));
    // ... and by station (the default up to 1000 stations).
    CHECK_THAT(http_get(shards[1]->http_port(), "/metrics").body,
               Catch::Contains("slmp_connections_accepted_total{station=\"" + mine[0] + "\"} 1\n"));
}

TEST_CASE("shards: a shard serves the same stations on every start, --shard K takes N from the file's shards",
          "[plant][shard]") {
    std::vector<std::string> first;
    {
        auto shard = start_shard("2/4", kRestartAddress);
        first = served(*shard);
    }
    auto again = start_shard("2", kRestartAddress);
    CHECK(served(*again) == first);
    CHECK(http_get(again->http_port(), "/api/plant").json()["shards"] == kShards);

    TempDir dir;
    auto wrong = run_sim({"--config", dir.write("plant.json", plant_file(kRestartAddress)).string(), "--shard", "4/4"});
    CHECK(wrong.exit_code == 2);
    CHECK_THAT(wrong.err, Catch::Contains("--shard 4/4: shards are numbered 0 to 3"));
}
