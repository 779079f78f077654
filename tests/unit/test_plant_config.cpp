// A plant's configuration: defaults, stations, templates and their
// placeholders, port expressions, the checks that name the station and the fix
// (docs/plants.md).
#include "support/fixtures.hpp"

#include "config/plant_config.hpp"
#include "control/endpoints/station_side.hpp"

using namespace slmp;
using config::parse_plant_config;

namespace {

config::PlantConfig plant(const std::string& text) { return parse_plant_config(text, "plant.json", "/etc/plants"); }

}  // namespace

TEST_CASE("a file without stations is one station, as before plants", "[plant]") {
    auto p = plant(R"({"profile": "Q26UDEHCPU", "ports": [{"transport": "tcp", "port": 6000}], "threads": 2})");
    CHECK_FALSE(p.plant);
    CHECK(p.threads == 2);
    REQUIRE(p.stations.size() == 1);
    CHECK(p.stations[0].server.profile == "Q26UDEHCPU");
    CHECK(p.stations[0].server.name.empty());
    REQUIRE(p.stations[0].server.ports.size() == 1);
    CHECK(p.stations[0].server.ports[0].port == 6000);
}

TEST_CASE("top-level keys are every station's defaults, a station's own key replaces the default whole", "[plant]") {
    auto p = plant(R"({"profile": "R08CPU", "bind": "127.0.0.1", "devices": {"D0": 1},
        "stations": [{"name": "press-1", "tcp_port": 20001},
                     {"name": "press-2", "profile": "R04CPU", "tcp_port": 20002, "udp_port": 21002, "devices": {"D1": 2}}]})");
    CHECK(p.plant);
    REQUIRE(p.stations.size() == 2);
    const auto& a = p.stations[0].server;
    const auto& b = p.stations[1].server;
    CHECK(a.name == "press-1");
    CHECK(a.profile == "R08CPU");
    CHECK(b.profile == "R04CPU");
    CHECK(a.bind == "127.0.0.1");
    REQUIRE(a.ports.size() == 1);   // tcp_port alone: TCP only
    CHECK(a.ports[0].transport == config::Transport::Tcp);
    CHECK(a.ports[0].port == 20001);
    REQUIRE(b.ports.size() == 2);
    CHECK(b.ports[1].transport == config::Transport::Udp);
    CHECK(b.ports[1].port == 21002);
    REQUIRE(a.devices.size() == 1);
    CHECK(devicemodel::format_address(a.devices[0].address) == "D0");
    REQUIRE(b.devices.size() == 1);
    CHECK(devicemodel::format_address(b.devices[0].address) == "D1");
}

TEST_CASE("a template expands to count stations with placeholders and port expressions", "[plant]") {
    auto p = plant(R"({"stations": [
        {"template": {"profile": "R08CPU", "devices": {"D0": 7}}, "count": 3, "first": 8,
         "name": "press-{i:03}", "tcp_port": "20000+2*i", "bind": "127.0.1.{i}"}
    ]})");
    REQUIRE(p.stations.size() == 3);
    CHECK(p.stations[0].server.name == "press-008");
    CHECK(p.stations[2].server.name == "press-010");
    CHECK(p.stations[1].server.bind == "127.0.1.9");
    CHECK(p.stations[1].server.ports[0].port == 20018);
    CHECK(p.stations[2].server.devices.size() == 1);
}

TEST_CASE("the issue's minimal template: 500 stations named press-{i} on 20000+i", "[plant]") {
    auto p = plant(R"({"stations": [{"template": {"profile": "R08CPU"}, "count": 500, "tcp_port": "20000+i", "name": "press-{i}"}]})");
    REQUIRE(p.stations.size() == 500);
    CHECK(p.stations[499].server.name == "press-500");
    CHECK(p.stations[499].server.ports.size() == 1);
    CHECK(p.stations[499].server.ports[0].port == 20500);
}

TEST_CASE("placeholders and index expressions", "[plant]") {
    CHECK(config::expand_placeholders("a{i}b{i+100}c{i:04}d{2*i-1}", 7, "w") == "a7b107c0007d13");
    long v = 0;
    CHECK(config::evaluate_index_expression("20000 + 2*(i+1)", 4, &v));
    CHECK(v == 20010);
    CHECK_FALSE(config::evaluate_index_expression("20000+j", 4, &v));
    CHECK_FALSE(config::evaluate_index_expression("", 4, &v));
    CHECK_THROWS_WITH(config::expand_placeholders("x{j}", 1, "plant.json: /stations/0"),
                      Catch::Contains("plant.json: /stations/0") && Catch::Contains("write {i}"));
}

TEST_CASE("a plant's state directory gives each station its own folder", "[plant]") {
    auto p = plant(R"({"state_dir": "/var/lib/plant", "stations": [{"name": "a", "tcp_port": 1}, {"name": "b", "tcp_port": 2, "state_dir": "/b"}]})");
    CHECK(p.stations[0].server.persistence.state_dir == "/var/lib/plant/a");
    CHECK(p.stations[1].server.persistence.state_dir == "/b");
}

TEST_CASE("scenarios in the file are relative to the file's folder", "[plant]") {
    auto p = plant(R"({"stations": [{"name": "a", "scenarios": ["conveyor.json", "/abs/x.json"]}]})");
    CHECK(p.stations[0].server.scenarios == std::vector<std::string>{"/etc/plants/conveyor.json", "/abs/x.json"});
}

TEST_CASE("plant mistakes name the station, the key and the fix", "[plant]") {
    CHECK_THROWS_WITH(plant(R"({"stations": [{"name": "a"}, {"name": "a", "tcp_port": 2}]})"),
                      Catch::Contains("the name 'a' is taken"));
    CHECK_THROWS_WITH(plant(R"({"stations": [{"name": "a"}, {"name": "b"}]})"),
                      Catch::Contains("stations 'a' and 'b' both listen on 0.0.0.0 TCP 5000") &&
                          Catch::Contains("\"tcp_port\": \"20000+i\""));
    CHECK_THROWS_WITH(plant(R"({"stations": [{"name": "a", "http": {"port": 1}}]})"),
                      Catch::Contains("\"http\" is plant-wide; move it to the top level"));
    CHECK_THROWS_WITH(plant(R"({"stations": [{"name": "a b"}]})"),
                      Catch::Contains("station name 'a b'") && Catch::Contains("letters, digits"));
    CHECK_THROWS_WITH(plant(R"({"stations": [{"name": "a", "profile": "R08CPU", "prfile": 1}]})"),
                      Catch::Contains("plant.json, station 'a': /prfile: unknown key"));
    CHECK_THROWS_WITH(plant(R"({"stations": [{"template": {}, "count": 2, "tcp_port": "65535+i"}]})"),
                      Catch::Contains("gives port 65536 for i = 1"));
    CHECK_THROWS_WITH(plant(R"({"stations": [{"name": "a", "tcp_port": "20000+i"}]})"),
                      Catch::Contains("needs a template entry"));
    CHECK_THROWS_WITH(plant(R"({"stations": []})"), Catch::Contains("no stations"));
    CHECK_THROWS_WITH(plant(R"({"threads": 0})"), Catch::Contains("/threads: must be at least 1"));
    CHECK_THROWS_WITH(plant(R"({"ports": [], "tcp_port": 1})"), Catch::Contains("both given"));
}

TEST_CASE("unnamed stations are station-N, a non-MELSEC station drops the default SLMP ports", "[plant]") {
    auto p = plant(R"({"ports": [{"transport": "tcp", "port": 5000}], "stations": [{}, {"kind": "ladder-motion", "hostlink": {"tcp_port": 0}}]})");
    CHECK(p.stations[0].server.name == "station-1");
    CHECK(p.stations[1].server.name == "station-2");
    CHECK(p.stations[1].server.ports.empty());
}

TEST_CASE("a plant's metrics: one HELP/TYPE per family, a station label on every sample", "[plant][metrics]") {
    std::string a = "# HELP m_total Help.\n# TYPE m_total counter\nm_total{x=\"1\"} 3\n"
                    "# HELP h Help h.\n# TYPE h histogram\nh_bucket{le=\"+Inf\"} 1\nh_sum 0.5\nh_count 1\n";
    std::string b = "# HELP m_total Help.\n# TYPE m_total counter\nm_total{x=\"2\"} 4\n"
                    "# HELP h Help h.\n# TYPE h histogram\nh_bucket{le=\"+Inf\"} 2\nh_sum 1\nh_count 2\n";
    CHECK(control::merge_metrics({{"p1", a}, {"p2", b}}) ==
          "# HELP m_total Help.\n# TYPE m_total counter\n"
          "m_total{station=\"p1\",x=\"1\"} 3\nm_total{station=\"p2\",x=\"2\"} 4\n"
          "# HELP h Help h.\n# TYPE h histogram\n"
          "h_bucket{station=\"p1\",le=\"+Inf\"} 1\nh_sum{station=\"p1\"} 0.5\nh_count{station=\"p1\"} 1\n"
          "h_bucket{station=\"p2\",le=\"+Inf\"} 2\nh_sum{station=\"p2\"} 1\nh_count{station=\"p2\"} 2\n");
}

TEST_CASE("redundant pairs and multidrop stations name stations of the plant", "[plant][redundant][multidrop]") {
    auto p = plant(R"({"stations": [{"name": "a", "tcp_port": 1, "redundant": {"pair": "b", "switchover_ms": 50}},
        {"name": "b", "tcp_port": 2, "redundant": {"pair": "a", "system": "B"}},
        {"name": "d", "tcp_port": 3, "multidrop": {"via": "a", "start_io": "0040", "number": 31}}]})");
    REQUIRE(p.stations[0].server.redundant);
    CHECK(p.stations[0].server.redundant->system == 'A');
    CHECK(p.stations[0].server.redundant->switchover_ms == 50);
    CHECK(p.stations[1].server.redundant->system == 'B');
    REQUIRE(p.stations[2].server.multidrop);
    CHECK(p.stations[2].server.multidrop->module_io == 0x0004);
    CHECK(p.stations[2].server.multidrop->number == 31);

    CHECK_THROWS_WITH(plant(R"({"stations": [{"name": "a", "redundant": {"pair": "x"}}]})"),
                      Catch::Contains("station 'a': /redundant/pair: no station is named 'x'"));
    CHECK_THROWS_WITH(plant(R"({"stations": [{"name": "a", "redundant": {"pair": "a"}}]})"),
                      Catch::Contains("cannot pair with itself"));
    CHECK_THROWS_WITH(plant(R"({"stations": [{"name": "a", "tcp_port": 1, "redundant": {"pair": "b"}},
        {"name": "b", "tcp_port": 2, "redundant": {"pair": "a"}}]})"),
                      Catch::Contains("are both system A"));
    CHECK_THROWS_WITH(plant(R"({"stations": [{"name": "a", "tcp_port": 1, "redundant": {"pair": "b"}},
        {"name": "b", "tcp_port": 2}, {"name": "c", "tcp_port": 3, "redundant": {"pair": "b", "system": "B"}}]})"),
                      Catch::Contains("a CPU is in one pair"));
    CHECK_THROWS_WITH(plant(R"({"stations": [{"name": "a", "redundant": {"pair": "b", "system": "C"}}]})"),
                      Catch::Contains("/redundant/system: unknown system 'C'"));
    CHECK_THROWS_WITH(plant(R"({"stations": [{"name": "d", "multidrop": {"via": "nobody", "start_io": "0040", "number": 1}}]})"),
                      Catch::Contains("/multidrop/via: no station is named 'nobody'"));
    CHECK_THROWS_WITH(plant(R"({"stations": [{"name": "d", "multidrop": {"via": "x", "start_io": "0040", "number": 32}}]})"),
                      Catch::Contains("/multidrop/number"));
    CHECK_THROWS_WITH(plant(R"({"stations": [{"name": "d", "multidrop": {"via": "x", "start_io": "2000", "number": 1}}]})"),
                      Catch::Contains("at most 1FF0"));

}

TEST_CASE("a redundant pair's tracked ranges", "[plant][redundant][tracking]") {
    auto p = plant(R"({"stations": [{"name": "a", "tcp_port": 1, "redundant": {"pair": "b", "tracking": ["D0-D99", "M16-M47", "TN"]}},
        {"name": "b", "tcp_port": 2, "redundant": {"pair": "a", "system": "B"}}]})");
    const auto& tracking = p.stations[0].server.redundant->tracking;
    REQUIRE(tracking);
    REQUIRE(tracking->size() == 3);
    CHECK((*tracking)[0].spec->symbol == "D");
    CHECK((*tracking)[0].count == 100);
    CHECK((*tracking)[1].first == 16);
    CHECK((*tracking)[1].count == 32);
    CHECK((*tracking)[2].spec->symbol == "TN");
    CHECK_FALSE(p.stations[1].server.redundant->tracking);   // the pair takes a's

    const auto with = [](const std::string& tracking) {
        return plant(R"({"stations": [{"name": "a", "redundant": {"pair": "b", "tracking": )" + tracking + "}}]}");
    };
    CHECK_THROWS_WITH(with(R"(["M3-M10"])"), Catch::Contains("is not whole words of M"));
    CHECK_THROWS_WITH(with(R"(["SD0-SD9"])"), Catch::Contains("SM and SD are each CPU's own"));
    CHECK_THROWS_WITH(with(R"(["SM"])"), Catch::Contains("SM and SD are each CPU's own"));
    CHECK_THROWS_WITH(with(R"(["D9-D0"])"), Catch::Contains("is not a range of devices"));
    CHECK_THROWS_WITH(with(R"(["Q"])"), Catch::Contains("is no device"));
    CHECK_THROWS_WITH(with(R"("D0-D9")"), Catch::Contains("/redundant/tracking"));
    CHECK_THROWS_WITH(plant(R"({"stations": [{"name": "a", "tcp_port": 1, "redundant": {"pair": "b", "tracking": ["D0-D9"]}},
        {"name": "b", "tcp_port": 2, "redundant": {"pair": "a", "system": "B", "tracking": ["D0-D19"]}}]})"),
                      Catch::Contains("track different ranges"));
}
