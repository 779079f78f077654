// Own network and station numbers (issue 13): a port whose station is set to
// network 1-239 / station 1-120 serves requests addressed to those numbers as
// the own station, besides 00/FF; other stations get the route codes chosen in
// docs/end-codes.md (another network 4A01, another station 4A02).
#include "support/fixtures.hpp"

using namespace slmp;
using namespace slmp::test;

namespace {

// One request through an engine whose port is set to network 0x12 station 0x05.
std::string exchange_numbered(devicemodel::Cpu& cpu, const Wire& wire, const Payload& p, Route route) {
    protocol::Session session;
    session.own = {0x12, 0x05};
    auto engine = engine_for(cpu);
    return wire.show(engine.process(wire.request(p, route), DataCodePolicy::Auto, session));
}

}  // namespace

TEST_CASE("own network and station numbers (decode.cpp check_route)", "[errors][route]") {
    auto cpu = make_cpu("Q06UDVCPU-QJ71E71");
    cpu.memory().set_value(*devicemodel::parse_address("D100")->spec, 100, 0x1234);
    auto wire = GENERATE(kBinary3E, kBinary4E, kAscii3E, kAscii4E);
    const auto read = read_words_req(Form::Q, "D100", 1);
    SECTION("network 12 station 05 is the own station; the route is echoed") {
        Route own{0x12, 0x05, 0x03FF, 0x00};
        CHECK(exchange_numbered(cpu, wire, read, own) == wire.expect(ok(words({0x1234})), own));
    }
    SECTION("00/FF is still the own station") {
        CHECK(exchange_numbered(cpu, wire, read, {}) == wire.expect(ok(words({0x1234}))));
    }
    SECTION("another station on the own network -> 4A02") {
        for (std::uint8_t station : {0x01, 0x06, 0x78, 0xFF}) {
            Route r{0x12, station, 0x03FF, 0x00};
            CHECK(exchange_numbered(cpu, wire, read, r) == wire.expect(error(0x4A02, 0x0401, 0x0000, r), r));
        }
    }
    SECTION("another network -> 4A01") {
        Route r{0x13, 0x05, 0x03FF, 0x00};
        CHECK(exchange_numbered(cpu, wire, read, r) == wire.expect(error(0x4A01, 0x0401, 0x0000, r), r));
    }
    SECTION("network 00 with the own station No. (not FF) -> 4A02") {
        Route r{0x00, 0x05, 0x03FF, 0x00};
        CHECK(exchange_numbered(cpu, wire, read, r) == wire.expect(error(0x4A02, 0x0401, 0x0000, r), r));
    }
    SECTION("without numbers set, network 12 station 05 is another network -> 4A01") {
        Route r{0x12, 0x05, 0x03FF, 0x00};
        CHECK(wire.exchange(cpu, read, r) == wire.expect(error(0x4A01, 0x0401, 0x0000, r), r));
    }
}

TEST_CASE("station numbers in the configuration: range checks name the key", "[config][route]") {
    auto c = config::parse_server_config(R"({"ports":[{"transport":"tcp","port":5000,"network":1,"station":120}]})", "t.json");
    CHECK(c.ports.front().numbers == protocol::StationNumbers{1, 120});
    CHECK_THROWS_WITH(config::parse_server_config(R"({"ports":[{"transport":"tcp","port":5000,"network":240,"station":1}]})",
                                                  "t.json"),
                      Catch::Contains("/ports/0") && Catch::Contains("1-239"));
    CHECK_THROWS_WITH(config::parse_server_config(R"({"ports":[{"transport":"tcp","port":5000,"network":1}]})", "t.json"),
                      Catch::Contains("1-120"));
}
