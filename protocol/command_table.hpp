// The one command table: each row is a (command, subcommand) the simulator
// serves, with every fact about it — the handler that executes it, the
// decoder that turns its request data into operands, how it addresses
// devices, and the flags the request path asks (password-exempt, operator
// command, writes memory, control CPU only, which port families accept it).
// Nothing outside this table names a command code.
#pragma once

#include <cstdint>
#include <span>
#include <string_view>

#include "devicemodel/cpu.hpp"
#include "protocol/end_code.hpp"
#include "protocol/engine.hpp"
#include "protocol/fields.hpp"
#include "protocol/port_profile.hpp"
#include "protocol/request.hpp"

namespace slmp::protocol {

// How a device command moves data: bit units (one point a device) or word units.
enum class Access : std::uint8_t { None, Bits, Words };

struct CommandSpec;

// What a handler gets. It reads the decoded operands (device commands) or
// fields from `in` (the others), writes response data to `out`, and returns
// the end code (Ok, or the error; `out` is dropped then).
struct CommandContext {
    devicemodel::Cpu& cpu;         // the CPU the request's module I/O number selects
    const PortProfile& port;       // its port's end codes and limits
    const CpuSet& cpus;            // every CPU of the station (U3E1\G reaches CPU No.2)
    const PortProfile& station_port;   // the port of CPU No.1, which the client is connected to
    const FrameHeader& header;
    const CommandSpec& spec;
    const Operands& operands;      // what the row's decoder read (empty without one)
    Session& session;
    FieldReader& in;               // the request data after the subcommand (rows without a decoder)
    FieldWriter& out;
    bool restarted = false;        // Remote RESET succeeded: no response, every connection closes
    std::string silent = {};       // non-empty: served, but not answered (why, for the log): a node command meant for another device
    std::string named = {};        // what the request names besides devices ("LabelW, DDD[0]"): Outcome::named
};

// What a decoder gets: the request data after the subcommand, the row, and
// the port whose limits are enforced while the fields are read.
struct DecodeContext {
    FieldReader& in;
    const CommandSpec& spec;
    const PortProfile& port;
    Operands& out;
    bool a_compatible = false;   // a 1E request: devices in the A-compatible layout
};

using Handler = EndCode (*)(CommandContext&);
using Decoder = void (*)(DecodeContext&);

// Per-row flags (a bit set).
enum Flag : std::uint16_t {
    kExtended = 1 << 0,        // 008x: devices in the extended layout (Appendix 1)
    kControlCpuOnly = 1 << 1,  // refused for CPU No.2–4 of a multi-CPU system (Appendix 3)
    kPasswordExempt = 1 << 2,  // served on a connection the remote password locks (§6)
    kOperator = 1 << 3,        // changes the CPU's operating state or lock: logged at info
    kWrites = 1 << 4,          // writes device or buffer memory
    // The node commands 0E30-0E53 (JA §3.12-3.14): served only on a port whose
    // profile has "node_commands" (an SLMP-compatible device); others answer
    // their "not supported" code.
    kNode = 1 << 5,
    // Parameter Set Start/Set/End/Cancel (JA §4.2.1.8): served while a parameter
    // write is under way, when every other command answers CEE0.
    kParameterWrite = 1 << 6,
    // File control (SLMP Reference Manual §3.1.4): the request destination module
    // I/O No. may be only 03FF, 03D2 or 03D3 (and 03E0-03E3 of a multi-CPU
    // system, Appendix 3); 03D0/03D1 and a multidrop station are refused.
    kFileRoute = 1 << 7,
    // Clear Error 1617 clears the error of the SLMP device the client is
    // connected to. The Chinese manual's access table marks the iQ-R, Q and L
    // CPUs' built-in ports × (they answer "not supported"); a module port
    // (an Ethernet module in front of the CPU) and the iQ-F port serve it.
    kConnectedDevice = 1 << 8,
};

// The port families that serve a command (a bit per devicemodel::Family).
using Families = std::uint8_t;
constexpr Families family_bit(devicemodel::Family f) { return static_cast<Families>(1u << static_cast<unsigned>(f)); }

struct CommandSpec {
    std::uint16_t command;
    std::uint16_t subcommand;
    std::string_view name;
    Handler handler;
    Decoder decode = nullptr;      // device commands: request data -> Operands, before the scenario hook
    DeviceForm form = DeviceForm::Q;
    Access access = Access::None;
    std::uint16_t flags = 0;
    Families families = 0xFF;      // every family unless the row says otherwise

    bool extended() const { return flags & kExtended; }
    bool control_cpu_only() const { return flags & kControlCpuOnly; }
    bool password_exempt() const { return flags & kPasswordExempt; }
    bool operator_command() const { return flags & kOperator; }
    bool writes() const { return flags & kWrites; }
    bool node_command() const { return flags & kNode; }
    bool parameter_write() const { return flags & kParameterWrite; }
    bool file_route() const { return flags & kFileRoute; }
    bool connected_device() const { return flags & kConnectedDevice; }
    bool served_by(devicemodel::Family family) const { return families & family_bit(family); }
    // A device command: it names devices, and its 00□2/00□3 forms are the iQ-R ones.
    bool device_command() const { return decode != nullptr; }
};

std::span<const CommandSpec> all_commands();
const CommandSpec* find_command(std::uint16_t command, std::uint16_t subcommand);
// Any row of this command (every row of a command shares its per-command
// flags: families, operator, password-exempt); null when none has it.
const CommandSpec* find_any_row(std::uint16_t command);

}  // namespace slmp::protocol
