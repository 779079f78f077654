// GET /api/events against the real binary: request summaries and device
// writes made over SLMP (binary and ASCII) or the API, connection changes,
// and the types filter.
#include <catch2/catch.hpp>

#include <string>
#include <vector>

#include "frames.hpp"
#include "http_client.hpp"
#include "link.hpp"
#include "sim_process.hpp"
#include "sockets.hpp"

using namespace slmp::test;
namespace client = slmp::protocol::client;
using nlohmann::json;

TEST_CASE("events: SLMP requests and the device writes they make, binary and ASCII", "[http][events]") {
    SimProcess sim;
    EventReader events(sim.http_port());
    CHECK(events.head().status == 200);
    CHECK(events.head().header("content-type") == "text/event-stream");

    TcpLink link(sim.tcp_port());
    for (const auto& w : {Wire{FrameKind::E3, Codec::Binary, 0}, Wire{FrameKind::E4, Codec::Ascii, 7}}) {
        INFO(w.name());
        // Different values each time: only changes are reported.
        std::vector<std::uint16_t> values = w.codec == Codec::Binary ? std::vector<std::uint16_t>{1, 2, 3}
                                                                      : std::vector<std::uint16_t>{4, 5, 6};
        auto request = client::write_words(w.options(), addr("D100"), values);
        REQUIRE(show(link.exchange(request)) == show(expected_response(w, {})));

        auto call = events.next_of("request").data;
        CHECK(call["command"] == "1401");
        CHECK(call["subcommand"] == "0000");
        CHECK(call["name"] == "Device Write (word units, Q form)");
        CHECK(call["device"] == "D100");
        CHECK(call["points"] == 3);
        CHECK(call["unit"] == "words");
        CHECK(call["end_code"] == "0000");
        CHECK(call["reaction"] == "answered");
        CHECK(call["transport"] == "tcp");
        CHECK(call["bytes_in"] == request.size());
        CHECK(call["bytes_out"] == expected_response(w, {}).size());
        CHECK(call["latency_us"].get<double>() >= 0);
        CHECK(call["note"] == "");

        auto write = events.next_of("devices").data;
        CHECK(write["device"] == "D100");
        CHECK(write["count"] == 3);
        CHECK(write["values"] == json(values));
        CHECK(write["source"] == "slmp");
        CHECK(write["peer"] == call["peer"]);
    }

    // A rejected request: its end code, its reason, and no device event.
    link.exchange(client::read_words(Wire{}.options(), addr("D10239"), 2));
    auto rejected = events.next_of("request").data;
    CHECK(rejected["end_code"] == "4031");
    CHECK(rejected["device"] == "D10239");
    CHECK(rejected["note"].get<std::string>().rfind("4031", 0) == 0);

    // A write that stores what is there already is no change: the next
    // devices event is the bit write after it.
    link.exchange(client::write_words(Wire{}.options(), addr("D100"), std::vector<std::uint16_t>{4, 5, 6}));
    // Bit writes come as one run of bit values.
    link.exchange(client::write_bits(Wire{}.options(), addr("M5"), std::vector<std::uint8_t>{1, 1, 1}));
    auto bits = events.next_of("devices").data;
    CHECK(bits["device"] == "M5");
    CHECK(bits["values"] == json{1, 1, 1});
}

TEST_CASE("events: API writes, the types filter and connection changes", "[http][events]") {
    SimProcess sim;
    SECTION("an API write is a devices event with source api") {
        EventReader events(sim.http_port(), "?types=devices");
        REQUIRE(http_put(sim.http_port(), "/api/devices/D7", R"({"values": [42]})").status == 200);
        auto write = events.next_of("devices").data;
        CHECK(write["device"] == "D7");
        CHECK(write["values"] == json{42});
        CHECK(write["source"] == "api");
        CHECK_FALSE(write.contains("peer"));
    }
    SECTION("types=devices leaves the request summaries out") {
        EventReader events(sim.http_port(), "?types=devices");
        TcpLink link(sim.tcp_port());
        link.exchange(client::write_words(Wire{}.options(), addr("D9"), std::vector<std::uint16_t>{5}));
        // The request event would come first; with the filter the first event is the write.
        auto first = events.next_external();
        REQUIRE(first);
        CHECK(first->type == "devices");
    }
    SECTION("connections opening and closing") {
        EventReader events(sim.http_port(), "?types=connection");
        std::uint64_t id = 0;
        {
            TcpLink link(sim.tcp_port());
            auto opened = events.next_of("connection").data;
            CHECK(opened["event"] == "opened");
            CHECK(opened["port"] == sim.tcp_port());
            id = opened["id"].get<std::uint64_t>();
        }
        auto closed = events.next_of("connection").data;
        CHECK(closed["event"] == "closed");
        CHECK(closed["id"] == id);
        CHECK(closed["why"] == "closed by the client");
    }
    SECTION("an unknown type is a 400") {
        auto r = http_get(sim.http_port(), "/api/events?types=devices,calls");
        CHECK(r.status == 400);
        CHECK(r.error() == "unknown event type 'calls'; use request, devices, connection and/or compare, comma-separated");
    }
}
