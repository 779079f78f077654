// SLMP as a protocol face (frontends/slmp/face.hpp): registered first,
// configured by the station's own "ports" rather than a section of its own,
// and timed — the listeners serve it from the same list as every other face,
// and its unit asks for the station's own serving path (station/inbox.hpp).
#include <catch2/catch.hpp>

#include <algorithm>
#include <array>
#include <thread>
#include <vector>

#include <boost/asio.hpp>

#include "config/frontend_config.hpp"
#include "frontends/face.hpp"
#include "server/listeners.hpp"
#include "station/station.hpp"

namespace {

namespace asio = boost::asio;
using namespace slmp;
using Bytes = std::vector<std::uint8_t>;

// 3E binary: batch read (0401/0000) of one word at D0 ...
const Bytes kReadD0 = {0x50, 0x00, 0x00, 0xFF, 0xFF, 0x03, 0x00, 0x0C, 0x00, 0x10, 0x00,
                       0x01, 0x04, 0x00, 0x00, 0x00, 0x00, 0x00, 0xA8, 0x01, 0x00};
// ... answered end code 0000 and the word (0: a fresh station's D0).
const Bytes kD0IsZero = {0xD0, 0x00, 0x00, 0xFF, 0xFF, 0x03, 0x00, 0x04, 0x00, 0x00, 0x00, 0x00, 0x00};

}  // namespace

TEST_CASE("SLMP is the first registered face, configured by the station's ports, and timed") {
    const auto& all = frontends::all_faces();
    REQUIRE(!all.empty());
    const auto& slmp_face = *all.front();
    CHECK(slmp_face.name() == "slmp");
    CHECK(frontends::find_face("slmp") == &slmp_face);
    CHECK_FALSE(slmp_face.own_section());
    // The sections, options, scenario protocols and metrics names list the others.
    const auto& sectioned = frontends::faces();
    CHECK(std::find(sectioned.begin(), sectioned.end(), &slmp_face) == sectioned.end());
    CHECK(frontends::face_names("slmp").find("\"slmp\", \"slmp\"") == std::string::npos);
    config::ServerConfig server;
    station::Station station(config::resolve_profile(server), protocol::EngineOptions{});
    auto unit = slmp_face.make_unit(station.cpu(), slmp_face.defaults());
    CHECK(unit->timed());
    CHECK(&unit->face() == &slmp_face);
    // Its listen failures read as they always have.
    CHECK(slmp_face.port_noun(config::Transport::Tcp) + " (" + slmp_face.port_fix(config::Transport::Tcp) + ")" ==
          "TCP (--tcp-port)");
}

TEST_CASE("the listeners serve SLMP's ports from the one list of faces, over TCP and UDP") {
    config::ServerConfig server;
    server.ports = {config::PortConfig{config::Transport::Tcp, 0}, config::PortConfig{config::Transport::Udp, 0}};
    asio::io_context io;
    station::Home home = asio::make_strand(io);
    station::Station station(home, server);
    server::Listeners listeners(home, station, server, config::FrontEndsConfig{}, asio::ip::make_address("127.0.0.1"));
    station.connect(listeners);
    REQUIRE(station.frontends().size() == 1);
    CHECK(station.frontends()[0]->face().name() == "slmp");
    REQUIRE(listeners.tcp_ports().size() == 1);
    REQUIRE(listeners.udp_ports().size() == 1);
    CHECK(listeners.face_tcp_ports("slmp") == listeners.tcp_ports());
    CHECK(listeners.face_udp_ports("slmp") == listeners.udp_ports());
    std::thread runner([&io] { io.run(); });

    asio::io_context client_io;
    asio::ip::tcp::socket tcp(client_io);
    tcp.connect({asio::ip::make_address("127.0.0.1"), listeners.tcp_ports()[0]});
    asio::write(tcp, asio::buffer(kReadD0));
    Bytes answer(kD0IsZero.size());
    asio::read(tcp, asio::buffer(answer));
    CHECK(answer == kD0IsZero);
    tcp.close();

    asio::ip::udp::socket udp(client_io, asio::ip::udp::endpoint(asio::ip::udp::v4(), 0));
    udp.send_to(asio::buffer(kReadD0), {asio::ip::make_address("127.0.0.1"), listeners.udp_ports()[0]});
    std::array<std::uint8_t, 64> datagram{};
    asio::ip::udp::endpoint from;
    const auto n = udp.receive_from(asio::buffer(datagram), from);
    CHECK(Bytes(datagram.begin(), datagram.begin() + static_cast<std::ptrdiff_t>(n)) == kD0IsZero);

    asio::post(home, [&listeners] { listeners.stop(); });
    io.stop();
    runner.join();
}
