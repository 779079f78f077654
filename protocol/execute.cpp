// execute: a decoded Request + the connection's Session -> Outcome. The
// gates come first, in the order a real port applies them: the frame kind,
// the header, the route, the remote password, the port's refusals, the
// table; then the row's handler runs against the target CPU.
#include <algorithm>
#include <optional>
#include <string>

#include "devicemodel/hex.hpp"
#include "devicemodel/node.hpp"
#include "protocol/command_table.hpp"
#include "protocol/engine.hpp"
#include "protocol/frame_1e.hpp"
#include "protocol/reply.hpp"

namespace slmp::protocol {
namespace {


// Garbage, oversized frames and partial frames: no command was read.
Outcome unframed(const Request& request, std::size_t max_frame_bytes) {
    Outcome out;
    out.consumed = request.size;
    switch (request.frame) {
        case Request::Frame::NeedMore:
        case Request::Frame::Complete: out.consumed = 0; break;
        case Request::Frame::Garbage:
            out.action = Outcome::Action::Silent;
            out.note = std::to_string(request.size) +
                       " byte(s) that do not start an SLMP request frame for this port's data code "
                       "(expected a 3E/4E subheader 5000/5400, binary or ASCII); skipped";
            break;
        case Request::Frame::TooLarge:
            out.consumed = 0;
            out.action = Outcome::Action::Close;
            out.note = "request data length announces a " + std::to_string(request.size) + "-byte frame, over the " +
                       std::to_string(max_frame_bytes) + "-byte maximum (max_request_bytes); closing the connection";
            break;
    }
    return out;
}

// Monitoring timer, command or subcommand missing or not hex.
Outcome bad_header(const Request& request, Reply& reply) {
    const std::size_t unit = request.header.codec == Codec::Binary ? 1 : 2;
    if (request.header.data_length < 6 * unit)
        return reply.drop(Outcome::Action::Silent,
                          "request data length " + std::to_string(request.header.data_length) +
                              " is too short to hold the monitoring timer, command and subcommand; not answered");
    return reply.error(request.header_error, "bad " + std::string(request.header_error_field));
}

std::string route_note(const Route& route) {
    return "request for network " + devicemodel::hex_text(route.network, 2) + " station " + devicemodel::hex_text(route.station, 2) +
           " module I/O " + devicemodel::hex4(route.module_io) + " multidrop " + devicemodel::hex_text(route.multidrop, 2) +
           "; only the own station (00/FF, or the port's own network/station numbers, module I/O 03FF, multidrop 00) and its configured CPUs (module I/O 03E0-03E3) are served";
}

// Remote password (SLMP Reference Manual §5.7): a locked connection gets
// C201 for everything but the rows that are exempt (Unlock 1630, Lock 1631).
bool locked_out(const devicemodel::Cpu& cpu, const Session& session, std::uint16_t command) {
    if (!password_guards(cpu, session) || session.password_unlocked) return false;
    const auto* row = find_any_row(command);
    return !row || !row->password_exempt();
}

// A CPU's own Ethernet port, not a module in front of it: the ports the
// Chinese manual's access table marks × for Clear Error 1617.
bool cpu_built_in_port(const devicemodel::CpuProfile& cpu, const PortProfile& port) {
    using devicemodel::Family;
    return !port.relays && (cpu.family == Family::IQR || cpu.family == Family::QnU || cpu.family == Family::L);
}

// The port's own refusals, before the table is asked for the subcommand: a
// command the port family does not serve (or the profile adds), a device
// command in the iQ-R form on a port that has only the Q form.
std::optional<Outcome> port_refusal(const devicemodel::CpuProfile& cpu, const PortProfile& profile,
                                    const Request& request, Reply& reply) {
    const auto* row = find_any_row(request.command);
    const auto& extra = profile.unsupported_commands;
    if ((row && !row->served_by(cpu.family)) || (row && row->node_command() && !profile.node_commands) ||
        (row && row->connected_device() && cpu_built_in_port(cpu, profile)) ||
        std::find(extra.begin(), extra.end(), request.command) != extra.end())
        return reply.error(end_code(profile.not_supported_code),
                           "command " + devicemodel::hex4(request.command) + " is not supported by " + cpu.name);
    const auto form = request.subcommand & 0xFF7F;   // 008x: the same forms with the extension specification
    if (row && row->device_command() && (form == 0x0002 || form == 0x0003) &&
        profile.iqr_subcommands.kind != Refusal::Kind::Serve)
        return reply.refuse(profile.iqr_subcommands, devicemodel::hex4(request.command) + "/" + devicemodel::hex4(request.subcommand) +
                                                         " uses the iQ-R device form, which " + cpu.name +
                                                         " does not accept");
    return std::nullopt;
}

// The target CPU's protections: system protect refuses writes and remote
// operations (the password's own Lock/Unlock stay served); a port without
// online change refuses writes while the CPU is in RUN. Both are checked
// before the handler, so a refused request changes nothing.
std::optional<Outcome> protection_refusal(const devicemodel::Cpu& cpu, const PortProfile& port, const CommandSpec& spec,
                                          const Session& session, Reply& reply) {
    const bool remote_operation = spec.operator_command() && !spec.password_exempt();
    if (cpu.runtime().config().system_protect && (spec.writes() || remote_operation))
        return reply.error(end_code(port.system_protect_code),
                           std::string(spec.name) + " refused: the CPU's system protect is on (cpu.system_protect)");
    if (spec.writes() && !session.port.online_change && cpu.runtime().state() == devicemodel::RunState::Run)
        return reply.error(end_code(port.online_change_code),
                           std::string(spec.name) + " refused: the CPU is in RUN and this port has online change "
                                                    "disabled (online_change: false)");
    return std::nullopt;
}

// Commands per connection (SLMP Reference Manual §3.3): 1 + buffer ÷ connections requests fit
// in the port's receive buffer, fractions truncated; one more is refused as
// the profile says (CEE0 by default, docs/end-codes.md).
std::optional<Outcome> over_pipeline_limit(const PortProfile& profile, const Session& session, Reply& reply) {
    if (profile.pipeline_buffer == 0) return std::nullopt;
    const auto limit = 1 + profile.pipeline_buffer / std::max<std::size_t>(session.connections, 1);
    if (session.queued_ahead < limit) return std::nullopt;
    return reply.refuse(profile.pipeline_over_limit,
                        std::to_string(session.queued_ahead) + " request(s) of this burst are ahead in the receive buffer; " +
                            "the port holds " + std::to_string(limit) + " per connection with " +
                            std::to_string(session.connections) + " connection(s) open (commands per connection)");
}

}  // namespace

bool password_guards(const devicemodel::Cpu& cpu, const Session& session) {
    return cpu.runtime().password().configured() && session.port.remote_password;
}

Outcome Engine::execute(const Request& request, Session& session) {
    if (!request.complete()) return unframed(request, options_.max_frame_bytes);
    const auto& cpu = cpu_.profile();
    const auto& profile = ports_[0];
    Reply reply(request);
    if (auto over = over_pipeline_limit(profile, session, reply)) return std::move(*over);
    if (request.header.kind == FrameKind::E4 && profile.frame_4e.kind != Refusal::Kind::Serve)
        return reply.refuse(profile.frame_4e, "4E frame on a port of " + cpu.name + ", which serves 3E only");
    if (!request.has_command) return bad_header(request, reply);
    if (request.route_error != EndCode::Ok)
        return reply.error(request.route_error, std::string(request.route_error == EndCode::SystemSwitching ||
                                                                    request.route_error == EndCode::OtherSystemError
                                                                ? describe(request.route_error)
                                                                : route_note(request.header.route)));
    if (locked_out(cpu_, session, request.command))
        return reply.error(EndCode::RemotePasswordLocked,
                           "this connection is locked by the remote password; send Unlock 1630 with the password first");
    // A 1E command with its own handler is served wherever 1E is: the family's
    // 3E refusals (0101, 0619 on QnU/L) are about the 3E commands.
    const auto* row_1e = request.header.kind == FrameKind::E1 ? find_command_1e(request.header.command_1e) : nullptr;
    const bool own_1e_handler = row_1e && row_1e->handler;
    if (!own_1e_handler)
        if (auto refused = port_refusal(cpu, profile, request, reply)) return std::move(*refused);

    const auto* spec = request.spec;
    if (!spec)
        return reply.error(end_code(profile.not_supported_code),
                           find_any_row(request.command)
                               ? "unknown subcommand " + devicemodel::hex4(request.subcommand) + " for command " + devicemodel::hex4(request.command)
                               : "unknown or unimplemented command " + devicemodel::hex4(request.command));
    // JA §4.2.1.8, "other request" while a parameter write runs: CEE0.
    if (profile.node_commands && !spec->parameter_write() && cpu_.node().busy(request_time(session, cpu_)))
        return reply.error(EndCode::Busy, std::string(spec->name) +
                                              " refused: a parameter write (Parameter Set Start 0E35) is under way; "
                                              "it ends with 0E36/0E3A or 10 s without Set");
    auto& target = *cpus_[request.target];
    if (spec->control_cpu_only() && request.target != 0)
        return reply.error(end_code(profile.not_supported_code),
                           std::string(spec->name) + " cannot reach CPU No.2-4 of a multi-CPU system (Appendix 3)");
    if (auto refused = protection_refusal(target, ports_[request.target], *spec, session, reply))
        return std::move(*refused);

    FieldReader in(request.header.codec, request.data, codec_options(0));
    FieldWriter out(request.header.codec, codec_options(request.target), std::move(command_data_));
    out.bytes().reserve(64);   // most answers fit; growing from empty cost several allocations a request
    struct GiveBack {   // the buffer returns to command_data_ when execute() returns, the answer made
        std::vector<std::uint8_t>& to;
        FieldWriter& from;
        ~GiveBack() { to = std::move(from.bytes()); }
    } give_back{command_data_, out};
    CommandContext ctx{target, ports_[request.target], cpus_, profile, request.header, *spec, request.operands,
                       session, in, out};
    auto code = own_1e_handler ? row_1e->handler(ctx) : spec->handler(ctx);
    if (code != EndCode::Ok) {
        auto field = code == request.operands.error ? request.operands.error_field : in.error_field();
        auto why = std::string(spec->name);
        if (!field.empty()) why += ": bad or missing field '" + std::string(field) + "'";
        auto outcome = reply.error(code, why);
        outcome.named = std::move(ctx.named);   // a refused label request still shows the names it sent
        return outcome;
    }
    if (ctx.restarted) return reply.drop(Outcome::Action::Restart, "");   // §5.6: no response on success
    if (!ctx.silent.empty()) {   // a node command meant for another device (docs/nodes.md)
        auto outcome = reply.drop(Outcome::Action::Silent, std::move(ctx.silent) + "; not answered");
        outcome.named = std::move(ctx.named);
        return outcome;
    }
    // 1E bit data come in whole bytes: an odd count gets a dummy 0 point
    // (binary packing already pads its last nibble).
    if (row_1e && row_1e->bit_data && request.header.codec == Codec::Ascii && !request.operands.devices.empty() &&
        request.operands.devices.front().points % 2 != 0)
        out.bytes().push_back('0');
    auto outcome = reply.ok(out.bytes());
    outcome.named = std::move(ctx.named);
    return outcome;
}

}  // namespace slmp::protocol
