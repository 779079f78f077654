// The settings a real module has per port and per CPU (issue 14): the remote
// password per port, online change (writes in RUN) and the CPU's system
// protect. Byte-exact in binary and ASCII; a refused request changes nothing.
#include "support/device_commands.hpp"

using namespace slmp;
using namespace slmp::test;

namespace {

Payload password_req(std::uint16_t command, const std::string& password) {
    return word(command) + word(0x0000) + word(static_cast<std::uint16_t>(password.size())) +
           Payload{hex(text(password)), password};
}
Payload stop_req() { return word(0x1002) + word(0x0000) + word(0x0001); }

// A connection on a port with the given settings.
struct Client {
    protocol::Session session{};
    Client(bool remote_password, bool online_change) {
        session.port.remote_password = remote_password;
        session.port.online_change = online_change;
    }
    std::string exchange(devicemodel::Cpu& cpu, const Wire& w, const Payload& p) {
        return w.show(engine_for(cpu).process(w.request(p), DataCodePolicy::Auto, session));
    }
};

devicemodel::Cpu configured_cpu(const std::string& profile, auto&& set) {
    auto cpu = make_cpu(profile);
    devicemodel::RuntimeConfig c;
    set(c);
    cpu.runtime().configure(std::move(c), cpu.memory());
    return cpu;
}

std::uint16_t d0(const devicemodel::Cpu& cpu) { return static_cast<std::uint16_t>(cpu.memory().value(spec_of("D"), 0)); }

}  // namespace

TEST_CASE("remote password per port: a port with it enabled starts locked, another does not", "[port_settings][password]") {
    auto cpu = configured_cpu("R08CPU", [](auto& c) { c.password = "secret1"; });
    auto wire = GENERATE(kBinary3E, kAscii3E);
    Client guarded(true, true), open(false, true);
    CHECK(guarded.exchange(cpu, wire, read_words_req(Form::Q, "D0", 1)) == wire.expect(error(0xC201, 0x0401, 0x0000)));
    CHECK(open.exchange(cpu, wire, write_words_req(Form::Q, "D0", {7})) == wire.expect(ok()));
    CHECK(d0(cpu) == 7);
    // On the open port there is nothing to unlock; Lock cannot match (C810, as without a password).
    CHECK(open.exchange(cpu, wire, password_req(0x1630, "secret1")) == wire.expect(ok()));
    CHECK(open.exchange(cpu, wire, password_req(0x1631, "secret1")) == wire.expect(error(0xC810, 0x1631, 0x0000)));
    // The guarded port still works as before.
    CHECK(guarded.exchange(cpu, wire, password_req(0x1630, "secret1")) == wire.expect(ok()));
    CHECK(guarded.exchange(cpu, wire, read_words_req(Form::Q, "D0", 1)) == wire.expect(ok(word(7))));
}

TEST_CASE("online change disabled: writes in RUN answer 0055 and change nothing, reads and STOP writes are served",
          "[port_settings]") {
    auto profile = GENERATE(as<std::string>{}, "R08CPU", "Q06UDVCPU-QJ71E71");
    auto cpu = make_cpu(profile);
    auto wire = GENERATE(kBinary3E, kAscii3E);
    Client no_online_change(true, false), normal(true, true);
    REQUIRE(cpu.runtime().state() == devicemodel::RunState::Run);
    CHECK(no_online_change.exchange(cpu, wire, write_words_req(Form::Q, "D0", {5})) ==
          wire.expect(error(0x0055, 0x1401, 0x0000)));
    CHECK(d0(cpu) == 0);
    CHECK(no_online_change.exchange(cpu, wire, read_words_req(Form::Q, "D0", 1)) == wire.expect(ok(word(0))));
    CHECK(normal.exchange(cpu, wire, write_words_req(Form::Q, "D0", {5})) == wire.expect(ok()));
    CHECK(d0(cpu) == 5);
    // In STOP the write is served on that port too.
    CHECK(no_online_change.exchange(cpu, wire, stop_req()) == wire.expect(ok()));
    CHECK(no_online_change.exchange(cpu, wire, write_words_req(Form::Q, "D0", {6})) == wire.expect(ok()));
    CHECK(d0(cpu) == 6);
}

TEST_CASE("system protect: writes and remote operations answer 4004 and change nothing, reads are served",
          "[port_settings]") {
    auto cpu = configured_cpu("R08CPU", [](auto& c) { c.system_protect = true; });
    auto wire = GENERATE(kBinary3E, kAscii3E);
    Client client(true, true);
    CHECK(client.exchange(cpu, wire, write_words_req(Form::Q, "D0", {5})) == wire.expect(error(0x4004, 0x1401, 0x0000)));
    CHECK(client.exchange(cpu, wire, stop_req()) == wire.expect(error(0x4004, 0x1002, 0x0000)));
    CHECK(d0(cpu) == 0);
    CHECK(cpu.runtime().state() == devicemodel::RunState::Run);
    CHECK(client.exchange(cpu, wire, read_words_req(Form::Q, "D0", 1)) == wire.expect(ok(word(0))));
}

TEST_CASE("port settings in the configuration and the profile", "[port_settings][config]") {
    auto config = config::parse_server_config(R"({"ports": [
        {"transport": "tcp", "port": 5000},
        {"transport": "tcp", "port": 5001, "remote_password": false, "online_change": false}],
        "cpu": {"system_protect": true}})",
                                              "plant.json");
    REQUIRE(config.ports.size() == 2);
    CHECK(config.ports[0].remote_password);
    CHECK_FALSE(config.ports[0].online_change.has_value());
    CHECK_FALSE(config.ports[1].remote_password);
    CHECK(config.ports[1].online_change == false);
    CHECK(config.cpu.runtime.system_protect);
    CHECK_THROWS_WITH(config::parse_server_config(R"({"ports": [{"transport": "tcp", "port": 1, "online_change": 1}]})",
                                                  "plant.json"),
                      Catch::Contains("plant.json: /ports/0/online_change"));
    // A profile may change the default and the codes.
    auto profile = config::parse_profile(R"({"name": "NoOnline", "extends": "R08CPU", "description": "test",
        "online_change": false, "end_codes": {"online_change_refused": "C05F", "system_protect": "4A00"}})",
                                         "p.json");
    CHECK_FALSE(profile.port.online_change);
    CHECK(profile.port.online_change_code == 0xC05F);
    CHECK(profile.port.system_protect_code == 0x4A00);
    CHECK(profile.port.not_supported_code == 0xC059);   // the base's codes stay
}
