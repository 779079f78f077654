// The one command table: each row is a (command, subcommand) the simulator
// serves, the handler that serves it and how it addresses devices.
// Anything not in the table gets the profile's "not supported" end code.
#pragma once

#include <cstdint>
#include <span>
#include <string_view>

#include "devicemodel/cpu.hpp"
#include "protocol/end_code.hpp"
#include "protocol/engine.hpp"
#include "protocol/fields.hpp"

namespace slmp::protocol {

// How a device command moves data: bit units (one point a device) or word units.
enum class Access : std::uint8_t { None, Bits, Words };

struct CommandSpec;

// What a handler gets. It reads fields from `in`, writes response data to
// `out`, and returns the end code (Ok, or the error; `out` is dropped then).
struct CommandContext {
    devicemodel::Cpu& cpu;         // the CPU the request's module I/O number selects
    const CpuSet& cpus;            // every CPU of the station (U3E1\G reaches CPU No.2)
    const FrameHeader& header;
    const CommandSpec& spec;
    Session& session;
    FieldReader& in;
    FieldWriter& out;
    bool restarted = false;        // Remote RESET succeeded: no response, every connection closes
};

using Handler = EndCode (*)(CommandContext&);

struct CommandSpec {
    std::uint16_t command;
    std::uint16_t subcommand;
    std::string_view name;
    Handler handler;
    DeviceForm form = DeviceForm::Q;
    Access access = Access::None;
    bool extended = false;         // 008x: devices in the extended layout (Appendix 1)
    bool control_cpu_only = false; // refused for CPU No.2–4 of a multi-CPU system (Appendix 3)
};

std::span<const CommandSpec> all_commands();
const CommandSpec* find_command(std::uint16_t command, std::uint16_t subcommand);
// Whether any row has this command (to log "unknown subcommand" apart from "unknown command").
bool is_known_command(std::uint16_t command);
// Device-access subcommands of the iQ-R family (00□2/00□3), which Q/L ports refuse.
bool is_iqr_device_subcommand(std::uint16_t command, std::uint16_t subcommand);

}  // namespace slmp::protocol
