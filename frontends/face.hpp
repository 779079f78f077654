// A protocol face of a station, as a plug-in (docs/architecture.md, "Where to
// add … a front end"): a protocol served on the station's CPU memory — SLMP,
// the MELSEC CPU's own (frontends/slmp/), and other controllers' served on the
// same memory: the Ladder Motion host link, the Sharp JW-51CM computer link.
// The core (config, station, control, scenarios, server) reaches a face only
// through these two classes and the registry (frontends/registry.cpp, one
// line a face), as libmodbus's core reaches a transport only through its
// backend table:
//
// - `Face`: what a kind of face is, one static object per kind — its name
//   (the JSON section, the scenario "protocol", the activity and metrics
//   label, the ready file's key), its settings (the JSON section's keys, the
//   command-line options it adds), its ports and log names, its scenario
//   command syntax, its own HTTP resources (api_routes()), and how it makes a `Unit`.
// - `Unit`: one station's instance of a face on its CPU — its framing and
//   command handling (stream()/datagram()), its per-connection state
//   (new_session()), its address names for the HTTP API (resolve_name()) and
//   its state beyond device memory for snapshots (save()/restore()).
//
// The transports serve every face alike (server/listeners.hpp): a face's ports,
// each with the inbox its unit asks for — the station's timed path for a
// timed unit (SLMP), else an at-once one that wraps every call in a
// station::FrontEndCall (faults, recording, activity). A face knows no sockets,
// scenarios or station: it asks for a clock or a connection out by StationServices.
#pragma once

#include <chrono>
#include <cstdint>
#include <functional>
#include <map>
#include <memory>
#include <optional>
#include <span>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

#include "config/config.hpp"
#include "devicemodel/cpu.hpp"
#include "devicemodel/device_table.hpp"
#include "frontends/gate.hpp"
#include "protocol/peer.hpp"

namespace boost::program_options {
class options_description;
class variables_map;
}  // namespace boost::program_options

namespace slmp::config {
class JsonAt;
}

namespace slmp::frontends {

class Face;

// One request cut from the bytes received and answered (or still incomplete).
struct Exchange {
    bool need_more = false;      // a request has begun but is not whole: read on
    std::size_t consumed = 0;    // bytes taken (a request, or garbage dropped)
    std::string response;        // bytes to send back (empty: none)
    std::string command;         // its command as text ("RD"; JW: the COM in hex); empty: none could be read
    bool known = false;          // the face's command table has it (metrics name others "other")
    std::string_view name;       // the table's name for it; empty when unknown
    std::string code;            // the response code answered ("00", "IC", "10"); empty: no answer

    static Exchange more() {     // no whole request yet
        Exchange e;
        e.need_more = true;
        return e;
    }
};

// A connection's own protocol state (the host link's QQMR list); faces without one return none.
struct SessionState {
    virtual ~SessionState() = default;
};

// A face's address name resolved for the HTTP API ("DM0100" -> D100).
struct DeviceName {
    devicemodel::DeviceAddress start;
    enum class View : std::uint8_t { Natural, Words, Dwords } view = View::Natural;   // the form's own default view
};

// Unit state beyond device memory, as named parts ("hostlink environment", ...):
// a station snapshot, its file form and the state directory carry them alike.
using Parts = std::map<std::string, std::vector<std::uint8_t>>;

// A connection a unit opens out of the station (the JW-51CM's SEND/RECEIVE to
// a partner station): TCP or UDP to one address and port, one request at a
// time. Made by StationServices::connect(); every callback comes on the
// station's strand, and none after the object is destroyed (which closes it).
class Outgoing {
public:
    virtual ~Outgoing() = default;
    // TCP: connects, then done(true); done(false) when it cannot (refused,
    // unreachable). UDP: done(true) soon after (nothing to set up).
    virtual void open(std::function<void(bool connected)> done) = 0;
    virtual bool connected() const = 0;
    // Sends `request`; `answer` gets the answer's bytes once `whole` — given
    // the bytes received so far — names the answer's length, or nullopt when
    // the connection failed or closed first. UDP: the first datagram from the
    // partner's address and port is the answer (`whole` is not asked).
    // A request whose answer never comes is the caller's to give up on (its timer).
    virtual void exchange(std::vector<std::uint8_t> request,
                          std::function<std::optional<std::size_t>(std::span<const std::uint8_t>)> whole,
                          std::function<void(std::optional<std::vector<std::uint8_t>>)> answer) = 0;
};

// What the station offers a unit that acts on its own and not only when asked
// (the JW-51CM's SEND/RECEIVE): a wait on the station's clock and
// connections out. Given by Unit::attach() once the station serves the unit;
// lives as long as the unit is attached.
class StationServices {
public:
    virtual ~StationServices() = default;
    // Calls `then` on the station's strand once `timer` has passed on the
    // station's clock (its speed, a frozen clock's steps: docs/timing.md), not
    // the host's — unless `wanted`, asked at every END meanwhile and before
    // `then`, says it no longer is (the wait keeps the station scanning every
    // scan, so a wait that is over should say so).
    virtual void after(std::chrono::milliseconds timer, std::function<bool()> wanted, std::function<void()> then) = 0;
    // A connection out to `address` (IPv4 text) and `port`, not yet open.
    virtual std::unique_ptr<Outgoing> connect(protocol::Transport transport, const std::string& address, std::uint16_t port) = 0;
};

// One station's instance of a face, on its CPU's memory. Lives as long as the
// listeners that serve it; used on the station's strand only.
class Unit {
public:
    virtual ~Unit() = default;
    virtual const Face& face() const = 0;

    // Whether the station decides when this unit's requests are served — at
    // once, at the END of the scan or at the modelled time (its timing mode,
    // docs/timing.md) — and serves them on its own path (station/inbox.hpp:
    // the request decoded once, relays, the upstream, Ondemand pushes). The
    // transports then hand the station the unit's bytes and call neither
    // stream() nor datagram(). False: the unit answers each request at once
    // through stream()/datagram(), in every timing mode.
    virtual bool timed() const { return false; }

    // A new connection's state (null: the face keeps none); `peer`: who
    // connected (a default Peer for a serial line). Made on the station's
    // strand when the connection opens and destroyed there when it closes, so a
    // unit that reports its connections (the JW-51CM's status flags) learns both.
    virtual std::unique_ptr<SessionState> new_session(const protocol::Peer& /*peer*/) { return nullptr; }
    // The front of a stream's buffered bytes: one request cut and answered, or need_more.
    // `gate` (a scenario fault) is asked once the request's command is known.
    virtual Exchange stream(std::span<const std::uint8_t> pending, SessionState* session, const Gate& gate) = 0;
    // One datagram, whole, from `from`.
    virtual Exchange datagram(std::span<const std::uint8_t> datagram, const Gate& gate, const protocol::Peer& /*from*/) {
        return stream(datagram, nullptr, gate);
    }

    // The CPU came up: the station's start, a Remote RESET, the end of a
    // scenario's power cut, a restore that drops the connections. What the
    // unit does at its power-on (the JW-51CM writes its status flags again).
    // On the station's strand; the TCP connections of before may still be closing.
    virtual void power_on() {}

    // The station serves the unit: what it may ask of it (a unit that only
    // answers needs nothing). Before any request, end_of_scan() or power_on().
    virtual void attach(StationServices& /*services*/) {}
    // The END of each of the station's scans (the ladder's requests to the
    // unit are read here: the JW-51CM's SEND/RECEIVE start bit). An idle
    // station scans when something writes to it (docs/timing.md, "What wakes a station").
    virtual void end_of_scan() {}

    // A name in the face's own address form; nullopt when `text` is not one,
    // with *error set when it is one but wrong.
    virtual std::optional<DeviceName> resolve_name(std::string_view, std::string*) const { return std::nullopt; }

    // Its parts and the size each must have; restore() gets only checked parts
    // (sizes, then check()'s problem: empty when good) and keeps its state for absent ones.
    virtual void save(Parts&) const {}
    virtual std::vector<std::pair<std::string, std::size_t>> part_sizes() const { return {}; }
    virtual std::string check(const Parts&) const { return {}; }
    virtual void restore(const Parts&) {}
};

// A face's own HTTP resource, served at /api/<face name>/<pattern> on the
// station's thread with the station's unit of that face (the JW-51CM's ring
// buffers: docs/api.md). The core routes it; the face reads the body and answers.
struct ApiAnswer {
    unsigned status = 200;   // 200: `body` is JSON text; 4xx: `body` is the error's message (naming the fix)
    std::string body;
};
struct ApiRoute {
    bool post = false;          // POST, else GET
    std::string_view pattern;   // after /api/<face name>/: "rings/{number}"
    ApiAnswer (*handler)(Unit& unit, const std::vector<std::string>& captures, const std::string& body);
};

// One station's settings of a face: its ports, and the face's own options.
struct Settings {
    const Face* face = nullptr;
    std::optional<config::PortConfig> tcp, udp;   // absent: no such port
    std::vector<config::PortConfig> ports;        // and any number more, either transport (SLMP: the station's "ports")
    std::string serial_path;                      // also on a pseudo-terminal linked here (empty: none)
    std::shared_ptr<void> options;                // the face's own (memory map, codes, sizes)
};

// What a kind of face is. One static object per kind, registered once.
class Face {
public:
    virtual ~Face() = default;

    // "hostlink": its JSON section, the scenarios' "protocol", the activity's and
    // metrics' protocol, the ready file's key, the snapshot parts' prefix.
    virtual std::string_view name() const = 0;
    virtual std::string_view title() const = 0;      // "Ladder Motion host link" (the start-up log line)
    virtual std::string_view log_name() const = 0;   // "host link" (a session's log lines)
    virtual std::string_view port_name() const = 0;  // "host-link" ("cannot listen on the host-link TCP port")
    // Its port in "cannot listen on <this> 127.0.0.1:9600": "the host-link TCP port".
    virtual std::string port_noun(config::Transport transport) const {
        return "the " + std::string(port_name()) + (transport == config::Transport::Tcp ? " TCP port" : " UDP port");
    }
    // The fix named when its port cannot be had: "\"hostlink\": {\"tcp_port\": ...} or --hostlink-port".
    virtual std::string port_fix(config::Transport transport) const = 0;
    virtual bool has_udp() const { return false; }   // ready file: {"tcp", "udp"} instead of a TCP list
    // Whether it is configured by a JSON section and options of its own, named
    // by name() (faces() lists these). False: by the station's own keys —
    // SLMP's ports are the station's "ports", --tcp-port and --udp-port
    // (config::ServerConfig::ports) — and served when they name any.
    virtual bool own_section() const { return true; }

    // The station "kind" that serves this face alone ("ladder-motion"; empty: none),
    // what such a station lacks of it ("host-link port": "a sharp-jw station has no
    // host-link port"), and the fixes when a station of its kind has SLMP ports.
    virtual std::string_view station_kind() const { return {}; }
    virtual std::string_view missing_noun() const = 0;
    virtual std::string ports_fix() const { return {}; }          // the JSON "ports" key
    virtual std::string command_line_refusal() const { return {}; }   // --tcp-port/--udp-port (and other faces)

    // Settings: on with its defaults, its JSON section, and its command-line options.
    virtual Settings defaults() const = 0;
    virtual void parse(const config::JsonAt& section, Settings& settings) const = 0;
    virtual void add_options(boost::program_options::options_description&) const {}
    virtual std::vector<std::string_view> one_station_options() const { return {}; }
    // Applies the options given; `settings` is this face's entry (null: off so far),
    // `enable` turns it on with defaults and returns it. Throws config::ConfigError.
    virtual void apply_options(const boost::program_options::variables_map&, Settings*,
                               const std::function<Settings&()>& /*enable*/) const {}

    // Scenarios: a fault's "command" in the face's form (normalised in place; false: not one)
    // and the fixes for a bad command and a bad response code.
    virtual bool scenario_command(std::string& text) const = 0;
    virtual std::string_view command_fix() const = 0;
    virtual std::string_view code_fix() const = 0;

    // The problem with `settings` on this CPU's memory (empty: none; --check-config, start-up).
    virtual std::string check(devicemodel::Cpu& cpu, const Settings& settings) const = 0;
    virtual std::unique_ptr<Unit> make_unit(devicemodel::Cpu& cpu, const Settings& settings) const = 0;

    // Its own HTTP resources (none for most faces); `handler` gets a Unit this face made.
    virtual std::span<const ApiRoute> api_routes() const { return {}; }
};

// Every registered face, in registration order (frontends/registry.cpp): what
// a station may serve.
const std::vector<const Face*>& all_faces();
// Those configured by a section of their own (Face::own_section): the
// configuration's sections, options, scenario protocols and metrics names
// beside SLMP's. In registration order.
const std::vector<const Face*>& faces();
const Face* find_face(std::string_view name);   // any registered face
// For a test's own face: registered after the built-in ones, for the process's life.
void register_face(const Face& face);
// The faces' names quoted for a fix, after `first` when given: "\"slmp\", \"a\" or \"b\"".
std::string face_names(std::string_view first = {});

}  // namespace slmp::frontends
