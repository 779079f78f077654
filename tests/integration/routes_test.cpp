// Networks in a plant (docs/plants.md, "Networks and routes"): a request sent
// to an Ethernet module's port with another network/station in its route is
// served by that station's CPU and answered exactly as that CPU answers its
// own clients, with the route echoed. Each routed answer is compared byte for
// byte with the answer a twin station (same profile and labels, on no network)
// gives the same request sent to its own port.
#include <catch2/catch.hpp>

#include <functional>
#include <thread>

#include "ask.hpp"
#include "frames.hpp"
#include "protocol/client.hpp"
#include "protocol/client_commands.hpp"
#include "protocol/client_files.hpp"
#include "protocol/client_labels.hpp"
#include "plant_ports.hpp"
#include "sim_process.hpp"
#include "sockets.hpp"

using namespace slmp::test;
namespace client = slmp::protocol::client;
using slmp::protocol::Codec;
using slmp::protocol::DeviceForm;
using slmp::protocol::FrameKind;
using slmp::protocol::Route;

namespace {

const char* kLabels = R"("labels": [{"name": "LabelW", "type": "Word [Signed]", "device": "D9000"},
                                    {"name": "DDD", "type": "Word [Signed]", "dims": [8]}])";

// gw: the line's Ethernet module (station 1 of network 1); press, welder
// (network 1's master) and relay on network 1; packer on network 2 behind
// relay. Each CPU has a twin on no network.
std::string line_plant() {
    auto cpu = [](const std::string& name, const std::string& networks) {
        return R"({"name": ")" + name + R"(", "profile": "R08CPU", "tcp_port": 0, "udp_port": 0, )" + kLabels +
               R"(, "networks": [)" + networks + "]}";
    };
    return R"({"bind": "127.0.0.1", "http": {"enabled": false}, "stations": [
        {"name": "gw", "profile": "RJ71EN71", "tcp_port": 0, "udp_port": 0, "networks": [{"number": 1, "station": 1}]},)" +
           cpu("press", R"({"number": 1, "station": 2})") + "," +
           cpu("welder", R"({"number": 1, "station": 3, "master": true})") + "," +
           cpu("relay", R"({"number": 1, "station": 4}, {"number": 2, "station": 1})") + "," +
           cpu("packer", R"({"number": 2, "station": 3})") + "," + cpu("press-twin", "") + "," + cpu("welder-twin", "") + "," +
           cpu("relay-twin", "") + "," + cpu("packer-twin", "") + "]}";
}



// A route's fields as they travel (§3.1.3-§3.1.5), and where they sit in an answer.
Bytes route_bytes(const Route& r, Codec codec) {
    slmp::protocol::FieldWriter w(codec);
    w.u8(r.network);
    w.u8(r.station);
    w.u16(r.module_io);
    w.u8(r.multidrop);
    return w.bytes();
}
std::size_t route_offset(FrameKind kind, Codec codec) {
    const std::size_t subheader = kind == FrameKind::E4 ? 6 : 2;
    return codec == Codec::Ascii ? subheader * 2 : subheader;
}
// The twin's answer as the routed station gives it: the route in the header,
// and in an error answer's error information, is the request's.
Bytes with_route(Bytes answer, FrameKind kind, Codec codec, const Route& route) {
    const auto own = route_bytes(Route{}, codec);
    const auto routed = route_bytes(route, codec);
    const auto at = route_offset(kind, codec);
    const std::size_t unit = codec == Codec::Ascii ? 2 : 1;
    auto replace = [&](std::size_t offset) {
        if (answer.size() >= offset + own.size() && std::equal(own.begin(), own.end(), answer.begin() + offset))
            std::copy(routed.begin(), routed.end(), answer.begin() + offset);
    };
    replace(at);
    const std::size_t end_code_at = at + own.size() + 2 * unit;
    const bool error = answer.size() > end_code_at + 2 * unit &&
                       !std::all_of(answer.begin() + end_code_at, answer.begin() + end_code_at + 2 * unit,
                                    [&](std::uint8_t b) { return b == (codec == Codec::Ascii ? '0' : 0); });
    if (error) replace(end_code_at + 2 * unit);
    return answer;
}

using Builder = std::function<Bytes(const client::FrameOptions&)>;

// Every device, label and file command, in the order a client would send them.
std::vector<std::pair<std::string, Builder>> every_command() {
    using DA = slmp::devicemodel::DeviceAddress;
    std::vector<std::pair<std::string, Builder>> list;
    auto add = [&](std::string name, Builder b) { list.emplace_back(std::move(name), std::move(b)); };
    const std::vector<std::uint16_t> words{0x1234, 0x5678, 0x9ABC};
    const std::vector<std::uint8_t> bits{1, 0, 1, 1};
    add("1401 words", [=](auto& o) { return client::write_words(o, addr("D100"), words); });
    add("0401 words", [](auto& o) { return client::read_words(o, addr("D100"), 3); });
    add("1401 bits", [=](auto& o) { return client::write_bits(o, addr("M10"), bits); });
    add("0401 bits", [](auto& o) { return client::read_bits(o, addr("M10"), 4); });
    add("1401 iQ-R words", [=](auto& o) { return client::write_words(o, addr("D200"), words, DeviceForm::IQR); });
    add("0401 iQ-R words", [](auto& o) { return client::read_words(o, addr("D200"), 3, DeviceForm::IQR); });
    add("0401 past the end", [](auto& o) { return client::read_words(o, addr("D65535"), 1); });
    add("1402 words", [](auto& o) {
        std::vector<client::WordWrite> w{{addr("D300"), 7}};
        std::vector<client::DwordWrite> d{{addr("D302"), 0x11223344}};
        return client::write_random_words(o, w, d);
    });
    add("1402 bits", [](auto& o) {
        std::vector<client::BitWrite> b{{addr("M20"), true}, {addr("Y5"), true}};
        return client::write_random_bits(o, b);
    });
    add("0403", [](auto& o) {
        std::vector<DA> w{addr("D300"), addr("D100")};
        std::vector<DA> d{addr("D302")};
        return client::read_random(o, w, d);
    });
    add("1406", [](auto& o) {
        return client::build_request(o, 0x1406, 0x0000, [](slmp::protocol::FieldWriter& w) {
            w.u8(1);
            w.u8(1);
            w.device(DeviceForm::Q, addr("D400"));
            w.u16(2);
            const std::vector<std::uint16_t> v{0xAAAA, 0x5555};
            w.words(v);
            w.device(DeviceForm::Q, addr("M32"));
            w.u16(1);
            const std::vector<std::uint16_t> m{0x0005};
            w.words(m);
        });
    });
    add("0406", [](auto& o) {
        return client::build_request(o, 0x0406, 0x0000, [](slmp::protocol::FieldWriter& w) {
            w.u8(1);
            w.u8(1);
            w.device(DeviceForm::Q, addr("D400"));
            w.u16(2);
            w.device(DeviceForm::Q, addr("M32"));
            w.u16(1);
        });
    });
    add("0801", [](auto& o) {
        return client::build_request(o, 0x0801, 0x0000, [](slmp::protocol::FieldWriter& w) {
            w.u8(2);
            w.u8(0);
            w.device(DeviceForm::Q, addr("D100"));
            w.device(DeviceForm::Q, addr("D300"));
        });
    });
    add("0802", [](auto& o) { return client::build_request(o, 0x0802, 0x0000); });
    add("0101", [](auto& o) { return client::read_type_name(o); });
    add("141B", [](auto& o) {
        std::vector<client::LabelWrite> w{{"LabelW", {slmp::devicemodel::BasicType::Word, {0x0055}}}};
        return client::label_write_random(o, w);
    });
    add("041C", [](auto& o) {
        std::vector<std::string> names{"LabelW", "DDD[1]"};
        return client::label_read_random(o, names);
    });
    add("141A", [](auto& o) {
        std::vector<client::ArrayWrite> w{{"DDD[0]", slmp::devicemodel::BasicType::Word, {{1}, {2}, {3}}}};
        return client::array_label_write(o, w);
    });
    add("041A", [](auto& o) {
        std::vector<client::ArrayRead> r{{"DDD[0]", false, 6}};
        return client::array_label_read(o, r);
    });
    add("041C unknown label", [](auto& o) {
        std::vector<std::string> names{"NoSuchLabel"};
        return client::label_read_random(o, names);
    });
    const client::FileTarget file{true, 4, "ROUTED.CSV", ""};
    add("1820", [=](auto& o) { return client::file_new(o, file, 64); });
    add("1827 write", [=](auto& o) { return client::file_open(o, file, true); });
    add("1829", [](auto& o) {
        const std::vector<std::uint8_t> data{'a', 'b', 'c', 'd'};
        return client::file_write(o, 0, 0, data);
    });
    add("182A", [](auto& o) { return client::file_close(o, 0, 0); });
    add("1811", [=](auto& o) { return client::file_search(o, file); });
    add("1827 read", [=](auto& o) { return client::file_open(o, file, false); });
    add("1828", [](auto& o) { return client::file_read(o, 0, 0, 4); });
    add("182A again", [](auto& o) { return client::file_close(o, 0, 0); });
    add("1822", [=](auto& o) { return client::file_delete(o, file); });
    add("1822 again", [=](auto& o) { return client::file_delete(o, file); });
    return list;
}

struct Shape {
    FrameKind kind;
    Codec codec;
    const char* name;
};
constexpr Shape kShapes[] = {{FrameKind::E3, Codec::Binary, "3E binary"},
                             {FrameKind::E3, Codec::Ascii, "3E ASCII"},
                             {FrameKind::E4, Codec::Binary, "4E binary"},
                             {FrameKind::E4, Codec::Ascii, "4E ASCII"}};

client::FrameOptions options(const Shape& shape, Route route) {
    client::FrameOptions o;
    o.kind = shape.kind;
    o.codec = shape.codec;
    o.serial = 0x1234;
    o.route = route;
    return o;
}

Route route_to(std::uint8_t network, std::uint8_t station, std::uint16_t module_io = 0x03FF) {
    return Route{network, station, module_io, 0x00};
}

// 0401 of D100 ×1, 3E binary, with a route: the error answers below quote it.
Bytes read_d100(const Route& route) {
    client::FrameOptions o;
    o.route = route;
    return client::read_words(o, addr("D100"), 1);
}

}  // namespace

TEST_CASE("routes: every device, label and file command through the Ethernet module reaches the routed CPU, byte-exact",
          "[route][plant]") {
    SimProcess sim(plant_options(line_plant()));
    struct Target {
        const char* name;
        Route route;
        const char* twin;
    };
    const Target targets[] = {{"press", route_to(1, 2), "press-twin"},
                              {"welder (7D, the designated master)", route_to(1, 0x7D), "welder-twin"},
                              {"relay", route_to(1, 4, 0x03E0), "relay-twin"},
                              {"packer behind relay", route_to(2, 3), "packer-twin"}};
    for (const auto& target : targets) {
        auto twin = TcpClient::open(tcp_of(sim, target.twin));
        for (const auto& shape : kShapes) {
            for (const bool udp : {false, true}) {
                auto gw = TcpClient::open(tcp_of(sim, "gw"));
                UdpClient gw_udp;
                for (const auto& [name, build] : every_command()) {
                    INFO(target.name << ", " << shape.name << (udp ? " UDP" : " TCP") << ": " << name);
                    const auto routed = build(options(shape, target.route));
                    const auto answer = udp ? ask(gw_udp, udp_of(sim, "gw"), routed) : ask(gw, routed);
                    const auto direct = ask(twin, build(options(shape, Route{})));
                    CHECK(show(answer) == show(with_route(direct, shape.kind, shape.codec, target.route)));
                }
            }
        }
    }
    // The writes landed in the routed CPUs only: the Ethernet module's own CPU
    // was never written, and packer's D100 is what the routes wrote.
    auto gw = TcpClient::open(tcp_of(sim, "gw"));
    CHECK(show(ask(gw, read_d100(Route{}))) == show(hex("D0 00 00 FF FF 03 00 04 00 00 00 00 00")));
    auto packer = TcpClient::open(tcp_of(sim, "packer"));
    CHECK(show(ask(packer, read_d100(Route{}))) == show(hex("D0 00 00 FF FF 03 00 04 00 00 00 34 12")));
}

TEST_CASE("routes: unreachable network or station, another CPU number, a built-in port asked for another station",
          "[route][plant]") {
    SimProcess sim(plant_options(line_plant()));
    auto gw = TcpClient::open(tcp_of(sim, "gw"));
    // Network 3 is on no station's module: 4A01.
    CHECK(show(ask(gw, read_d100(route_to(3, 2)))) ==
          show(hex("D0 00 03 02 FF 03 00 0B 00 01 4A 03 02 FF 03 00 01 04 00 00")));
    // Network 1 has no station 9: 4A02.
    CHECK(show(ask(gw, read_d100(route_to(1, 9)))) ==
          show(hex("D0 00 01 09 FF 03 00 0B 00 02 4A 01 09 FF 03 00 01 04 00 00")));
    // 7E, the current master, is welder; its D100 is 0.
    CHECK(show(ask(gw, read_d100(route_to(1, 0x7E)))) == show(hex("D0 00 01 7E FF 03 00 04 00 00 00 00 00")));
    // The gateway by its own numbers is its own CPU.
    CHECK(show(ask(gw, read_d100(route_to(1, 1)))) == show(hex("D0 00 01 01 FF 03 00 04 00 00 00 00 00")));
    // Multi-CPU No.2 on a single-CPU station: the routed station answers 4B02.
    CHECK(show(ask(gw, read_d100(route_to(2, 3, 0x03E1)))) ==
          show(hex("D0 00 02 03 E1 03 00 0B 00 02 4B 02 03 E1 03 00 01 04 00 00")));
    // press's built-in port reaches only press: network 1 station 3 gets 4A01 there.
    auto press = TcpClient::open(tcp_of(sim, "press"));
    CHECK(show(ask(press, read_d100(route_to(1, 3)))) ==
          show(hex("D0 00 01 03 FF 03 00 0B 00 01 4A 01 03 FF 03 00 01 04 00 00")));
}

TEST_CASE("routes: at most 7 relay stations, the 8th answers 4A03", "[route][plant]") {
    // gw on network 1; hop-k on networks k and k+1 (k = 1..8); end-7 on
    // network 8 (7 relay stations away), end-8 on network 9 (8 away).
    std::string stations = R"({"name": "gw", "profile": "RJ71EN71", "tcp_port": 0, "networks": [{"number": 1, "station": 1}]})";
    for (int k = 1; k <= 8; ++k)
        stations += R"(, {"name": "hop-)" + std::to_string(k) + R"(", "profile": "R08CPU", "tcp_port": 0, "networks": [{"number": )" +
                    std::to_string(k) + R"(, "station": 2}, {"number": )" + std::to_string(k + 1) + R"(, "station": 3}]})";
    stations += R"(, {"name": "end-7", "profile": "R08CPU", "tcp_port": 0, "networks": [{"number": 8, "station": 9}]})";
    stations += R"(, {"name": "end-8", "profile": "R08CPU", "tcp_port": 0, "networks": [{"number": 9, "station": 9}]})";
    SimProcess sim(plant_options(R"({"bind": "127.0.0.1", "http": {"enabled": false}, "stations": [)" + stations + "]}"));
    auto gw = TcpClient::open(tcp_of(sim, "gw"));
    CHECK(show(ask(gw, read_d100(route_to(8, 9)))) == show(hex("D0 00 08 09 FF 03 00 04 00 00 00 00 00")));
    CHECK(show(ask(gw, read_d100(route_to(9, 9)))) ==
          show(hex("D0 00 09 09 FF 03 00 0B 00 03 4A 09 09 FF 03 00 01 04 00 00")));
}

TEST_CASE("routes: a routed station that does not answer gets the monitoring timer's CF71 from the module", "[route][plant]") {
    // packer drops every request (a scenario fault); the module waits the
    // request's monitoring timer (1 × 250 ms), then answers CF71.
    TempDir dir;
    const auto drop = dir.write("drop.json", R"({"stations": "packer", "faults": [{"do": "no_response"}]})");
    SimProcess sim(plant_options(R"({"bind": "127.0.0.1", "http": {"enabled": false}, "stations": [
        {"name": "gw", "profile": "RJ71EN71", "tcp_port": 0, "networks": [{"number": 1, "station": 1}]},
        {"name": "packer", "profile": "R08CPU", "tcp_port": 0, "networks": [{"number": 1, "station": 2}],
         "scenarios": [")" + drop.string() + R"("]}]})"));
    auto gw = TcpClient::open(tcp_of(sim, "gw"));
    auto request = hex("50 00 01 02 FF 03 00 0C 00 01 00 01 04 00 00 64 00 00 A8 01 00");
    CHECK(show(ask(gw, request)) == show(hex("D0 00 01 02 FF 03 00 0B 00 71 CF 01 02 FF 03 00 01 04 00 00")));
}

namespace {

// 1406/0080 (J1\W…, one word) and 0406/0080, 3E binary to the own station.
Bytes write_link_word(const std::string& device, std::uint16_t value) {
    client::FrameOptions o;
    return client::build_request(o, 0x1406, 0x0080, [&](slmp::protocol::FieldWriter& f) {
        f.u8(1);
        f.u8(0);
        f.extended_device(DeviceForm::Q, addr(device), {slmp::protocol::DeviceExtension::Kind::LinkDirect, 1});
        f.u16(1);
        f.u16(value);
    });
}
Bytes read_link_word(const std::string& device) {
    client::FrameOptions o;
    return client::build_request(o, 0x0406, 0x0080, [&](slmp::protocol::FieldWriter& f) {
        f.u8(1);
        f.u8(0);
        f.extended_device(DeviceForm::Q, addr(device), {slmp::protocol::DeviceExtension::Kind::LinkDirect, 1});
        f.u16(1);
    });
}
Bytes word_answer(std::uint16_t value) {
    return hex("D0 00 00 FF FF 03 00 04 00 00 00" + hex_digits(value & 0xFF, 2) + hex_digits(value >> 8, 2));
}

// Asks until the answer is `want` (the sender's next link scan brings it) or 5 s pass.
std::string link_value_at(TcpClient& c, const std::string& device, std::uint16_t want) {
    const auto deadline = std::chrono::steady_clock::now() + std::chrono::seconds(5);
    std::string seen;
    do {
        seen = show(ask(c, read_link_word(device)));
        if (seen == show(word_answer(want))) break;
        std::this_thread::sleep_for(std::chrono::milliseconds(10));
    } while (std::chrono::steady_clock::now() < deadline);
    return seen;
}

}  // namespace

TEST_CASE("routes: a station's send range of LW is seen at the network's other stations after its link scan",
          "[route][plant][link]") {
    // press is station 2: by default it sends J1\B100-B1FF and J1\W100-W1FF;
    // welder (station 3) sends J1\W200-W20F as configured.
    SimProcess sim(plant_options(R"({"bind": "127.0.0.1", "http": {"enabled": false}, "stations": [
        {"name": "gw", "profile": "RJ71EN71", "tcp_port": 0, "networks": [{"number": 1, "station": 1}]},
        {"name": "press", "profile": "R08CPU", "tcp_port": 0, "networks": [{"number": 1, "station": 2}]},
        {"name": "welder", "profile": "R08CPU", "tcp_port": 0, "networks": [{"number": 1, "station": 3, "send": ["W200-W20F"]}]},
        {"name": "other", "profile": "R08CPU", "tcp_port": 0, "networks": [{"number": 1}]}]})"));
    auto press = TcpClient::open(tcp_of(sim, "press"));
    auto welder = TcpClient::open(tcp_of(sim, "welder"));
    auto gw = TcpClient::open(tcp_of(sim, "gw"));
    const auto ok = show(hex("D0 00 00 FF FF 03 00 02 00 00 00"));
    CHECK(show(ask(press, write_link_word("W100", 0x1234))) == ok);
    CHECK(link_value_at(welder, "W100", 0x1234) == show(word_answer(0x1234)));
    CHECK(link_value_at(gw, "W100", 0x1234) == show(word_answer(0x1234)));
    CHECK(show(ask(welder, write_link_word("W205", 0x0BEE))) == ok);
    CHECK(link_value_at(press, "W205", 0x0BEE) == show(word_answer(0x0BEE)));
    // A station on network 1 without a station No. has the link devices but is not linked.
    auto other = TcpClient::open(tcp_of(sim, "other"));
    CHECK(show(ask(other, read_link_word("W100"))) == show(word_answer(0)));
}

TEST_CASE("routes: a module's fault matched on the route refuses the requests for one network only", "[route][plant]") {
    // gw refuses every request for network 2 with CF70 ("a whole network that
    // fails", docs/plants.md); network 1's stations are reached as before.
    TempDir dir;
    const auto faults = dir.write("gw.json", R"({"stations": "gw", "faults": [
        {"do": "end_code", "end_code": "CF70", "match": {"route": {"network": 2}}}]})");
    SimProcess sim(plant_options(R"({"bind": "127.0.0.1", "http": {"enabled": false}, "stations": [
        {"name": "gw", "profile": "RJ71EN71", "tcp_port": 0, "networks": [{"number": 1, "station": 1}],
         "scenarios": [")" + faults.string() + R"("]},
        {"name": "relay", "profile": "R08CPU", "tcp_port": 0, "networks": [{"number": 1, "station": 4}, {"number": 2, "station": 1}],
         "devices": {"D100": 4660}},
        {"name": "packer", "profile": "R08CPU", "tcp_port": 0, "networks": [{"number": 2, "station": 3}]}]})"));
    auto gw = TcpClient::open(tcp_of(sim, "gw"));
    CHECK(show(ask(gw, hex("50 00 02 03 FF 03 00 0C 00 01 00 01 04 00 00 64 00 00 A8 01 00"))) ==
          show(hex("D0 00 02 03 FF 03 00 0B 00 70 CF 02 03 FF 03 00 01 04 00 00")));
    CHECK(show(ask(gw, hex("50 00 01 04 FF 03 00 0C 00 01 00 01 04 00 00 64 00 00 A8 01 00"))) ==
          show(hex("D0 00 01 04 FF 03 00 04 00 00 00 34 12")));
}

TEST_CASE("routes: a relay station's faults refuse or drop the requests it passes on", "[route][plant]") {
    // relay refuses every 0401 with CF70 and drops every 1401; the module
    // answers a dropped request CF71 when its monitoring timer (250 ms) runs out.
    TempDir dir;
    const auto faults = dir.write("relay.json", R"({"stations": "relay", "faults": [
        {"do": "end_code", "end_code": "CF70", "match": {"command": "0401"}},
        {"do": "no_response", "match": {"command": "1401"}}]})");
    SimProcess sim(plant_options(R"({"bind": "127.0.0.1", "http": {"enabled": false}, "stations": [
        {"name": "gw", "profile": "RJ71EN71", "tcp_port": 0, "udp_port": 0, "networks": [{"number": 1, "station": 1}]},
        {"name": "relay", "profile": "R08CPU", "tcp_port": 0, "networks": [{"number": 1, "station": 4}, {"number": 2, "station": 1}],
         "scenarios": [")" + faults.string() + R"("]},
        {"name": "packer", "profile": "R08CPU", "tcp_port": 0, "networks": [{"number": 2, "station": 3}]}]})"));
    auto gw = TcpClient::open(tcp_of(sim, "gw"));
    CHECK(show(ask(gw, hex("50 00 02 03 FF 03 00 0C 00 01 00 01 04 00 00 64 00 00 A8 01 00"))) ==
          show(hex("D0 00 02 03 FF 03 00 0B 00 70 CF 02 03 FF 03 00 01 04 00 00")));
    CHECK(show(ask(gw, hex("50 00 02 03 FF 03 00 0E 00 01 00 01 14 00 00 64 00 00 A8 01 00 34 12"))) ==
          show(hex("D0 00 02 03 FF 03 00 0B 00 71 CF 02 03 FF 03 00 01 14 00 00")));
    UdpClient udp;
    CHECK(show(ask(udp, udp_of(sim, "gw"), hex("50 00 02 03 FF 03 00 0E 00 01 00 01 14 00 00 64 00 00 A8 01 00 34 12"))) ==
          show(hex("D0 00 02 03 FF 03 00 0B 00 71 CF 02 03 FF 03 00 01 14 00 00")));
    // Nothing was written: packer's own D100 is still 0.
    auto packer = TcpClient::open(tcp_of(sim, "packer"));
    CHECK(show(ask(packer, read_d100(Route{}))) == show(hex("D0 00 00 FF FF 03 00 04 00 00 00 00 00")));
}
