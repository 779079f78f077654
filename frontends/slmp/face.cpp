// SLMP's face (face.hpp): its names, its ports' fixes, and its unit, which
// asks the station to serve it (Unit::timed).
#include "frontends/slmp/face.hpp"

#include <cctype>
#include <stdexcept>

#include "config/json_path.hpp"

namespace slmp::slmp_face {

namespace {

// The station serves SLMP itself (station/inbox.hpp decodes each frame once
// and hands it to the protocol engine when the timing mode says), so the unit
// holds no state of its own: no session state, no snapshot parts, SLMP's
// device names are the HTTP API's default form.
class Unit final : public frontends::Unit {
public:
    const frontends::Face& face() const override { return slmp_face::face(); }
    bool timed() const override { return true; }
    // Never called: the transports hand a timed unit's bytes to the station
    // (frontends/face.hpp, Unit::timed). A call is a bug in a transport, said
    // loudly rather than leaving the connection waiting.
    frontends::Exchange stream(std::span<const std::uint8_t>, frontends::SessionState*, const frontends::Gate&) override {
        throw std::logic_error("SLMP's unit is timed: the station serves its requests, not Unit::stream()");
    }
};

class Face final : public frontends::Face {
public:
    std::string_view name() const override { return "slmp"; }
    std::string_view title() const override { return "SLMP"; }
    std::string_view log_name() const override { return {}; }   // SLMP's log lines name the peer alone
    std::string_view port_name() const override { return "SLMP"; }
    std::string port_noun(config::Transport transport) const override {
        return transport == config::Transport::Tcp ? "TCP" : "UDP";
    }
    std::string port_fix(config::Transport transport) const override {
        return transport == config::Transport::Tcp ? "--tcp-port" : "--udp-port";
    }
    bool has_udp() const override { return true; }
    bool own_section() const override { return false; }
    std::string_view missing_noun() const override { return "SLMP port"; }

    // Its settings are the station's "ports" (config::ServerConfig::ports),
    // read with the station's keys; it has no section to parse.
    frontends::Settings defaults() const override {
        frontends::Settings s;
        s.face = this;
        return s;
    }
    void parse(const config::JsonAt& at, frontends::Settings&) const override {
        at.fail("SLMP has no section of its own", "give its ports as the station's \"ports\"");
    }

    // A fault's "command": four hex digits ("0401"), in uppercase.
    bool scenario_command(std::string& text) const override {
        if (text.size() != 4) return false;
        for (auto& ch : text) {
            if (!std::isxdigit(static_cast<unsigned char>(ch))) return false;
            ch = static_cast<char>(std::toupper(static_cast<unsigned char>(ch)));
        }
        return true;
    }
    std::string_view command_fix() const override { return "write the command as four hex digits, e.g. \"0401\""; }
    std::string_view code_fix() const override { return "write the end code as four hex digits, e.g. \"C059\""; }

    std::string check(devicemodel::Cpu&, const frontends::Settings&) const override { return {}; }
    std::unique_ptr<frontends::Unit> make_unit(devicemodel::Cpu&, const frontends::Settings&) const override {
        return std::make_unique<Unit>();
    }
};

}  // namespace

const frontends::Face& face() {
    static const Face instance;
    return instance;
}

}  // namespace slmp::slmp_face
