// The timing model's arithmetic (station/response_timing.hpp), its
// configuration ("timing" in the configuration and in profiles) and the
// Ondemand frame (protocol/ondemand.hpp), byte-exact in both codes.
#include <catch2/catch.hpp>

#include <vector>

#include "config/config.hpp"
#include "protocol/client.hpp"
#include "protocol/ondemand.hpp"
#include "station/response_timing.hpp"
#include "station/station.hpp"

namespace config = slmp::config;
namespace protocol = slmp::protocol;
using slmp::station::ResponseTiming;
using std::chrono::microseconds;
using std::chrono::milliseconds;

namespace {

using Bytes = std::vector<std::uint8_t>;

Bytes text(const std::string& s) { return Bytes(s.begin(), s.end()); }

protocol::Request decoded(slmp::station::Station& station, const Bytes& frame) {
    return station.engine().decode(frame, protocol::DataCodePolicy::Auto, {});
}

slmp::devicemodel::DeviceAddress at(const std::string& name) { return *slmp::devicemodel::parse_address(name); }

}  // namespace

TEST_CASE("ondemand frame: 3E/4E response shape, end code 0000, 2101 0000, the words", "[timing][ondemand]") {
    const std::vector<std::uint16_t> words = {0x1234, 0x5678};
    CHECK(protocol::encode_ondemand(protocol::FrameKind::E3, protocol::Codec::Binary, words) ==
          Bytes{0xD0, 0x00, 0x00, 0xFF, 0xFF, 0x03, 0x00, 0x0A, 0x00, 0x00, 0x00, 0x01, 0x21, 0x00, 0x00, 0x34, 0x12, 0x78, 0x56});
    CHECK(protocol::encode_ondemand(protocol::FrameKind::E4, protocol::Codec::Binary, words) ==
          Bytes{0xD4, 0x00, 0x00, 0x00, 0x00, 0x00, 0x00, 0xFF, 0xFF, 0x03, 0x00, 0x0A, 0x00,
                0x00, 0x00, 0x01, 0x21, 0x00, 0x00, 0x34, 0x12, 0x78, 0x56});
    CHECK(protocol::encode_ondemand(protocol::FrameKind::E3, protocol::Codec::Ascii, words) ==
          text("D00000FF03FF00001400002101000012345678"));
    CHECK(protocol::encode_ondemand(protocol::FrameKind::E4, protocol::Codec::Ascii, words) ==
          text("D4000000000000FF03FF00001400002101000012345678"));
    // 1E and the station-number-extended frame have no Ondemand: the 3E shape.
    CHECK(protocol::encode_ondemand(protocol::FrameKind::E1, protocol::Codec::Binary, words) ==
          protocol::encode_ondemand(protocol::FrameKind::E3, protocol::Codec::Binary, words));
}

TEST_CASE("timing model: Ke + Kdt x words by data code, plus the scan wait when modelled", "[timing]") {
    slmp::station::Station station(config::load_profile("R08CPU"), {});
    config::TimingModel m{2.0, 3.0, 0.5, 1.0, true};
    ResponseTiming timing(m, 0, 1);
    protocol::client::FrameOptions bin;
    auto ascii = bin;
    ascii.codec = protocol::Codec::Ascii;

    auto read10 = decoded(station, protocol::client::read_words(bin, at("D0"), 10));
    CHECK(ResponseTiming::words(read10) == 10);
    CHECK(timing.modelled(read10, microseconds{0}) == microseconds{7000});        // 2 + 0.5 x 10
    CHECK(timing.modelled(read10, microseconds{4000}) == microseconds{11000});    // + the wait for END
    auto ascii10 = decoded(station, protocol::client::read_words(ascii, at("D0"), 10));
    CHECK(timing.modelled(ascii10, microseconds{0}) == microseconds{13000});      // 3 + 1.0 x 10
    // Bit units: 16 points to a word; double words count twice.
    auto bits = decoded(station, protocol::client::read_bits(bin, at("M0"), 17));
    CHECK(ResponseTiming::words(bits) == 2);
    // No scan wait when the model says so.
    m.scan_wait = false;
    ResponseTiming no_wait(m, 0, 1);
    CHECK(no_wait.modelled(read10, microseconds{4000}) == microseconds{7000});
}

TEST_CASE("timing model: jitter stays within its fraction and repeats for the same seed", "[timing]") {
    slmp::station::Station station(config::load_profile("R08CPU"), {});
    config::TimingModel m{10.0, 10.0, 0, 0, false};
    ResponseTiming a(m, 0.2, 42), b(m, 0.2, 42), c(m, 0.2, 43);
    auto request = decoded(station, protocol::client::read_words({}, at("D0"), 1));
    bool differs = false;
    for (int i = 0; i < 200; ++i) {
        auto ta = a.modelled(request, {});
        CHECK(ta == b.modelled(request, {}));
        CHECK(ta >= microseconds{8000});
        CHECK(ta <= microseconds{12000});
        if (ta != c.modelled(request, {})) differs = true;
    }
    CHECK(differs);
}

TEST_CASE("monitoring timer: units of 250 ms, 0 = forever, binary and ASCII", "[timing]") {
    slmp::station::Station station(config::load_profile("R08CPU"), {});
    protocol::client::FrameOptions o;
    o.monitoring_timer = 0x0004;
    auto frame = protocol::client::read_words(o, at("D0"), 1);
    CHECK(ResponseTiming::monitoring_timer(decoded(station, frame), frame) == milliseconds{1000});
    o.codec = protocol::Codec::Ascii;
    o.monitoring_timer = 0x0010;
    frame = protocol::client::read_words(o, at("D0"), 1);
    CHECK(ResponseTiming::monitoring_timer(decoded(station, frame), frame) == milliseconds{4000});
    o.monitoring_timer = 0;
    frame = protocol::client::read_words(o, at("D0"), 1);
    CHECK(ResponseTiming::monitoring_timer(decoded(station, frame), frame) == milliseconds{0});
}

TEST_CASE("timing configuration: mode, constants over the profile's, errors name the key", "[timing][config]") {
    auto c = config::parse_server_config(R"({"timing": {"mode": "model", "ke_ms": 5, "kdt_ascii_ms": 0.01, "jitter": 0.1, "seed": 7}})",
                                         "t.json");
    CHECK(c.timing.mode == config::TimingMode::Model);
    CHECK(c.timing.jitter == 0.1);
    CHECK(c.timing.seed == 7);
    auto m = c.timing.model.over(config::TimingModel{});
    CHECK(m.ke_binary_ms == 5);
    CHECK(m.ke_ascii_ms == 5);
    CHECK(m.kdt_binary_ms == 0.003);   // the profile's, not named
    CHECK(m.kdt_ascii_ms == 0.01);
    CHECK(config::parse_server_config("{}", "t.json").timing.mode == config::TimingMode::Instant);
    CHECK_THROWS_WITH(config::parse_server_config(R"({"timing": {"mode": "fast"}})", "t.json"),
                      "t.json: /timing/mode: unknown timing mode 'fast'; use \"instant\" (default), \"end_of_scan\" or \"model\"");
    CHECK_THROWS_WITH(config::parse_server_config(R"({"timing": {"jitter": 2}})", "t.json"), Catch::Contains("/timing/jitter"));
    CHECK_THROWS_WITH(config::parse_server_config(R"({"timing": {"ke": 2}})", "t.json"), Catch::Contains("ke"));
    // A profile's own constants.
    auto p = config::parse_profile(R"({"extends": "R08CPU", "name": "SLOW", "description": "a slow CPU", "timing": {"ke_ms": 20, "scan_wait": false}})", "slow.json");
    CHECK(p.timing.ke_binary_ms == 20);
    CHECK(p.timing.kdt_binary_ms == 0.003);
    CHECK_FALSE(p.timing.scan_wait);
    CHECK(config::load_profile("R08CPU").timing.ke_binary_ms == 3.9);
}

TEST_CASE("monitoring timer of a 1E frame: the header's field after the PC No., binary and ASCII", "[timing][1E]") {
    slmp::station::Station station(config::load_profile("Q06UDVCPU-QJ71E71"), {});
    const Bytes binary = {0x01, 0xFF, 0x04, 0x00, 0x00, 0x00, 0x00, 0x00, 0x20, 0x44, 0x01, 0x00};   // D0 x1, timer 4
    CHECK(ResponseTiming::monitoring_timer(decoded(station, binary), binary) == milliseconds{1000});
    const auto ascii = text("01FF0010" "4420" "00000000" "0100");   // timer 0010 = 16
    CHECK(ResponseTiming::monitoring_timer(decoded(station, ascii), ascii) == milliseconds{4000});
}

TEST_CASE("end_of_scan: served at the END unless the monitoring timer ran out first", "[timing]") {
    using slmp::station::Station;
    using namespace std::chrono_literals;
    const auto t0 = std::chrono::steady_clock::time_point{} + 1s;
    // Before the END it waits, until its timer has run out: then CF71 at the timer's time.
    CHECK_FALSE(Station::end_of_scan_service(t0, 250ms, t0 + 249ms, false));
    auto s = Station::end_of_scan_service(t0, 250ms, t0 + 250ms, false);
    REQUIRE(s);
    CHECK(s->timed_out);
    CHECK(s->at == t0 + 250ms);
    // At the END: in time (also exactly at the timer), or too late.
    s = Station::end_of_scan_service(t0, 250ms, t0 + 250ms, true);
    REQUIRE(s);
    CHECK_FALSE(s->timed_out);
    s = Station::end_of_scan_service(t0, 250ms, t0 + 251ms, true);
    REQUIRE(s);
    CHECK(s->timed_out);
    // Timer 0 waits for ever; a request that arrived after the END it is served at is in time.
    CHECK_FALSE(Station::end_of_scan_service(t0, 0ms, t0 + 10s, false));
    s = Station::end_of_scan_service(t0, 0ms, t0 + 10s, true);
    REQUIRE(s);
    CHECK_FALSE(s->timed_out);
    s = Station::end_of_scan_service(t0, 250ms, t0 - 1ms, true);
    REQUIRE(s);
    CHECK_FALSE(s->timed_out);
}
