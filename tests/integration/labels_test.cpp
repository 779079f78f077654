// Global labels against the real binary (docs/labels.md): a configuration with
// every kind of label, written and read with 141B/041C and 141A/041A over TCP
// and UDP in all four frame shapes, the device view checked with 0401, the
// non-external label refused with 40C0, and --labels FILE.
#include <catch2/catch.hpp>

#include "frames.hpp"
#include "http_client.hpp"
#include "link.hpp"
#include "protocol/client_labels.hpp"
#include "cli_support.hpp"
#include "sim_process.hpp"

using namespace slmp::test;
namespace client = slmp::protocol::client;
using slmp::devicemodel::BasicType;

namespace {

const char* kLabels = R"J({
  "structures": [
    {"name": "Valve", "members": [{"name": "Open", "type": "Bit"}, {"name": "Pos", "type": "INT"}]},
    {"name": "TankT", "members": [{"name": "Level", "type": "REAL"}, {"name": "V", "type": "Valve", "dims": [2]},
                                  {"name": "Delay", "type": "Timer"}]}],
  "labels": [
    {"name": "LabelB", "type": "Bit", "device": "M100"},
    {"name": "LabelW", "type": "Word [Signed]", "device": "D9000"},
    {"name": "LabelD", "type": "Double Word [Unsigned]/Bit String [32-bit]", "device": "D9002"},
    {"name": "Speed", "type": "FLOAT [Single Precision]"},
    {"name": "Title", "type": "String(8)", "device": "D9010"},
    {"name": "UTitle", "type": "String [Unicode](4)"},
    {"name": "Delay", "type": "Time"},
    {"name": "DDD", "type": "Word [Signed]", "dims": [20], "device": "D9100"},
    {"name": "Grid", "type": "INT(0..1,0..2)"},
    {"name": "Cube", "type": "DINT", "dims": [2, 2, 2]},
    {"name": "Tank1", "type": "TankT"},
    {"name": "T1", "type": "Timer", "device": "T5"},
    {"name": "Hidden", "type": "Bit", "external": false}]})J";

const std::vector<Wire> kWires = {
    {FrameKind::E3, Codec::Binary, 0},
    {FrameKind::E3, Codec::Ascii, 0},
    {FrameKind::E4, Codec::Binary, 0x0102},
    {FrameKind::E4, Codec::Ascii, 0xFEDC},
};

client::Response ask(Link& link, const Bytes& request) {
    auto reply = link.exchange(request);
    auto parsed = client::parse_response(reply);
    REQUIRE(parsed);
    return *parsed;
}

void labels_round_trip(Link& link) {
    for (const auto& w : kWires) {
        INFO(link.name() << ", " << w.name());
        const auto o = w.options();
        const std::vector<client::LabelWrite> writes = {
            {"LabelB", {BasicType::Bit, {1}}},
            {"LabelW", {BasicType::Word, {0x8001}}},
            {"LabelD", {BasicType::UDWord, {0x5678, 0x1234}}},
            {"Speed", {BasicType::Real, {0x0000, 0x3FC0}}},
            {"Title", {BasicType::String, {0x4241, 0x0043, 0, 0, 0}}},        // "ABC"
            {"UTitle", {BasicType::WString, {0x30C6, 0x30B9, 0x0054, 0, 0}}},   // "テスT"
            {"Delay", {BasicType::Time, {0xFFFF, 0x7FFF}}},
            {"Grid[1,2]", {BasicType::Word, {6}}},
            {"Cube[1,1,1]", {BasicType::DWord, {7, 0}}},
            {"Tank1.V[1].Pos", {BasicType::Word, {42}}},
            {"Tank1.V[1].Open", {BasicType::Bit, {1}}},
            {"Tank1.Delay.N", {BasicType::UWord, {300}}},
            {"T1.N", {BasicType::UWord, {12}}},
        };
        auto wrote = ask(link, client::label_write_random(o, writes));
        REQUIRE(wrote.end_code == 0);
        std::vector<std::string> names;
        for (const auto& e : writes) names.push_back(e.name);
        auto read = ask(link, client::label_read_random(o, names));
        REQUIRE(read.end_code == 0);
        auto data = client::decode_label_read(read, false);
        REQUIRE(data);
        REQUIRE(data->size() == writes.size());
        for (std::size_t i = 0; i < writes.size(); ++i) {
            INFO(writes[i].name);
            CHECK((*data)[i].type_id == static_cast<std::uint8_t>(writes[i].value.type));
            REQUIRE((*data)[i].elements.size() == 1);
            CHECK((*data)[i].elements[0] == writes[i].value.words);
        }
        // The device view: D9000 (LabelW), D9002-D9003 (LabelD), D9010 (Title), M100, TN5.
        CHECK(show(link.exchange(client::read_words(o, addr("D9000"), 4))) ==
              show(expected_response(w, word_data(w, {0x8001, 0, 0x5678, 0x1234}))));
        CHECK(show(link.exchange(client::read_words(o, addr("D9010"), 2))) ==
              show(expected_response(w, word_data(w, {0x4241, 0x0043}))));
        CHECK(show(link.exchange(client::read_bits(o, addr("M100"), 1))) == show(expected_response(w, bit_data(w, {1}))));
        CHECK(show(link.exchange(client::read_words(o, addr("TN5"), 1))) == show(expected_response(w, word_data(w, {12}))));

        // 141A / 041A: DDD[5..7] on D9105-D9107, then 1401 to D9108 read back as DDD[8].
        std::vector<client::ArrayWrite> arrays = {{"DDD[5]", BasicType::Word, {{1}, {2}, {3}}}};
        REQUIRE(ask(link, client::array_label_write(o, arrays)).end_code == 0);
        CHECK(show(link.exchange(client::read_words(o, addr("D9105"), 3))) ==
              show(expected_response(w, word_data(w, {1, 2, 3}))));
        std::vector<std::uint16_t> nine = {9};
        REQUIRE(ask(link, client::write_words(o, addr("D9108"), nine)).end_code == 0);
        std::vector<client::ArrayRead> reads = {{"DDD[5]", false, 8}, {"Cube[0,0,0]", false, 32}};
        auto arr = ask(link, client::array_label_read(o, reads));
        REQUIRE(arr.end_code == 0);
        auto decoded = client::decode_label_read(arr, true);
        REQUIRE(decoded);
        REQUIRE(decoded->size() == 2);
        CHECK((*decoded)[0].elements == std::vector<std::vector<std::uint16_t>>{{1}, {2}, {3}, {9}});
        CHECK((*decoded)[1].type_id == 5);
        CHECK((*decoded)[1].elements.back() == std::vector<std::uint16_t>{7, 0});

        // Not external: 40C0, and a refused write changes nothing.
        auto hidden = ask(link, client::label_read_random(o, std::vector<std::string>{"Hidden"}));
        CHECK(hidden.end_code == 0x40C0);
        std::vector<client::LabelWrite> bad = {{"LabelW", {BasicType::Word, {1}}}, {"Hidden", {BasicType::Bit, {1}}}};
        CHECK(ask(link, client::label_write_random(o, bad)).end_code == 0x40C0);
        CHECK(show(link.exchange(client::read_words(o, addr("D9000"), 1))) ==
              show(expected_response(w, word_data(w, {0x8001}))));
    }
}

SimOptions labelled() {
    SimOptions options;
    options.config_json = kLabels;
    return options;
}

}  // namespace

TEST_CASE("labels over TCP: every kind, both command pairs, four frame shapes", "[labels][tcp]") {
    SimProcess sim(labelled());
    TcpLink link(sim.tcp_port());
    labels_round_trip(link);
}

TEST_CASE("labels over UDP: every kind, both command pairs, four frame shapes", "[labels][udp]") {
    SimProcess sim(labelled());
    UdpLink link(sim.udp_port());
    labels_round_trip(link);
}

TEST_CASE("labels from a file given with --labels, and a mistake in it stops start-up naming the file and pointer", "[labels][cli]") {
    TempDir dir;
    auto file = dir.write("labels.json", R"J({"labels": [{"name": "LabelW", "type": "INT", "device": "D9000"}]})J");
    {
        SimProcess sim(with_args({"--labels", file.string()}));
        TcpLink link(sim.tcp_port());
        const Wire w{FrameKind::E3, Codec::Binary, 0};
        std::vector<client::LabelWrite> writes = {{"LabelW", {BasicType::Word, {5}}}};
        REQUIRE(ask(link, client::label_write_random(w.options(), writes)).end_code == 0);
        CHECK(show(link.exchange(client::read_words(w.options(), addr("D9000"), 1))) ==
              show(expected_response(w, word_data(w, {5}))));
    }
    auto bad = dir.write("bad.json", R"J({"labels": [{"name": "A", "type": "INTEGER"}]})J");
    auto result = run_sim({"--labels", bad.string(), "--tcp-port", "0", "--udp-port", "0", "--no-http"});
    CHECK(result.exit_code == 2);
    CHECK_THAT(result.err, Catch::Contains(bad.string() + ": /labels/0/type: unknown data type 'INTEGER'"));
}

TEST_CASE("HTTP: GET /api/labels lists them, GET/PUT /api/labels/{name} share memory with SLMP", "[labels][http]") {
    using nlohmann::json;
    SimProcess sim(labelled());
    auto list = http_get(sim.http_port(), "/api/labels").json();
    REQUIRE(list["labels"].size() == 13);
    CHECK(list["labels"][1] == json{{"name", "LabelW"}, {"type", "Word [Signed]"}, {"device", "D9000"},
                                    {"external", true}, {"words", 1}});
    CHECK(list["labels"][12]["external"] == false);
    CHECK(list["structures"][0]["name"] == "Valve");

    auto put = http_put(sim.http_port(), "/api/labels/DDD%5B2%5D", R"J({"values": [5, -6]})J");
    REQUIRE(put.status == 200);
    CHECK(put.json() == json{{"name", "DDD[2]"}, {"type", "Word [Signed]"}, {"values", {5, -6}}});
    CHECK(http_put(sim.http_port(), "/api/labels/Title", R"J({"string": "Hi"})J").status == 200);
    CHECK(http_put(sim.http_port(), "/api/labels/Speed", R"J({"values": [2.5]})J").status == 200);
    // The same memory over SLMP: DDD[2..3] are D9102-D9103.
    TcpLink link(sim.tcp_port());
    const Wire w{FrameKind::E3, Codec::Binary, 0};
    CHECK(show(link.exchange(client::read_words(w.options(), addr("D9102"), 2))) ==
          show(expected_response(w, word_data(w, {5, 0xFFFA}))));
    CHECK(http_get(sim.http_port(), "/api/labels/Speed").json()["values"] == json{2.5});
    CHECK(http_get(sim.http_port(), "/api/labels/Title").json()["values"] == json{"Hi"});
    CHECK(http_get(sim.http_port(), "/api/labels/Hidden").status == 200);   // the API reaches it
    // Refused: nothing written.
    CHECK(http_get(sim.http_port(), "/api/labels/Nope").status == 404);
    CHECK(http_put(sim.http_port(), "/api/labels/LabelW", R"J({"values": [40000]})J").status == 400);
    CHECK(http_put(sim.http_port(), "/api/labels/DDD%5B19%5D", R"J({"values": [1, 2]})J").status == 400);
    CHECK(http_get(sim.http_port(), "/api/labels/DDD%5B19%5D").json()["values"] == json{0});
}

TEST_CASE("slmp label write/read: the CLI asks the type, then writes and reads by name", "[labels][cli]") {
    SimProcess sim(labelled());
    for (const auto& variant : {std::vector<std::string>{}, std::vector<std::string>{"--ascii", "--4e"}}) {
        auto base = target(sim.tcp_port()) + variant;
        auto w = run_cli(base + std::vector<std::string>{"label", "write", "LabelW", "5"});
        INFO(w.err);
        REQUIRE(w.exit_code == 0);
        REQUIRE(run_cli(base + std::vector<std::string>{"label", "write", "DDD[0]", "1", "-2", "3"}).exit_code == 0);
        REQUIRE(run_cli(base + std::vector<std::string>{"label", "write", "Title", "Hello"}).exit_code == 0);
        REQUIRE(run_cli(base + std::vector<std::string>{"label", "write", "Speed", "1.5"}).exit_code == 0);
        auto json = json_of(run_cli(base + std::vector<std::string>{"--json", "label", "read", "LabelW", "DDD[0]:3",
                                                                    "Title", "Speed"}));
        CHECK(json["values"] == nlohmann::json::parse(R"J([
            {"label": "LabelW", "type": "Word [Signed]", "value": 5},
            {"label": "DDD[0]", "type": "Word [Signed]", "value": 1},
            {"label": "DDD[0]+1", "type": "Word [Signed]", "value": -2},
            {"label": "DDD[0]+2", "type": "Word [Signed]", "value": 3},
            {"label": "Title", "type": "String", "value": "Hello"},
            {"label": "Speed", "type": "FLOAT [Single Precision]", "value": 1.5}])J"));
        // A value out of the type's range is a usage error (exit 2); a hidden label is the PLC's 40C0 (exit 1).
        CHECK(run_cli(base + std::vector<std::string>{"label", "write", "LabelW", "40000"}).exit_code == 2);
        auto hidden = run_cli(base + std::vector<std::string>{"label", "read", "Hidden"});
        CHECK(hidden.exit_code == 1);
        CHECK_THAT(hidden.err, Catch::Contains("40C0"));
    }
}
