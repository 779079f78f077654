// The HTTP API's pure parts: routing (404/405, captures, query checks,
// percent-decoding), device views and string packing, and the metrics text
// after a known set of activity reports — no sockets, no clock.
#include <catch2/catch.hpp>

#include <chrono>
#include <string>
#include <vector>

#include "config/config.hpp"
#include "control/endpoints/device_view.hpp"
#include "control/http/router.hpp"
#include "control/observers/metrics.hpp"
#include "station/station.hpp"

using namespace slmp::station;
using namespace slmp::control;

TEST_CASE("router: captures, query parameters, 404 and 405", "[http]") {
    slmp::control::Router router;
    router.add(Verb::get, "/api/devices/{address}", {"count"}, [](const ApiRequest& r) {
        return json_reply({{"address", r.captures.at(0)}, {"count", r.param("count") ? *r.param("count") : "-"}});
    });
    router.add(Verb::put, "/api/devices/{address}", {}, [](const ApiRequest& r) { return json_reply({{"body", r.body}}); });

    auto ok = router.route(Verb::get, "/api/devices/U3E0%5CG10?count=2", "");
    CHECK(ok.status == Status::ok);
    CHECK(ok.body == "{\"address\":\"U3E0\\\\G10\",\"count\":\"2\"}\n");
    CHECK(router.route(Verb::put, "/api/devices/D1", "{}").body == "{\"body\":\"{}\"}\n");

    auto missing = router.route(Verb::get, "/api/device/D1", "");
    CHECK(missing.status == Status::not_found);
    auto wrong = router.route(Verb::delete_, "/api/devices/D1", "");
    CHECK(wrong.status == Status::method_not_allowed);
    CHECK(wrong.headers == std::vector<std::pair<std::string, std::string>>{{"Allow", "GET, PUT"}});
    auto unknown = router.route(Verb::get, "/api/devices/D1?count=1&as=bits", "");
    CHECK(unknown.status == Status::bad_request);
    CHECK(unknown.body == "{\"error\":\"unknown query parameter 'as' for /api/devices/D1; use count\"}\n");
    CHECK(router.route(Verb::get, "/api/devices/D1?count=%zz", "").status == Status::bad_request);
}

TEST_CASE("router: percent-decoding", "[http]") {
    std::string out;
    CHECK(percent_decode("a%20b+c", false, &out));
    CHECK(out == "a b+c");
    CHECK(percent_decode("a%20b+c", true, &out));
    CHECK(out == "a b c");
    CHECK_FALSE(percent_decode("%2", false, &out));
    CHECK_FALSE(percent_decode("%g0", false, &out));
}

TEST_CASE("device views: strings are bytes, NUL-terminated, low byte first", "[http]") {
    CHECK(pack_string("HELLO") == std::vector<std::uint16_t>{0x4548, 0x4C4C, 0x004F});
    CHECK(pack_string("AB") == std::vector<std::uint16_t>{0x4241, 0x0000});
    CHECK(pack_string("") == std::vector<std::uint16_t>{0x0000});
    CHECK(pack_string("\xC3\xA9") == std::vector<std::uint16_t>{0x00E9});
    CHECK_THROWS_AS(pack_string("\xE3\x81\x82"), ApiError);
    CHECK(unpack_string({0x4548, 0x4C4C, 0x004F, 0x4141}) == "HELLO");
    CHECK(unpack_string({0x4241}) == "AB");
    CHECK(unpack_string({0x00E9}) == "\xC3\xA9");
}

TEST_CASE("device views: spans, defaults and checks", "[http]") {
    slmp::devicemodel::Cpu cpu(slmp::config::load_profile("R08CPU").cpu);
    auto m = parse_device("M0");
    CHECK(default_view(*m.spec) == View::Bits);
    CHECK(make_run(cpu, m, View::Words, 2).devices == 32);
    CHECK(make_run(cpu, m, View::Dwords, 1).devices == 32);
    auto d = parse_device("D0");
    CHECK(default_view(*d.spec) == View::Words);
    CHECK(make_run(cpu, d, View::Dwords, 3).devices == 6);
    auto ltn = parse_device("LTN0");
    CHECK(default_view(*ltn.spec) == View::Dwords);
    CHECK(make_run(cpu, ltn, View::Dwords, 3).devices == 3);
    CHECK_THROWS_AS(make_run(cpu, d, View::Bits, 1), ApiError);
    CHECK_THROWS_AS(make_run(cpu, d, View::Words, 0), ApiError);
    CHECK_THROWS_AS(make_run(cpu, d, View::Words, kMaxValues + 1), ApiError);
    CHECK_THROWS_AS(parse_device("Q0"), ApiError);

    // Bits written as words land on the bit devices, bit 0 lowest.
    auto run = make_run(cpu, parse_device("M4"), View::Words, 1);
    write_run(cpu.memory(), run, {0x8001});
    CHECK(cpu.memory().bit(*m.spec, 4));
    CHECK(cpu.memory().bit(*m.spec, 19));
    CHECK_FALSE(cpu.memory().bit(*m.spec, 5));
    CHECK(read_run(cpu.memory(), make_run(cpu, parse_device("M4"), View::Bits, 2))["values"] == nlohmann::json{1, 0});
}

TEST_CASE("metrics: text after known activity", "[http][metrics]") {
    Station station(slmp::config::load_profile("R08CPU"), {});
    Metrics metrics(station);

    slmp::protocol::Outcome ok;
    ok.action = slmp::protocol::Outcome::Action::Respond;
    ok.command = 0x0401;
    ok.response.assign(13, 0);
    slmp::protocol::Outcome refused = ok;
    refused.end_code = slmp::protocol::EndCode::DeviceOutOfRange;
    slmp::protocol::Outcome garbage;
    garbage.action = slmp::protocol::Outcome::Action::Silent;
    std::vector<std::uint8_t> frame(21);

    using std::chrono::microseconds;
    const slmp::protocol::Peer tcp{Transport::Tcp, "x"};
    const slmp::protocol::Peer udp{Transport::Udp, "x"};
    const slmp::protocol::Request request;   // metrics count outcomes; the decoded request is not read
    station.activity().request({1, tcp, frame, request, ok, microseconds(30)});
    station.activity().request({1, tcp, frame, request, ok, microseconds(300)});
    station.activity().request({1, tcp, frame, request, refused, microseconds(2000)});
    station.activity().request({2, udp, std::span(frame).first(5), request, garbage, microseconds(1)});

    auto text = metrics.render();
    auto has = [&](const std::string& line) {
        INFO(line);
        CHECK(text.find("\n" + line + "\n") != std::string::npos);
    };
    has("slmp_requests_total{transport=\"tcp\",command=\"0401\",subcommand=\"0000\",end_code=\"0000\"} 2");
    has("slmp_requests_total{transport=\"tcp\",command=\"0401\",subcommand=\"0000\",end_code=\"4031\"} 1");
    has("slmp_unparsed_frames_total{transport=\"udp\"} 1");
    has("slmp_request_duration_seconds_bucket{le=\"5e-05\"} 1");
    has("slmp_request_duration_seconds_bucket{le=\"0.0005\"} 2");
    has("slmp_request_duration_seconds_bucket{le=\"0.0025\"} 3");
    has("slmp_request_duration_seconds_bucket{le=\"+Inf\"} 3");
    has("slmp_request_duration_seconds_count 3");
    has("slmp_received_bytes_total{transport=\"tcp\"} 63");
    has("slmp_sent_bytes_total{transport=\"tcp\"} 39");
    has("slmp_received_bytes_total{transport=\"udp\"} 5");
    has("slmp_open_connections 0");
}
