// slmp-bench end to end (docs/bench.md): the baseline server's answers over
// real sockets as a strict client takes them (byte for byte, and through the
// project's response parser), slmp-bench against it in every frame shape,
// --targets refusals, and a run spread over the two stations of a real
// slmp-sim plant. No figure is asserted: performance is measured, not tested.
#include <catch2/catch.hpp>

#include "baseline_process.hpp"
#include "frames.hpp"
#include "http_client.hpp"
#include "sim_process.hpp"
#include "sockets.hpp"

using namespace slmp::test;

namespace {

// A strict client: exactly one response frame, the kind, codec and serial asked
// for, end code 0 and `data_bytes` of data.
void accept_strictly(const Bytes& frame, const Wire& wire, std::size_t data_bytes) {
    bool garbage = false;
    auto response = slmp::protocol::client::parse_response(frame, &garbage);
    REQUIRE(response);
    CHECK(response->size == frame.size());
    CHECK(response->header.kind == wire.kind);
    CHECK(response->header.codec == wire.codec);
    if (wire.kind == FrameKind::E4) CHECK(response->header.serial == wire.serial);
    CHECK(response->end_code == 0);
    CHECK(response->data.size() == data_bytes);
}

nlohmann::json bench_json(const RunResult& run) {
    INFO("slmp-bench stdout: " << run.out << "\nstderr: " << run.err);
    auto json = nlohmann::json::parse(run.out, nullptr, false);
    REQUIRE_FALSE(json.is_discarded());
    return json;
}

}  // namespace

TEST_CASE("bench: the baseline server answers a 3E binary read byte for byte, over TCP and UDP", "[bench]") {
    BaselineProcess baseline;
    const Wire wire{FrameKind::E3, Codec::Binary};
    auto request = slmp::protocol::client::read_words(wire.options(), addr("D100"), 3);
    REQUIRE(show(request) == show(hex("500000FFFF03000C00100001040000640000A80300")));
    const Bytes expected = hex("D00000FFFF030008000000000000000000");

    auto tcp = TcpClient::open(baseline.tcp_port());
    REQUIRE(tcp.send(request));
    Bytes frame;
    REQUIRE(tcp.response(&frame));
    CHECK(show(frame) == show(expected));
    accept_strictly(frame, wire, 6);

    UdpClient udp;
    REQUIRE(udp.send_to(baseline.udp_port(), request));
    auto datagram = udp.receive();
    REQUIRE(datagram);
    CHECK(show(*datagram) == show(expected));
}

TEST_CASE("bench: the baseline server answers pipelined 4E ASCII reads byte for byte, each with its serial", "[bench]") {
    BaselineProcess baseline;
    Wire first{FrameKind::E4, Codec::Ascii, 0x1234};
    Wire second{FrameKind::E4, Codec::Ascii, 0x0BCD};
    auto one = slmp::protocol::client::read_words(first.options(), addr("D100"), 3);
    REQUIRE(show(one) == show(text("54001234000000FF03FF00001800100401" "0000D*0001000003")));
    auto two = slmp::protocol::client::read_words(second.options(), addr("D100"), 3);

    auto tcp = TcpClient::open(baseline.tcp_port());
    REQUIRE(tcp.send(concat({one, two})));   // one send: both arrive together
    Bytes frame;
    REQUIRE(tcp.response(&frame));
    CHECK(show(frame) == show(text("D4001234000000FF03FF0000100000" "000000000000")));
    accept_strictly(frame, first, 12);
    REQUIRE(tcp.response(&frame));
    CHECK(show(frame) == show(text("D4000BCD000000FF03FF0000100000" "000000000000")));
    accept_strictly(frame, second, 12);
}

TEST_CASE("bench: the baseline server closes a connection that does not speak SLMP", "[bench]") {
    BaselineProcess baseline;
    auto tcp = TcpClient::open(baseline.tcp_port());
    REQUIRE(tcp.send(text("GET / HTTP/1.1\r\n\r\n")));
    Bytes unexpected;
    CHECK(tcp.wait_closed(kReplyTimeout, &unexpected));
    CHECK(unexpected.empty());
}

TEST_CASE("bench: slmp-bench finds no error in the baseline's answers, in every frame shape", "[bench]") {
    BaselineProcess baseline;
    const std::string tcp = std::to_string(baseline.tcp_port()), udp = std::to_string(baseline.udp_port());
    const std::vector<std::vector<std::string>> runs = {
        {"--port", tcp, "-c", "3"},
        {"--port", tcp, "-c", "3", "--ascii"},
        {"--port", tcp, "-c", "2", "--4e", "-d", "8"},
        {"--port", tcp, "-c", "2", "--4e", "-d", "8", "--ascii"},
        {"--port", udp, "-c", "3", "--udp", "--4e"},
        {"--port", udp, "-c", "3", "--udp", "--ascii"},
    };
    for (auto args : runs) {
        args.insert(args.end(), {"--mix", "read1,read960,write1,write960,readbits", "--requests", "2000", "--warmup", "0",
                                 "--json", "--server-pid", std::to_string(baseline.pid())});
        auto run = run_bench(args);
        std::string shown;
        for (auto& a : args) shown += a + " ";
        INFO("slmp-bench " << shown << "\n" << run.out << run.err);
        CHECK(run.exit_code == 0);
        auto json = bench_json(run);
        CHECK(json["sent"] == 2000);
        CHECK(json["total"]["requests"] == 2000);
        CHECK(json["total"]["errors"]["total"] == 0);
        CHECK(json["cpu"]["server_pid"] == baseline.pid());
        CHECK(json["cpu"]["server_s"].get<double>() >= 0.0);
    }
}

TEST_CASE("bench: --targets and --server-pid refuse bad input with exit status 2 and the reason", "[bench]") {
    struct Case {
        std::vector<std::string> args;
        std::string message;
    };
    const std::vector<Case> cases = {
        {{"--targets", "127.0.0.1:20999-20000"}, "slmp-bench: --targets entry '127.0.0.1:20999-20000': the range runs backwards"},
        {{"--targets", "127.0.0.1"}, "slmp-bench: --targets entry '127.0.0.1': no port"},
        {{"--targets", "127.0.0.1:5000,,127.0.0.1:5001"}, "slmp-bench: --targets '127.0.0.1:5000,,127.0.0.1:5001' has an empty entry"},
        {{"--targets", "127.0.0.1:0"}, "slmp-bench: --targets entry '127.0.0.1:0': port 0 is outside 1-65535"},
        {{"--targets", "127.0.0.1:5000", "--port", "5001"}, "slmp-bench: --targets replaces --host and --port; give one or the other"},
        {{"--targets", "192.0.2.1:5000"}, "slmp-bench: host 192.0.2.1 (192.0.2.1) is not a loopback address; add --allow-remote"},
        {{"--targets", "127.0.0.1:5000", "--server-pid", "0"}, "slmp-bench: --server-pid must be a process id"},
    };
    for (const auto& c : cases) {
        auto run = run_bench(c.args);
        INFO(c.args[1] << "\nstdout: " << run.out << "\nstderr: " << run.err);
        CHECK(run.exit_code == 2);
        CHECK(run.err.starts_with(c.message));
        CHECK(run.out.empty());
    }
}

TEST_CASE("bench: --targets spreads the connections over two stations of a plant, and each gets requests", "[bench]") {
    SimOptions options;
    options.plant = true;
    options.config_json = R"({"bind": "127.0.0.1", "http": {"port": 0},
        "stations": [{"template": {"profile": "R08CPU"}, "count": 2, "name": "st-{i}", "tcp_port": 0}]})";
    options.args = {"--threads", "2"};
    SimProcess sim(options);
    REQUIRE(sim.ready()["stations"].size() == 2);
    std::string targets;
    for (const auto& station : sim.ready()["stations"])
        targets += (targets.empty() ? "" : ",") + std::string("127.0.0.1:") + std::to_string(station["tcp"][0].get<int>());

    // A fixed number of requests, all measured (no warm-up): the plant must have seen exactly these.
    auto run = run_bench({"--targets", targets, "-c", "4", "--requests", "2000", "--warmup", "0", "--json",
                          "--server-pid", std::to_string(sim.pid())});
    INFO(run.out << run.err);
    REQUIRE(run.exit_code == 0);
    auto json = bench_json(run);
    CHECK(json["targets"] == 2);
    CHECK(json["target"] == "tcp " + targets + " (2 targets)");
    CHECK(json["total"]["requests"] == 2000);
    CHECK(json["total"]["errors"]["total"] == 0);
    CHECK(json["cpu"]["server_pid"] == sim.pid());

    auto stations = http_get(sim.http_port(), "/api/stations").json();
    REQUIRE(stations.size() == 2);
    INFO(stations.dump());
    CHECK(stations[0]["requests"].get<int>() > 0);
    CHECK(stations[1]["requests"].get<int>() > 0);
    CHECK(stations[0]["requests"].get<int>() + stations[1]["requests"].get<int>() == 2000);
    CHECK(stations[0]["errors"] == 0);
    CHECK(stations[1]["errors"] == 0);
}

TEST_CASE("bench: --octal-xy numbers an FX5's X/Y in octal: --device Y10 is bit 8, binary and ASCII", "[bench][octal]") {
    SimProcess sim(with_args({"--profile", "FX5U-32MR"}));
    const auto port = std::to_string(sim.tcp_port());
    for (const auto& codec : std::vector<std::vector<std::string>>{{}, {"--ascii"}}) {
        std::vector<std::string> args{"--port", port, "--octal-xy", "--device", "Y10", "--mix", "write1",
                                      "--requests", "50", "--warmup", "0", "--json"};
        args.insert(args.end(), codec.begin(), codec.end());
        auto run = run_bench(args);
        INFO(run.out << run.err);
        REQUIRE(run.exit_code == 0);
        CHECK(bench_json(run)["total"]["errors"]["total"] == 0);
        // write1 writes 1 to the word at Y10: bit 8 on, so Y0-Y17 read as one word is 0x0100.
        CHECK(http_get(sim.http_port(), "/api/devices/Y0?as=words").json()["values"] == nlohmann::json::array({0x0100}));
        REQUIRE(http_put(sim.http_port(), "/api/devices/Y0?as=words", R"({"values": [0]})").status == 200);
    }
    auto bad = run_bench({"--port", port, "--octal-xy", "--device", "X8"});
    CHECK(bad.exit_code == 2);
    CHECK(bad.err.find("X is numbered in octal on this CPU: X7 is followed by X10") != std::string::npos);
}
