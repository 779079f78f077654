// A plant: many stations in one process on several threads, each its own CPU
// on its own ports or bind address, reached over SLMP and over
// /api/stations/{name}/... (docs/plants.md).
#include <catch2/catch.hpp>

#include <netinet/in.h>

#include <atomic>
#include <thread>

#include "cli_support.hpp"
#include "frames.hpp"
#include "http_client.hpp"
#include "plant_ports.hpp"
#include "sim_process.hpp"
#include "sockets.hpp"

using namespace slmp::test;

namespace {

// 3E binary, own station: write D100 = value; read D100; read the type name (0101).
Bytes write_d100(std::uint16_t value) {
    return hex("500000FFFF03000E00100001140000640000A80100" + hex_digits(value & 0xFF, 2) + hex_digits(value >> 8, 2));
}
const Bytes kReadD100 = hex("500000FFFF03000C00100001040000640000A80100");
const Bytes kWriteOk = hex("D00000FFFF030002000000");
Bytes read_answer(std::uint16_t value) {
    return hex("D00000FFFF0300040000" "00" + hex_digits(value & 0xFF, 2) + hex_digits(value >> 8, 2));
}

Bytes ask(TcpClient& client, const Bytes& request) {
    REQUIRE(client.send(request));
    Bytes frame;
    std::string why;
    REQUIRE(client.response(&frame, kReplyTimeout, &why));
    return frame;
}

// A port free on 127.0.1.1 now, for stations that share one port on many addresses.
std::uint16_t free_port_on_127_0_1_1() {
    int fd = ::socket(AF_INET, SOCK_STREAM, 0);
    auto addr = loopback(0, "127.0.1.1");
    REQUIRE(::bind(fd, reinterpret_cast<sockaddr*>(&addr), sizeof addr) == 0);
    socklen_t len = sizeof addr;
    ::getsockname(fd, reinterpret_cast<sockaddr*>(&addr), &len);
    ::close(fd);
    return ntohs(addr.sin_port);
}

}  // namespace

TEST_CASE("plant: stations on two threads keep their own memory, identity and HTTP routes", "[plant]") {
    SimProcess sim(plant_options(R"({"bind": "127.0.0.1", "http": {"port": 0},
        "stations": [{"template": {"profile": "R08CPU"}, "count": 3, "name": "press-{i}", "tcp_port": 0, "udp_port": 0},
                     {"name": "packer", "profile": "R04CPU", "tcp_port": 0}]})",
                                 {"--threads", "2"}));
    REQUIRE(sim.ready()["stations"].size() == 4);
    CHECK(sim.ready()["threads"] == 2);

    auto press1 = TcpClient::open(tcp_of(sim, "press-1"));
    auto press2 = TcpClient::open(tcp_of(sim, "press-2"));   // on the other thread
    CHECK(show(ask(press1, write_d100(0x1234))) == show(kWriteOk));
    CHECK(show(ask(press1, kReadD100)) == show(read_answer(0x1234)));
    CHECK(show(ask(press2, kReadD100)) == show(read_answer(0)));

    // UDP reaches press-3's own CPU.
    UdpClient udp;
    REQUIRE(udp.send_to(station_in(sim, "press-3")["udp"][0].get<std::uint16_t>(), write_d100(7)));
    auto answer = udp.receive();
    REQUIRE(answer);
    CHECK(show(*answer) == show(kWriteOk));

    // The packer answers 0101 with its own type name.
    auto packer = TcpClient::open(tcp_of(sim, "packer"));
    auto type = ask(packer, hex("500000FFFF03000600100001010000"));
    REQUIRE(type.size() == 11 + 16 + 2);
    CHECK(std::string(type.begin() + 11, type.begin() + 17) == "R04CPU");

    // HTTP: the station's routes under /api/stations/{name}; the plain routes are the first station's.
    auto d100 = nlohmann::json::parse(http_get(sim.http_port(), "/api/stations/press-3/devices/D100").body);
    CHECK(d100["values"][0] == 7);
    CHECK(nlohmann::json::parse(http_get(sim.http_port(), "/api/devices/D100").body)["values"][0] == 0x1234);
    auto put = http_put(sim.http_port(), "/api/stations/press-2/devices/D100", R"({"values": [42]})");
    CHECK(put.status == 200);
    CHECK(show(ask(press2, kReadD100)) == show(read_answer(42)));
    CHECK(http_get(sim.http_port(), "/api/stations/nope/devices/D100").status == 404);

    auto list = nlohmann::json::parse(http_get(sim.http_port(), "/api/stations").body);
    REQUIRE(list.size() == 4);
    CHECK(list[3]["name"] == "packer");
    CHECK(list[3]["type_name"] == "R04CPU");
    CHECK(list[0]["state"] == "RUN");
    CHECK(list[0]["requests"] == 2);
    CHECK(list[1]["connections"] == 1);
    auto filtered = nlohmann::json::parse(http_get(sim.http_port(), "/api/stations?filter=press").body);
    CHECK(filtered.size() == 3);
    CHECK(nlohmann::json::parse(http_get(sim.http_port(), "/api/stations/packer").body)["profile"] == "R04CPU");

    CHECK(http_get(sim.http_port(), "/healthz").status == 200);
    auto ready = http_get(sim.http_port(), "/readyz");
    CHECK(ready.status == 200);
    CHECK(nlohmann::json::parse(ready.body) == nlohmann::json{{"ready", true}, {"stations", 4}});

    // One exposition for the plant: every sample carries its station.
    auto metrics = http_get(sim.http_port(), "/metrics").body;
    CHECK(metrics.find("slmp_info{station=\"packer\",profile=\"R04CPU\"") != std::string::npos);
    CHECK(metrics.find("slmp_requests_total{station=\"press-1\",transport=\"tcp\",command=\"1401\"") != std::string::npos);
    CHECK(metrics.find("# TYPE slmp_requests_total counter") == metrics.rfind("# TYPE slmp_requests_total counter"));
    auto own = http_get(sim.http_port(), "/api/stations/press-1/metrics").body;
    CHECK(own.find("slmp_info{profile=\"R08CPU\"") != std::string::npos);

    // A fault posted to press-2 acts on press-2 only.
    auto posted = http(sim.http_port(), "POST", "/api/stations/press-2/scenarios",
                       R"({"name": "sick", "faults": [{"do": "end_code", "end_code": "C051"}]})");
    CHECK(posted.status == 201);
    CHECK(show(ask(press2, kReadD100)) == show(hex("D00000FFFF03000B0051C000FFFF030001040000")));
    CHECK(show(ask(press1, kReadD100)) == show(read_answer(0x1234)));
}

TEST_CASE("plant: a wait on a station of another thread is answered by an SLMP write to it", "[plant]") {
    SimProcess sim(plant_options(R"({"bind": "127.0.0.1", "http": {"port": 0},
        "stations": [{"template": {}, "count": 2, "name": "s{i}", "tcp_port": 0}]})",
                                 {"--threads", "2"}));
    // The wait is sent first and answered only after the write.
    auto waiter = TcpClient::open(sim.http_port());
    REQUIRE(waiter.send("GET /api/stations/s2/devices/D100/wait?equals=9&timeout_ms=10000 HTTP/1.1\r\nHost: x\r\n"
                        "Connection: close\r\n\r\n"));
    auto s2 = TcpClient::open(tcp_of(sim, "s2"));
    // The wait is registered when its answer is still missing after a round trip on s2's thread.
    CHECK(show(ask(s2, kReadD100)) == show(read_answer(0)));
    CHECK(show(ask(s2, write_d100(9))) == show(kWriteOk));
    std::string data;
    for (;;) {
        auto got = waiter.recv_some(kReplyTimeout);
        if (got.status != RecvStatus::Data) break;
        data.append(got.data.begin(), got.data.end());
    }
    CHECK(data.find("200 OK") != std::string::npos);
    CHECK(data.find("\"value\":9") != std::string::npos);
}

TEST_CASE("plant: stations on one port and many loopback addresses", "[plant]") {
    auto port = free_port_on_127_0_1_1();
    auto config = R"({"http": {"port": 0, "bind": "127.0.0.1"}, "stations": [{"template": {"profile": "R08CPU"},
        "count": 5, "name": "line-{i}", "bind": "127.0.1.{i}", "tcp_port": )" + std::to_string(port) + "}]}";
    SimProcess sim(plant_options(config));
    for (int i = 1; i <= 5; ++i) {
        auto address = "127.0.1." + std::to_string(i);
        auto client = TcpClient::open(port, address.c_str());
        CHECK(show(ask(client, write_d100(static_cast<std::uint16_t>(100 + i)))) == show(kWriteOk));
    }
    for (int i = 1; i <= 5; ++i) {
        auto body = http_get(sim.http_port(), "/api/stations/line-" + std::to_string(i) + "/devices/D100").body;
        CHECK(nlohmann::json::parse(body)["values"][0] == 100 + i);
    }
}

TEST_CASE("plant: one-station options are refused, --check-config checks every station", "[plant]") {
    TempDir dir;
    auto file = dir.write("plant.json", R"({"stations": [{"name": "a", "tcp_port": 0}, {"name": "b", "profile": "R99CPU", "tcp_port": 0}]})");
    auto refused = run_sim({"--config", file.string(), "--tcp-port", "5000"});
    CHECK(refused.exit_code == 2);
    CHECK(refused.err.find("--tcp-port sets one station") != std::string::npos);
    auto checked = run_sim({"--check-config", file.string()});
    CHECK(checked.exit_code == 2);
    CHECK(checked.err.find("station 'b': ") != std::string::npos);
    CHECK(checked.err.find("R99CPU") != std::string::npos);
    auto good = dir.write("good.json", R"({"stations": [{"template": {}, "count": 50, "tcp_port": "20000+i"}]})");
    auto ok = run_sim({"--check-config", good.string()});
    CHECK(ok.exit_code == 0);
    CHECK(ok.out.find("configuration OK") != std::string::npos);
}

TEST_CASE("plant: a lone station's ready file and routes are as before plants", "[plant]") {
    SimProcess sim;
    CHECK_FALSE(sim.ready().contains("stations"));
    // --threads defaults to the machine's cores, also for one station (its
    // connections are served by all of them).
    CHECK(sim.ready()["threads"] == std::max(1u, std::thread::hardware_concurrency()));
    CHECK(http_get(sim.http_port(), "/healthz").status == 200);
    auto list = nlohmann::json::parse(http_get(sim.http_port(), "/api/stations").body);
    REQUIRE(list.size() == 1);
    CHECK(list[0]["name"] == "");
    auto metrics = http_get(sim.http_port(), "/metrics").body;
    CHECK(metrics.find("station=") == std::string::npos);
}

TEST_CASE("plant: the slmp CLI names a station and finds its port through the HTTP API", "[plant][cli]") {
    SimProcess sim(plant_options(R"({"bind": "127.0.0.1", "http": {"port": 0},
        "stations": [{"template": {}, "count": 3, "name": "p{i}", "tcp_port": 0, "udp_port": 0}]})"));
    auto api = std::to_string(sim.http_port());
    auto wrote = run_cli({"--plant-station", "p2", "--api-port", api, "write", "D100", "321"});
    INFO(wrote.err);
    CHECK(wrote.exit_code == 0);
    CHECK(nlohmann::json::parse(http_get(sim.http_port(), "/api/stations/p2/devices/D100").body)["values"][0] == 321);
    CHECK(nlohmann::json::parse(http_get(sim.http_port(), "/api/stations/p1/devices/D100").body)["values"][0] == 0);
    auto read = run_cli({"--plant-station", "p2", "--api-port", api, "--udp", "--json", "read", "D100"});
    CHECK(read.exit_code == 0);
    CHECK(read.out.find("321") != std::string::npos);
    auto unknown = run_cli({"--plant-station", "p9", "--api-port", api, "read", "D100"});
    CHECK(unknown.exit_code == 2);
    CHECK(unknown.err.find("has no station 'p9'") != std::string::npos);
}

TEST_CASE("plant: a scenario on a group of stations, all or nothing, and stopped for the group", "[plant]") {
    SimProcess sim(plant_options(R"({"bind": "127.0.0.1", "http": {"port": 0}, "stations": [
        {"template": {}, "count": 2, "name": "line-{i}", "tcp_port": 0}, {"name": "other", "tcp_port": 0}]})",
                                 {"--threads", "2"}));
    auto sick = R"({"stations": "line-*", "scenario": {"name": "sick", "faults": [{"do": "end_code", "end_code": "C051"}]}})";
    auto posted = http(sim.http_port(), "POST", "/api/plant/scenarios", sick);
    CHECK(posted.status == 201);
    CHECK(nlohmann::json::parse(posted.body) == nlohmann::json{{"name", "sick"}, {"stations", {"line-1", "line-2"}}});
    const auto refused = show(hex("D00000FFFF03000B0051C000FFFF030001040000"));
    for (const char* name : {"line-1", "line-2"}) {
        auto client = TcpClient::open(tcp_of(sim, name));
        CHECK(show(ask(client, kReadD100)) == refused);
    }
    auto other = TcpClient::open(tcp_of(sim, "other"));
    CHECK(show(ask(other, kReadD100)) == show(read_answer(0)));

    // "other" runs a scenario named "x": a group start of "x" over every station fails and leaves none running it.
    REQUIRE(http(sim.http_port(), "POST", "/api/stations/other/scenarios", R"({"name": "x"})").status == 201);
    auto clash = http(sim.http_port(), "POST", "/api/plant/scenarios", R"({"stations": "*", "scenario": {"name": "x"}})");
    CHECK(clash.status == 409);
    CHECK(clash.body.find("station other: a scenario named 'x' is already running") != std::string::npos);
    for (const char* name : {"line-1", "line-2"}) {
        auto list = nlohmann::json::parse(http_get(sim.http_port(), std::string("/api/stations/") + name + "/scenarios").body);
        REQUIRE(list["scenarios"].size() == 1);
        CHECK(list["scenarios"][0]["name"] == "sick");
    }

    auto stopped = http(sim.http_port(), "DELETE", "/api/plant/scenarios/sick");
    CHECK(stopped.status == 200);
    CHECK(nlohmann::json::parse(stopped.body)["stations"] == nlohmann::json{"line-1", "line-2"});
    auto line1 = TcpClient::open(tcp_of(sim, "line-1"));
    CHECK(show(ask(line1, kReadD100)) == show(read_answer(0)));
    CHECK(http(sim.http_port(), "DELETE", "/api/plant/scenarios/sick").status == 404);
    CHECK(http(sim.http_port(), "POST", "/api/plant/scenarios", R"({"stations": "nope-*", "scenario": {"name": "y"}})").status == 404);
}

TEST_CASE("plant: the shipped example plants check out", "[plant]") {
    for (const char* file : {"press-line.json", "one-port-many-addresses.json", "line-networks.json", "redundant-line.json"}) {
        auto path = std::filesystem::path(SLMP_SOURCE_DIR) / "examples/plants" / file;
        auto result = run_sim({"--check-config", path.string()}, std::chrono::seconds(60));
        INFO(file << ": " << result.err);
        CHECK(result.exit_code == 0);
    }
}

namespace {

// 4E binary read of D100 with serial `serial`, and its answer with `value`.
Bytes read_d100_4e(std::uint16_t serial) {
    return hex("5400" + hex_digits(serial & 0xFF, 2) + hex_digits(serial >> 8, 2) +
               "000000FFFF03000C00100001040000640000A80100");
}
Bytes answer_4e(std::uint16_t serial, std::uint16_t value) {
    return hex("D400" + hex_digits(serial & 0xFF, 2) + hex_digits(serial >> 8, 2) + "000000FFFF030004000000" +
               hex_digits(value & 0xFF, 2) + hex_digits(value >> 8, 2));
}

}  // namespace

TEST_CASE("plant: 200 stations from a template, each its own CPU over SLMP, HTTP and metrics", "[plant]") {
    SimProcess sim(plant_options(R"({"bind": "127.0.0.1", "http": {"port": 0}, "stations": [
        {"template": {"profile": "R08CPU"}, "count": 100, "name": "a{i}", "tcp_port": 0},
        {"template": {"profile": "R04CPU"}, "count": 100, "name": "b{i}", "tcp_port": 0}]})",
                                 {"--threads", "2"}));
    REQUIRE(sim.ready()["stations"].size() == 200);
    std::vector<std::string> names;
    for (const auto& s : sim.ready()["stations"]) names.push_back(s["name"]);
    for (std::size_t k = 0; k < names.size(); ++k) {
        auto client = TcpClient::open(tcp_of(sim, names[k]));
        auto type = ask(client, hex("500000FFFF03000600100001010000"));
        REQUIRE(type.size() == 29);
        CHECK(std::string(type.begin() + 11, type.begin() + 17) == (names[k][0] == 'a' ? "R08CPU" : "R04CPU"));
        CHECK(show(ask(client, write_d100(static_cast<std::uint16_t>(1000 + k)))) == show(kWriteOk));
    }
    // Each write landed in its own station only.
    for (std::size_t k = 0; k < names.size(); ++k) {
        auto client = TcpClient::open(tcp_of(sim, names[k]));
        CHECK(show(ask(client, kReadD100)) == show(read_answer(static_cast<std::uint16_t>(1000 + k))));
        auto body = http_get(sim.http_port(), "/api/stations/" + names[k] + "/devices/D100").body;
        CHECK(nlohmann::json::parse(body)["values"][0] == 1000 + k);
    }
    auto metrics = http_get(sim.http_port(), "/metrics").body;
    for (const auto& name : names)
        CHECK(metrics.find("slmp_requests_total{station=\"" + name + "\",transport=\"tcp\",command=\"1401\"") !=
              std::string::npos);
}

TEST_CASE("plant: a partitioned station answers nothing until healed, the others answer", "[plant]") {
    SimProcess sim(plant_options(R"({"bind": "127.0.0.1", "http": {"port": 0},
        "stations": [{"template": {}, "count": 2, "name": "press-{i}", "tcp_port": 0}]})",
                                 {"--threads", "2"}));
    auto partition = R"({"stations": "press-2", "scenario": {"name": "partition", "faults": [{"do": "no_response", "until_ms": 600000}]}})";
    REQUIRE(http(sim.http_port(), "POST", "/api/plant/scenarios", partition).status == 201);
    auto cut = TcpClient::open(tcp_of(sim, "press-2"));
    auto fine = TcpClient::open(tcp_of(sim, "press-1"));
    REQUIRE(cut.send(read_d100_4e(1)));                                      // swallowed
    CHECK(show(ask(fine, read_d100_4e(2))) == show(answer_4e(2, 0)));        // press-1 is unaffected
    // Heal only once press-2 has swallowed serial 1 (its fault has fired): under load its
    // thread may not have read the request yet, and would then answer it after the heal.
    auto fired = [&] {
        auto faults = nlohmann::json::parse(http_get(sim.http_port(), "/api/stations/press-2/faults").body)["faults"];
        return !faults.empty() && faults[0]["fired"] == 1;
    };
    auto deadline = std::chrono::steady_clock::now() + std::chrono::seconds(20);
    while (!fired() && std::chrono::steady_clock::now() < deadline) std::this_thread::sleep_for(std::chrono::milliseconds(10));
    REQUIRE(fired());
    REQUIRE(http(sim.http_port(), "DELETE", "/api/plant/scenarios/partition").status == 200);
    // The first answer press-2 gives is to the request after the heal: serial 1 was never answered.
    CHECK(show(ask(cut, read_d100_4e(3))) == show(answer_4e(3, 0)));
}

TEST_CASE("plant: clients of one station on several threads see every request atomic, no write lost", "[plant]") {
    SimProcess sim(plant_options(R"({"bind": "127.0.0.1", "http": {"port": 0},
        "stations": [{"name": "hot", "tcp_port": 0}, {"name": "other", "tcp_port": 0}]})",
                                 {"--threads", "2"}));
    auto port = tcp_of(sim, "hot");
    constexpr int kClients = 8, kRounds = 40;
    // Writers fill D0-D959 (overlapping: all of them) with one value per request,
    // and D1000+client (disjoint) with their round; readers check no block is torn.
    auto block_write = [](std::uint16_t value) {
        std::string data;
        for (int w = 0; w < 960; ++w) data += hex_digits(value & 0xFF, 2) + hex_digits(value >> 8, 2);
        return hex("500000FFFF0300" + hex_digits((12 + 1920) & 0xFF, 2) + hex_digits((12 + 1920) >> 8, 2) +
                   "100001140000000000A8C003" + data);
    };
    const Bytes block_read = hex("500000FFFF03000C00100001040000000000A8C003");
    std::vector<std::thread> threads;
    std::atomic<int> torn{0}, failed{0};
    for (int c = 0; c < kClients; ++c)
        threads.emplace_back([&, c] {
            auto client = TcpClient::open(port);
            for (int r = 1; r <= kRounds; ++r) {
                Bytes answer;
                std::string why;
                auto value = static_cast<std::uint16_t>(c * 1000 + r);
                auto request = c % 2 == 0 ? block_write(value) : block_read;
                if (!client.send(request) || !client.response(&answer, kReplyTimeout, &why)) {
                    ++failed;
                    return;
                }
                if (c % 2 == 1) {
                    if (answer.size() != 11 + 1920) ++failed;
                    else
                        for (std::size_t w = 1; w < 960; ++w)
                            if (answer[11 + 2 * w] != answer[11] || answer[12 + 2 * w] != answer[12]) {
                                ++torn;
                                break;
                            }
                }
                auto own = static_cast<std::uint16_t>(1000 + c);
                auto single = hex("500000FFFF03000E00100001140000" + hex_digits(own & 0xFF, 2) +
                                  hex_digits(own >> 8, 2) + "00A80100" + hex_digits(r & 0xFF, 2) + hex_digits(r >> 8, 2));
                if (!client.send(single) || !client.response(&answer, kReplyTimeout, &why)) ++failed;
            }
        });
    for (auto& t : threads) t.join();
    CHECK(failed == 0);
    CHECK(torn == 0);
    auto last = nlohmann::json::parse(http_get(sim.http_port(), "/api/stations/hot/devices/D1000?count=8").body);
    CHECK(last["values"] == nlohmann::json(std::vector<int>(kClients, kRounds)));
}

TEST_CASE("plant: scenario files name their stations, one list places each where it belongs", "[plant][scenario]") {
    TempDir dir;
    auto presses = dir.write("presses.json", R"({"name": "presses", "stations": "press-*", "initial": {"devices": {"D0": 7}}})");
    auto oven = dir.write("oven.json", R"({"name": "oven", "stations": ["oven-1"], "initial": {"devices": {"D0": 9}}})");
    auto everyone = dir.write("all.json", R"({"name": "all", "initial": {"devices": {"D1": 1}}})");
    SimProcess sim(plant_options(R"({"bind": "127.0.0.1", "http": {"port": 0}, "scenarios": [")" + presses.string() +
                                 R"(", ")" + oven.string() + R"(", ")" + everyone.string() + R"("],
        "stations": [{"template": {}, "count": 2, "name": "press-{i}", "tcp_port": 0}, {"name": "oven-1", "tcp_port": 0}]})"));
    auto words = [&](const std::string& station) {
        return nlohmann::json::parse(http_get(sim.http_port(), "/api/stations/" + station + "/devices/D0?count=2").body)["values"];
    };
    CHECK(words("press-1") == nlohmann::json({7, 1}));
    CHECK(words("press-2") == nlohmann::json({7, 1}));
    CHECK(words("oven-1") == nlohmann::json({9, 1}));

    SECTION("posted to the plant without \"stations\", a scenario goes to the stations it names") {
        auto posted = http(sim.http_port(), "POST", "/api/plant/scenarios",
                           R"({"scenario": {"name": "p2", "stations": "*-2", "initial": {"devices": {"D1": 5}}}})");
        INFO(posted.body);
        CHECK(posted.status == 201);
        CHECK(posted.json()["stations"] == nlohmann::json::array({"press-2"}));
        CHECK(words("press-2") == nlohmann::json({7, 5}));
        CHECK(words("press-1") == nlohmann::json({7, 1}));
    }
    SECTION("posted to a station it does not name, it is refused") {
        auto refused = http(sim.http_port(), "POST", "/api/stations/oven-1/scenarios",
                            R"({"name": "x", "stations": "press-*", "initial": {"devices": {"D1": 5}}})");
        CHECK(refused.status == 400);
        CHECK(refused.error() == "request body (x): /stations: the scenario is for [\"press-*\"], not this station; post it "
                                 "to one of those, or to /api/plant/scenarios");
        CHECK(words("oven-1") == nlohmann::json({9, 1}));
    }
}

TEST_CASE("plant: a scenario file whose stations match none of the plant is a configuration error", "[plant][scenario]") {
    TempDir dir;
    auto typo = dir.write("typo.json", R"({"name": "typo", "stations": "pres-*"})");
    auto file = dir.write("plant.json", R"({"scenarios": [")" + typo.string() +
                                            R"("], "stations": [{"template": {}, "count": 2, "name": "press-{i}", "tcp_port": 0}]})");
    auto checked = run_sim({"--check-config", file.string()});
    CHECK(checked.exit_code == 2);
    CHECK(checked.err.find(typo.string() + ": /stations: no station of the plant is named \"pres-*\"") != std::string::npos);
    // A one-station file with a name is checked too; a lone unnamed station runs every scenario.
    auto named = dir.write("named.json", R"({"name": "oven-1", "scenarios": [")" + typo.string() + R"("]})");
    CHECK(run_sim({"--check-config", named.string()}).exit_code == 2);
    auto unnamed = dir.write("unnamed.json", R"({"scenarios": [")" + typo.string() + R"("]})");
    CHECK(run_sim({"--check-config", unnamed.string()}).exit_code == 0);
}

TEST_CASE("plant: each station's log lines start with its name", "[plant][logs]") {
    auto options = plant_options(R"({"bind": "127.0.0.1", "http": {"port": 0}, "log_level": "info",
        "stations": [{"template": {}, "count": 2, "name": "press-{i}", "tcp_port": 0}]})");
    options.default_log_level = true;
    SimProcess sim(options);
    {
        auto press2 = TcpClient::open(tcp_of(sim, "press-2"));
        CHECK(show(ask(press2, kReadD100)) == show(read_answer(0)));
    }
    auto logs = sim.logs();
    INFO(logs);
    // The connection's line names press-2 (it is written before the request is read); press-1 has none.
    CHECK(logs.find("press-2: tcp:127.0.0.1:") != std::string::npos);
    CHECK(logs.find(" connected (connection 1)") != std::string::npos);
    CHECK(logs.find("press-1: tcp:") == std::string::npos);
    // Process-wide lines have no prefix (the stations' loggers share the format, not a name).
    CHECK(logs.find("info  slmp-sim 0.1.0: a plant of 2 stations") != std::string::npos);
}
