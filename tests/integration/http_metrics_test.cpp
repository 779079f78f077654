// GET /metrics against the real binary: after a known sequence of SLMP
// requests over TCP and UDP, every counter has moved by exactly what was sent.
#include <catch2/catch.hpp>

#include <map>
#include <sstream>
#include <string>

#include "frames.hpp"
#include "protocol/client_commands.hpp"
#include "http_client.hpp"
#include "link.hpp"
#include "sim_process.hpp"
#include "sockets.hpp"

using namespace slmp::test;
namespace client = slmp::protocol::client;

namespace {

// "name{labels} value" lines of the exposition text, by "name{labels}".
std::map<std::string, double> samples(const std::string& text) {
    std::map<std::string, double> out;
    std::istringstream in(text);
    for (std::string line; std::getline(in, line);) {
        if (line.empty() || line[0] == '#') continue;
        auto space = line.rfind(' ');
        out[line.substr(0, space)] = std::stod(line.substr(space + 1));
    }
    return out;
}

}  // namespace

TEST_CASE("metrics: counters move as expected after a known sequence of requests", "[http][metrics]") {
    SimProcess sim;
    const Wire binary{FrameKind::E3, Codec::Binary, 0};
    const Wire ascii{FrameKind::E3, Codec::Ascii, 0};

    auto before = http_get(sim.http_port(), "/metrics");
    REQUIRE(before.status == 200);
    CHECK(before.header("content-type") == "text/plain; version=0.0.4; charset=utf-8");
    auto m0 = samples(before.body);
    CHECK(m0["slmp_request_duration_seconds_count"] == 0);
    CHECK(m0["slmp_open_connections"] == 0);
    CHECK(m0["slmp_info{profile=\"R08CPU\",type_name=\"R08CPU\"}"] == 1);

    std::size_t tcp_in = 0, tcp_out = 0;
    {
        TcpLink tcp(sim.tcp_port());
        auto send = [&](const Bytes& request) {
            auto response = tcp.exchange(request);
            REQUIRE(!response.empty());
            tcp_in += request.size();
            tcp_out += response.size();
        };
        for (int i = 0; i < 3; ++i) send(client::read_words(binary.options(), addr("D0"), 2));      // 0401 ok ×3
        send(client::write_words(ascii.options(), addr("D0"), std::vector<std::uint16_t>{1}));      // 1401 ok
        send(client::read_words(binary.options(), addr("D10239"), 2));                               // 0401 → 4031
        send(client::build_request(binary.options(), 0x0E99, 0x0000));                               // → C059
        auto open = samples(http_get(sim.http_port(), "/metrics").body);
        CHECK(open["slmp_open_connections"] == 1);
        CHECK(open["slmp_connections_accepted_total"] == 1);
    }
    UdpLink udp(sim.udp_port());
    auto udp_request = client::read_words(binary.options(), addr("D0"), 1);
    auto udp_response = udp.exchange(udp_request);
    REQUIRE(!udp_response.empty());

    // The TCP close is seen by the server shortly after; bounded wait.
    std::map<std::string, double> m;
    auto deadline = std::chrono::steady_clock::now() + kReplyTimeout;
    do {
        m = samples(http_get(sim.http_port(), "/metrics").body);
    } while (m["slmp_connections_closed_total"] != 1 && std::chrono::steady_clock::now() < deadline);

    CHECK(m["slmp_requests_total{transport=\"tcp\",command=\"0401\",subcommand=\"0000\",end_code=\"0000\"}"] == 3);
    CHECK(m["slmp_requests_total{transport=\"tcp\",command=\"1401\",subcommand=\"0000\",end_code=\"0000\"}"] == 1);
    CHECK(m["slmp_requests_total{transport=\"tcp\",command=\"0401\",subcommand=\"0000\",end_code=\"4031\"}"] == 1);
    CHECK(m["slmp_requests_total{transport=\"tcp\",command=\"0E99\",subcommand=\"0000\",end_code=\"C059\"}"] == 1);
    CHECK(m["slmp_requests_total{transport=\"udp\",command=\"0401\",subcommand=\"0000\",end_code=\"0000\"}"] == 1);
    CHECK(m["slmp_request_duration_seconds_count"] == 7);
    CHECK(m["slmp_request_duration_seconds_bucket{le=\"+Inf\"}"] == 7);
    CHECK(m["slmp_received_bytes_total{transport=\"tcp\"}"] == static_cast<double>(tcp_in));
    CHECK(m["slmp_sent_bytes_total{transport=\"tcp\"}"] == static_cast<double>(tcp_out));
    CHECK(m["slmp_received_bytes_total{transport=\"udp\"}"] == static_cast<double>(udp_request.size()));
    CHECK(m["slmp_sent_bytes_total{transport=\"udp\"}"] == static_cast<double>(udp_response.size()));
    CHECK(m["slmp_open_connections"] == 0);
    CHECK(m["slmp_connections_accepted_total"] == 1);
    CHECK(m["slmp_connections_closed_total"] == 1);
    CHECK(m["slmp_unparsed_frames_total{transport=\"tcp\"}"] == 0);

    // Bytes that are no frame are counted apart from requests.
    UdpClient garbage;
    REQUIRE(garbage.send_to(sim.udp_port(), std::string("hello")));
    deadline = std::chrono::steady_clock::now() + kReplyTimeout;
    do {
        m = samples(http_get(sim.http_port(), "/metrics").body);
    } while (m["slmp_unparsed_frames_total{transport=\"udp\"}"] != 1 && std::chrono::steady_clock::now() < deadline);
    CHECK(m["slmp_unparsed_frames_total{transport=\"udp\"}"] == 1);
    CHECK(m["slmp_request_duration_seconds_count"] == 7);
}

TEST_CASE("metrics: the CPU state follows a remote STOP and RUN, scan times appear in RUN", "[http][metrics]") {
    SimProcess sim;
    const Wire binary{FrameKind::E3, Codec::Binary, 0};
    auto scrape = [&] { return samples(http_get(sim.http_port(), "/metrics").body); };

    // Scan statistics exist from the second scan in RUN on (as SD520-SD525); bounded wait.
    auto m = scrape();
    auto deadline = std::chrono::steady_clock::now() + kReplyTimeout;
    while (!m.count("slmp_scan_time_seconds{kind=\"max\"}") && std::chrono::steady_clock::now() < deadline) m = scrape();
    CHECK(m["slmp_cpu_state"] == 0);
    REQUIRE(m.count("slmp_scan_time_seconds{kind=\"max\"}"));
    CHECK(m["slmp_scan_time_seconds{kind=\"min\"}"] > 0);
    CHECK(m["slmp_scan_time_seconds{kind=\"min\"}"] <= m["slmp_scan_time_seconds{kind=\"max\"}"]);

    TcpLink tcp(sim.tcp_port());
    // A remote operation takes effect at a scan boundary: wait for it, bounded.
    auto state_after = [&](const Bytes& request, double expected) {
        REQUIRE(!tcp.exchange(request).empty());
        auto until = std::chrono::steady_clock::now() + kReplyTimeout;
        auto state = scrape()["slmp_cpu_state"];
        while (state != expected && std::chrono::steady_clock::now() < until) state = scrape()["slmp_cpu_state"];
        return state;
    };
    CHECK(state_after(client::remote_stop(binary.options()), 2) == 2);
    CHECK(state_after(client::remote_run(binary.options(), client::RemoteMode::Normal, client::ClearMode::None), 0) == 0);
}
