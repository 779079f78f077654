// A protocol face added without touching anything outside its own code: a toy
// face defined here, registered with frontends::register_face (what its one
// line in frontends/registry.cpp would do), configured by name, and served by
// the real listeners over a loopback TCP socket (frontends/face.hpp).
#include <catch2/catch.hpp>

#include <string>
#include <thread>

#include <boost/asio.hpp>

#include "config/frontend_config.hpp"
#include "frontends/face.hpp"
#include "server/listeners.hpp"
#include "station/station.hpp"

namespace {

namespace asio = boost::asio;
using namespace slmp;

// The toy protocol: a request is a line; the answer is "OK <line> <n>\n" with n
// the connection's n-th request (its session state), or "NG\n" for a line the
// toy's table does not know.
struct ToySession final : frontends::SessionState {
    int requests = 0;
};

class ToyUnit final : public frontends::Unit {
public:
    explicit ToyUnit(const frontends::Face& face) : face_(face) {}
    const frontends::Face& face() const override { return face_; }
    std::unique_ptr<frontends::SessionState> new_session(const protocol::Peer&) override { return std::make_unique<ToySession>(); }

    frontends::Exchange stream(std::span<const std::uint8_t> pending, frontends::SessionState* session,
                               const frontends::Gate& gate) override {
        frontends::Exchange e;
        std::string text(pending.begin(), pending.end());
        auto end = text.find('\n');
        if (end == std::string::npos) return frontends::Exchange::more();
        e.consumed = end + 1;
        e.command = text.substr(0, end);
        e.known = e.command == "PING" || e.command == "HELLO";
        e.name = e.known ? "greeting" : "";
        if (gate && gate(e.command).kind != frontends::Intercept::Kind::Pass) return e;
        auto& state = *static_cast<ToySession*>(session);
        e.code = e.known ? "00" : "01";
        e.response = e.known ? "OK " + e.command + " " + std::to_string(++state.requests) + "\n" : "NG\n";
        return e;
    }

private:
    const frontends::Face& face_;
};

class ToyFace final : public frontends::Face {
public:
    std::string_view name() const override { return "toy"; }
    std::string_view title() const override { return "toy line protocol"; }
    std::string_view log_name() const override { return "toy"; }
    std::string_view port_name() const override { return "toy"; }
    std::string port_fix(config::Transport) const override { return "\"toy\": {}"; }
    std::string_view missing_noun() const override { return "toy port"; }
    frontends::Settings defaults() const override {
        frontends::Settings s;
        s.face = this;
        s.tcp = config::PortConfig{config::Transport::Tcp, 0, config::DataCode::Ascii, 4};
        return s;
    }
    void parse(const config::JsonAt& at, frontends::Settings&) const override { at.only_keys({}); }
    bool scenario_command(std::string& text) const override { return !text.empty(); }
    std::string_view command_fix() const override { return "write a word"; }
    std::string_view code_fix() const override { return "write two digits"; }
    std::string check(devicemodel::Cpu&, const frontends::Settings&) const override { return {}; }
    std::unique_ptr<frontends::Unit> make_unit(devicemodel::Cpu&, const frontends::Settings&) const override {
        return std::make_unique<ToyUnit>(*this);
    }
};

std::string ask(asio::ip::tcp::socket& socket, const std::string& line) {
    asio::write(socket, asio::buffer(line));
    std::string answer;
    asio::read_until(socket, asio::dynamic_buffer(answer), '\n');
    return answer;
}

}  // namespace

TEST_CASE("a toy face registered by a test is configured by name and served over TCP") {
    static const ToyFace toy;
    frontends::register_face(toy);
    REQUIRE(frontends::find_face("toy") == &toy);

    // Configured the way a file's "toy": {} section is: by the face's name.
    auto frontends = config::parse_frontends_config(R"({"toy": {}})", "toy.json");
    REQUIRE(frontends.faces.size() == 1);
    REQUIRE(frontends.find("toy") != nullptr);

    asio::io_context io;
    station::Home home = asio::make_strand(io);
    config::ServerConfig server;
    server.ports.clear();
    station::Station station(home, server);
    server::Listeners listeners(home, station, server, frontends, asio::ip::make_address("127.0.0.1"));
    station.connect(listeners);
    REQUIRE(station.frontends().size() == 1);
    auto ports = listeners.face_tcp_ports("toy");
    REQUIRE(ports.size() == 1);
    std::thread runner([&io] { io.run(); });

    asio::io_context client_io;
    asio::ip::tcp::socket client(client_io);
    client.connect({asio::ip::make_address("127.0.0.1"), ports[0]});
    CHECK(ask(client, "HELLO\n") == "OK HELLO 1\n");
    CHECK(ask(client, "PING\n") == "OK PING 2\n");
    CHECK(ask(client, "WHAT\n") == "NG\n");
    asio::ip::tcp::socket second(client_io);   // a connection of its own: its own session state
    second.connect({asio::ip::make_address("127.0.0.1"), ports[0]});
    CHECK(ask(second, "PING\n") == "OK PING 1\n");
    client.close();
    second.close();

    asio::post(home, [&listeners] { listeners.stop(); });
    io.stop();
    runner.join();
}
