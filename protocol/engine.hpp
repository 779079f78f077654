// The protocol core: decode (bytes -> Request) and execute (Request + Session
// -> Outcome). No I/O, no threads. The station calls decode, lets the scenario
// hook look at the decoded Request, then calls execute; process() is the two
// in one, for callers with no hook (unit tests, tools).
#pragma once

#include <array>
#include <chrono>
#include <cstdint>
#include <functional>
#include <span>
#include <string>
#include <vector>

#include "devicemodel/cpu.hpp"
#include "protocol/end_code.hpp"
#include "protocol/fields.hpp"
#include "protocol/frame.hpp"
#include "protocol/port_profile.hpp"
#include "protocol/request.hpp"

namespace slmp::protocol {

// Devices registered by Entry Monitor Device 0801 for Execute Monitor 0802.
// Kept as they arrived, so index registers are applied at every 0802.
struct MonitorRegistration {
    bool registered = false;
    DeviceForm form = DeviceForm::Q;
    std::vector<DeviceField> words;
    std::vector<DeviceField> dwords;
};

// Per-connection state (one per TCP connection; one per UDP port). It grows
// with the remote password lock.
struct Session {
    std::uint64_t id = 0;
    // Who owns the file locks of the request being served (1827-182A): the
    // connection, or for UDP the peer (protocol/lock_owner.hpp); set by
    // station::Station::handle before each request, 0 = the session id.
    std::uint64_t file_owner = 0;
    std::uint64_t lock_owner() const { return file_owner ? file_owner : id; }
    MonitorRegistration monitor;   // per connection: another client's 0801 does not replace it
    // Remote password (1630/1631): a connection starts locked whenever the CPU
    // has a password and its port has the password enabled; Unlock opens this
    // connection only (SLMP Reference Manual §5.7).
    bool password_unlocked = false;
    // Settings of the port the connection came in on (config::PortConfig, with
    // the profile's defaults); station::Station::new_session fills them.
    struct PortSettings {
        bool remote_password = true;   // the remote password guards this port
        bool online_change = true;     // writes are served while the CPU is in RUN
    } port;
    // The port's own network and station numbers (set by the transport from
    // the port's configuration); requests addressed to them are served.
    StationNumbers own{};
    // A session at the station a route leads to (station/network_map.hpp): its
    // requests were routed here, their network/station already resolved.
    bool routed = false;
    // Commands per connection (SLMP Reference Manual §3.3), set by the transport before each
    // request: how many requests of the same burst came before this one and
    // are not answered yet, and how many connections the port has open.
    std::size_t queued_ahead = 0;
    std::size_t connections = 1;
    // Who sent the request being served, set by station::Station before each
    // request like file_owner: the sender's IPv4 address (0.0.0.0 when not
    // IPv4) and the simulator's port it reached — what Status Read2 0E53
    // compares and Communication Setting Get 0E45 reports (docs/nodes.md).
    std::array<std::uint8_t, 4> peer_ipv4{};
    std::uint16_t local_port = 0;
    // When a request is served, for the few commands that need it (the node's
    // 10 s parameter-write timeout, the remote password's lock-out): `now` when
    // set (a test's fixed instant), else the station's clock, read only then
    // (station::Station::new_session sets it, so a request pays for no clock
    // read it does not use). Neither (a bare engine): the CPU's last scan.
    std::chrono::steady_clock::time_point now{};
    std::function<std::chrono::steady_clock::time_point()> clock;
};

inline std::chrono::steady_clock::time_point request_time(const Session& session, const devicemodel::Cpu& cpu) {
    if (session.now != std::chrono::steady_clock::time_point{}) return session.now;
    return session.clock ? session.clock() : cpu.runtime().now();
}

// Whether the remote password guards this connection: the CPU has one and the
// connection's port has it enabled.
bool password_guards(const devicemodel::Cpu& cpu, const Session& session);

// CPU No.1–4 of a multi-CPU system; [0] is the CPU whose port the client uses.
using CpuSet = std::array<devicemodel::Cpu*, 4>;

// What the plant made of a station besides its CPU Nos. (docs/plants.md):
// one CPU of a redundant pair, whose module I/O 03D0-03D3 name it once the
// plant chose it from the pair; a multidrop station, reached through another
// station's serial module (module I/O = that module's start I/O ÷ 16) with
// its multidrop No.
struct RouteIdentity {
    bool redundant = false;
    bool multidrop = false;
    std::uint16_t multidrop_io = 0;
    std::uint8_t multidrop_number = 0;
};

// The request destinations a file command may name (SLMP Reference Manual
// §3.1.4): 03FF, 03D2, 03D3 — and 03E0-03E3, which Appendix 3 lists for
// every file command (docs/end-codes.md). Others: 4B02.
bool file_route_allowed(const Route& route);

struct EngineOptions {
    std::size_t max_frame_bytes = 8192;   // a larger length field closes the connection
};

struct Outcome {
    enum class Action : std::uint8_t {
        NeedMore,   // no whole frame yet; nothing consumed
        Respond,    // send `response`
        Silent,     // consume and send nothing (garbage, frames the port ignores)
        Close,      // close the connection (oversized frame, profile says so)
        Restart,    // Remote RESET succeeded: the CPU has restarted; send nothing and
                    // close every connection of the station (§5.6)
    };
    Action action = Action::NeedMore;
    std::size_t consumed = 0;
    std::vector<std::uint8_t> response;
    std::string note;              // why a request was rejected or ignored; empty on success
    std::string named;             // what the request named besides devices (label names), for the call monitor and recordings
    std::uint16_t command = 0;
    std::uint16_t subcommand = 0;
    EndCode end_code = EndCode::Ok;
};

class Engine {
public:
    // `port`: what the CPU's SLMP port answers (from the same profile file as the CPU).
    Engine(devicemodel::Cpu& cpu, PortProfile port, EngineOptions options = {}) : cpu_(cpu), options_(options) {
        cpus_[0] = &cpu;
        ports_[0] = std::move(port);
    }

    // Adds CPU No.2–4 of a multi-CPU system, reached with module I/O 03E1–03E3.
    void add_cpu(int number, devicemodel::Cpu& cpu, PortProfile port) {
        cpus_.at(static_cast<std::size_t>(number - 1)) = &cpu;
        ports_.at(static_cast<std::size_t>(number - 1)) = std::move(port);
    }
    const CpuSet& cpus() const { return cpus_; }
    void set_identity(RouteIdentity identity) { identity_ = identity; }
    const RouteIdentity& identity() const { return identity_; }

    // Where the frame at the start of `input` ends, without decoding it: the
    // framing decode() starts with (a transport that holds whole frames for
    // the clock asks this, so the request is still decoded once).
    FrameScan frame(std::span<const std::uint8_t> input, DataCodePolicy policy) const;
    // Decodes the frame at the start of `input` (at most one); touches no memory.
    // `own`: the port's network/station numbers, served like 00/FF. `routed`:
    // the plant's router brought the request here through a module (its
    // network/station name this station), so only module I/O and multidrop
    // are checked.
    Request decode(std::span<const std::uint8_t> input, DataCodePolicy policy, StationNumbers own = {},
                   bool routed = false) const;
    // Serves a decoded request: the port's refusals, route, password, then the handler.
    Outcome execute(const Request& request, Session& session);
    // decode + execute.
    Outcome process(std::span<const std::uint8_t> input, DataCodePolicy policy, Session& session) {
        return execute(decode(input, policy, session.own), session);
    }

    devicemodel::Cpu& cpu() { return cpu_; }
    const PortProfile& port() const { return ports_[0]; }
    const EngineOptions& options() const { return options_; }

private:
    // A 1E request after framing: its 1E row, route, 3E row and operands (decode_1e.cpp).
    void decode_1e(Request& request, std::span<const std::uint8_t> input, StationNumbers own) const;
    // How fields are written for CPU No.(index+1): its port's ZR form, its X/Y numbering.
    CodecOptions codec_options(std::size_t index) const {
        return {ports_[index].zr_ascii_hex, cpus_[index]->profile().numbering};
    }

    devicemodel::Cpu& cpu_;
    CpuSet cpus_{};
    std::array<PortProfile, 4> ports_{};   // the port of each CPU in cpus_
    EngineOptions options_;
    RouteIdentity identity_;
    // What a command writes, kept between requests so its capacity is reused:
    // no allocation a request (a 960-word read's 1920 bytes included).
    std::vector<std::uint8_t> command_data_;
};

}  // namespace slmp::protocol
