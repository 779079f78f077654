// Shards of a plant (config/shard.hpp, docs/plants.md "Shards"): which process
// serves which station, by rendezvous hashing of the names; the --shard option;
// the per-profile sums of a large plant's /metrics.
#include "support/fixtures.hpp"

#include <map>
#include <set>

#include "config/config_error.hpp"
#include "config/plant_config.hpp"
#include "config/shard.hpp"
#include "control/observers/metrics.hpp"

using namespace slmp;
using config::shard_of;

namespace {

std::string press(unsigned i) {
    auto digits = std::to_string(i);
    return "press-" + std::string(4 - std::min<std::size_t>(4, digits.size()), '0') + digits;
}

config::PlantConfig plant(const std::string& text) { return config::parse_plant_config(text, "plant.json", "/etc/plants"); }

}  // namespace

TEST_CASE("a station's shard is a fixed function of its name and N (the generator computes the same)", "[shard]") {
    // Pinned: a change here moves stations between the pods of every deployed
    // plant, and deploy/k8s/render_shards.py must change with it.
    CHECK(shard_of("press-0001", 4) == 2);
    CHECK(shard_of("press-0421", 4) == 3);
    CHECK(shard_of("oven-1", 4) == 1);
    CHECK(shard_of("packer", 4) == 3);
    CHECK(shard_of("press-0001", 10) == 6);
    CHECK(shard_of("press-0421", 10) == 4);
    CHECK(shard_of("oven-1", 10) == 8);
    CHECK(shard_of("packer", 10) == 3);
    CHECK(shard_of("anything", 1) == 0);
}

TEST_CASE("1000 stations over 4 shards: every shard a fair share, one more shard moves only what it takes", "[shard]") {
    std::map<unsigned, unsigned> sizes;
    unsigned moved = 0;
    for (unsigned i = 1; i <= 1000; ++i) {
        auto four = shard_of(press(i), 4), five = shard_of(press(i), 5);
        ++sizes[four];
        if (five != four) {
            ++moved;
            CHECK(five == 4);   // a station that moves goes to the new shard, never between old ones
        }
    }
    REQUIRE(sizes.size() == 4);
    for (auto [shard, size] : sizes) CHECK((size >= 200 && size <= 300));
    CHECK((moved >= 150 && moved <= 250));   // about 1000 / 5
}

TEST_CASE("the shard option: K/N, K, auto and auto/N, the pod ordinal from the host name", "[shard]") {
    auto both = config::parse_shard_option("3/10");
    CHECK(both.index == 3u);
    CHECK(both.count == 10u);
    auto index = config::parse_shard_option("2");
    CHECK(index.index == 2u);
    CHECK_FALSE(index.count);
    auto automatic = config::parse_shard_option("auto/4");
    CHECK_FALSE(automatic.index);
    CHECK(automatic.count == 4u);
    CHECK_THROWS_WITH(config::parse_shard_option("x/4"), Catch::Contains("write --shard K/N"));
    CHECK_THROWS_WITH(config::parse_shard_option("1/0"), Catch::Contains("at least 1 shard"));
    CHECK(config::ordinal_of_host_name("slmp-plant-7") == 7);
    CHECK(config::ordinal_of_host_name("line-3-plant-12") == 12);
    CHECK_THROWS_WITH(config::ordinal_of_host_name("build-vm"), Catch::Contains("--shard K/N"));
    CHECK(config::shard_host("slmp-plant-{shard}.slmp-plant", 4) == "slmp-plant-4.slmp-plant");
}

TEST_CASE("select_shard keeps the shard's stations and maps the whole plant, it refuses port 0 and an empty shard",
          "[shard]") {
    const std::string file = R"({"bind": "127.0.0.1", "shards": 4, "shard_host": "p-{shard}.p",
        "stations": [{"template": {}, "count": 40, "name": "press-{i:04}", "tcp_port": "20000+i"}]})";
    std::set<std::string> union_of_shards;
    for (unsigned k = 0; k < 4; ++k) {
        auto p = plant(file);
        CHECK(p.layout.file_count == 4);
        CHECK(p.layout.host_pattern == "p-{shard}.p");
        config::select_shard(p, k, 4);
        REQUIRE(p.layout.stations.size() == 40);
        for (const auto& station : p.stations) {
            CHECK(shard_of(station.server.name, 4) == k);
            CHECK(union_of_shards.insert(station.server.name).second);   // disjoint
        }
        CHECK(p.layout.stations[19].name == "press-0020");   // the file's order
        CHECK(p.layout.stations[19].tcp == std::vector<std::uint16_t>{20020});
    }
    CHECK(union_of_shards.size() == 40);

    auto any_port = plant(R"({"stations": [{"template": {}, "count": 4, "name": "s{i}", "tcp_port": 0}]})");
    CHECK_THROWS_WITH(config::select_shard(any_port, 0, 2), Catch::Contains("give each station a fixed port"));
    auto one = plant(R"({"stations": [{"name": "press-0421", "tcp_port": 20421}]})");
    CHECK_THROWS_WITH(config::select_shard(one, shard_of("press-0421", 4) == 0 ? 1 : 0, 4),
                      Catch::Contains("serves none of the 1 stations; use fewer shards"));
    CHECK_THROWS_WITH(plant(R"({"shards": 0, "stations": [{"name": "a"}]})"), Catch::Contains("1 to 1000 shards"));
    CHECK_THROWS_WITH(plant(R"({"stations": [{"name": "a", "shards": 2}]})"), Catch::Contains("plant-wide"));
}

TEST_CASE("a plant's metrics by profile: sums per profile, the CPU states counted, non-additive gauges left out",
          "[shard][metrics]") {
    auto station = [](const std::string& profile, int requests, int state, double seconds) {
        return "# HELP slmp_info I.\n# TYPE slmp_info gauge\nslmp_info{profile=\"" + profile + "\"} 1\n"
               "# HELP slmp_requests_total R.\n# TYPE slmp_requests_total counter\n"
               "slmp_requests_total{transport=\"tcp\"} " + std::to_string(requests) + "\n"
               "# HELP h H.\n# TYPE h histogram\nh_sum " + std::to_string(seconds) + "\nh_count 1\n"
               "# HELP slmp_cpu_state S.\n# TYPE slmp_cpu_state gauge\nslmp_cpu_state " + std::to_string(state) + "\n";
    };
    CHECK(control::sum_metrics({{"R08CPU", station("R08CPU", 3, 0, 0.25)},
                               {"R08CPU", station("R08CPU", 4, 2, 0.5)},
                               {"Q03UDVCPU", station("Q03UDVCPU", 1, 0, 1)}}) ==
          "# HELP slmp_info I.\n# TYPE slmp_info gauge\n"
          "slmp_info{profile=\"R08CPU\"} 2\nslmp_info{profile=\"Q03UDVCPU\"} 1\n"   // the stations of each profile
          "# HELP slmp_requests_total R.\n# TYPE slmp_requests_total counter\n"
          "slmp_requests_total{profile=\"R08CPU\",transport=\"tcp\"} 7\n"
          "slmp_requests_total{profile=\"Q03UDVCPU\",transport=\"tcp\"} 1\n"
          "# HELP h H.\n# TYPE h histogram\n"
          "h_sum{profile=\"R08CPU\"} 0.75\nh_count{profile=\"R08CPU\"} 2\n"
          "h_sum{profile=\"Q03UDVCPU\"} 1\nh_count{profile=\"Q03UDVCPU\"} 1\n"
          "# HELP slmp_stations Stations of each profile in each operating state (the plant's /metrics by profile).\n"
          "# TYPE slmp_stations gauge\n"
          "slmp_stations{profile=\"Q03UDVCPU\",state=\"RUN\"} 1\n"
          "slmp_stations{profile=\"R08CPU\",state=\"RUN\"} 1\n"
          "slmp_stations{profile=\"R08CPU\",state=\"STOP\"} 1\n");
}
