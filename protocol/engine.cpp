#include "protocol/engine.hpp"

#include <algorithm>
#include <string>

#include "protocol/command_table.hpp"
#include "protocol/error_response.hpp"
#include "protocol/hex.hpp"
#include "protocol/message.hpp"

namespace slmp::protocol {
namespace {

using devicemodel::Refusal;

std::string hex(std::uint32_t value, unsigned digits) {
    std::vector<std::uint8_t> text;
    append_hex(text, value, digits);
    return std::string(text.begin(), text.end());
}
std::string hex4(std::uint16_t value) { return hex(value, 4); }

// The own station (§3.1.3–§3.1.5): anything else would need routing, which a
// CPU's built-in port cannot do. Module I/O 03FF is the connected CPU, 03E0–03E3
// CPU No.1–4 of a multi-CPU system. The codes are chosen; see docs/end-codes.md.
EndCode check_route(const Route& route, const CpuSet& cpus, devicemodel::Cpu*& target) {
    if (route.network != 0x00) return EndCode::RouteNetworkNotFound;
    if (route.station != 0xFF || route.multidrop != 0x00) return EndCode::RouteStationNotFound;
    if (route.module_io == 0x03FF) {
        target = cpus[0];
        return EndCode::Ok;
    }
    if (route.module_io < 0x03E0 || route.module_io > 0x03E3) return EndCode::RouteNotCpu;
    target = cpus[route.module_io - 0x03E0u];
    return target ? EndCode::Ok : EndCode::RouteNotCpu;
}

class Reply {
public:
    Reply(const FrameHeader& header, std::size_t consumed) : header_(header) { outcome_.consumed = consumed; }

    Outcome& outcome() { return outcome_; }

    Outcome ok(std::span<const std::uint8_t> data) {
        FieldWriter w(header_.codec);
        w.u16(raw(EndCode::Ok));
        w.raw(data);
        return send(w.bytes());
    }

    // End code, then the error information: the responding station's route and
    // the request's command and subcommand (spec §3.2.4; hardware-behaviour §1).
    Outcome error(EndCode code, std::string note) {
        outcome_.end_code = code;
        outcome_.note = hex4(raw(code)) + " (" + std::string(describe(code)) + "): " + note;
        outcome_.action = Outcome::Action::Respond;
        outcome_.response = encode_error_response(header_, outcome_.command, outcome_.subcommand, code);
        return std::move(outcome_);
    }

    Outcome refuse(const Refusal& refusal, std::string note) {
        switch (refusal.kind) {
            case Refusal::Kind::EndCode: return error(end_code(refusal.end_code), std::move(note));
            case Refusal::Kind::Close: return drop(Outcome::Action::Close, std::move(note) + "; closing the connection");
            case Refusal::Kind::Silence:
            case Refusal::Kind::Answer: return drop(Outcome::Action::Silent, std::move(note) + "; not answered");
        }
        return drop(Outcome::Action::Silent, std::move(note));
    }

    Outcome drop(Outcome::Action action, std::string note) {
        outcome_.action = action;
        outcome_.note = std::move(note);
        return std::move(outcome_);
    }

private:
    Outcome send(std::vector<std::uint8_t>& payload) {
        outcome_.action = Outcome::Action::Respond;
        outcome_.response = encode_frame(Direction::Response, header_.kind, header_.codec, header_.serial,
                                         header_.route, payload);
        return std::move(outcome_);
    }

    const FrameHeader& header_;
    Outcome outcome_;
};

}  // namespace

Outcome Engine::process(std::span<const std::uint8_t> input, DataCodePolicy policy, Session& session) {
    auto scan = scan_frame(input, Direction::Request, policy, options_.max_frame_bytes);
    switch (scan.status) {
        case FrameScan::Status::NeedMore: return Outcome{};
        case FrameScan::Status::Garbage: {
            Outcome out;
            out.action = Outcome::Action::Silent;
            out.consumed = scan.size;
            out.note = std::to_string(scan.size) +
                       " byte(s) that do not start an SLMP request frame for this port's data code "
                       "(expected a 3E/4E subheader 5000/5400, binary or ASCII); skipped";
            return out;
        }
        case FrameScan::Status::TooLarge: {
            Outcome out;
            out.action = Outcome::Action::Close;
            out.note = "request data length announces a " + std::to_string(scan.size) +
                       "-byte frame, over the " + std::to_string(options_.max_frame_bytes) +
                       "-byte maximum (max_request_bytes); closing the connection";
            return out;
        }
        case FrameScan::Status::Complete: break;
    }

    const auto& header = scan.header;
    const auto& profile = cpu_.profile();
    Reply reply(header, scan.size);
    auto& outcome = reply.outcome();

    if (header.kind == FrameKind::E4 && profile.frame_4e.kind != Refusal::Kind::Answer)
        return reply.refuse(profile.frame_4e, "4E frame on a port of " + profile.name + ", which serves 3E only");

    // After the header: monitoring timer, command, subcommand (2 bytes each).
    const std::size_t unit = header.codec == Codec::Binary ? 1 : 2;
    auto body = input.subspan(header.header_size, header.data_length);
    FieldReader in(header.codec, body, CodecOptions{profile.zr_ascii_hex});
    in.u16("monitoring timer");
    outcome.command = in.u16("command");
    outcome.subcommand = in.u16("subcommand");
    if (!in.ok()) {
        if (body.size() < 6 * unit)
            return reply.drop(Outcome::Action::Silent,
                              "request data length " + std::to_string(header.data_length) +
                                  " is too short to hold the monitoring timer, command and subcommand; not answered");
        return reply.error(in.error(), "bad " + std::string(in.error_field()));
    }

    auto name = hex4(outcome.command) + "/" + hex4(outcome.subcommand);
    devicemodel::Cpu* target = nullptr;
    if (auto code = check_route(header.route, cpus_, target); code != EndCode::Ok)
        return reply.error(code, "request for network " + hex(header.route.network, 2) + " station " +
                                     hex(header.route.station, 2) + " module I/O " + hex4(header.route.module_io) +
                                     " multidrop " + hex(header.route.multidrop, 2) +
                                     "; only the own station (00/FF/03FF/00) and its configured CPUs "
                                     "(module I/O 03E0-03E3) are served");

    // Remote password (slmp-labels-remote-misc.md §6): a locked connection gets
    // C201 for everything but Unlock 1630 and Lock 1631 (a no-op while locked).
    if (cpu_.runtime().password().configured() && !session.password_unlocked && outcome.command != 0x1630 &&
        outcome.command != 0x1631)
        return reply.error(EndCode::RemotePasswordLocked,
                           "this connection is locked by the remote password; send Unlock 1630 with the password first");

    const auto& unsupported = profile.unsupported_commands;
    if (std::find(unsupported.begin(), unsupported.end(), outcome.command) != unsupported.end())
        return reply.error(end_code(profile.not_supported_code),
                           "command " + hex4(outcome.command) + " is not supported by " + profile.name);
    if (is_iqr_device_subcommand(outcome.command, outcome.subcommand) &&
        profile.iqr_subcommands.kind != Refusal::Kind::Answer)
        return reply.refuse(profile.iqr_subcommands,
                            name + " uses the iQ-R device form, which " + profile.name + " does not accept");

    const auto* spec = find_command(outcome.command, outcome.subcommand);
    if (!spec) {
        auto why = is_known_command(outcome.command) ? "unknown subcommand " + hex4(outcome.subcommand) +
                                                           " for command " + hex4(outcome.command)
                                                     : "unknown or unimplemented command " + hex4(outcome.command);
        return reply.error(end_code(profile.not_supported_code), why);
    }

    if (spec->control_cpu_only && target != cpus_[0])
        return reply.error(end_code(profile.not_supported_code),
                           std::string(spec->name) + " cannot reach CPU No.2-4 of a multi-CPU system (Appendix 3)");

    FieldWriter out(header.codec, CodecOptions{target->profile().zr_ascii_hex});
    CommandContext ctx{*target, cpus_, header, *spec, session, in, out};
    auto code = spec->handler(ctx);
    if (code != EndCode::Ok) {
        auto why = std::string(spec->name);
        if (!in.ok()) why += ": bad or missing field '" + std::string(in.error_field()) + "'";
        return reply.error(code, why);
    }
    if (ctx.restarted) return reply.drop(Outcome::Action::Restart, "");   // §5.6: no response on success
    return reply.ok(out.bytes());
}

}  // namespace slmp::protocol
