// Remote Password — SLMP Reference Manual §5.7, real-CPU measurements.
//   1630 Unlock / 1631 Lock: length (word), then the password as raw characters
//   in both codes. The lock state is per connection (Session); the password and
//   the mismatch count are the connected CPU's (devicemodel::RemotePassword).
// Unlock while unlocked and Lock while locked are no-ops without a check (§6).
// Wrong password C810; during the lock-out after repeated mismatches C815
// (chosen within the C810-C815 family; docs/cpu-runtime.md). A length outside
// the family's rule cannot match the configured password, so it is a mismatch.
#include "protocol/commands/handlers.hpp"

namespace slmp::protocol::commands {
namespace {

using devicemodel::RemotePassword;

EndCode verdict(RemotePassword::Check check) {
    switch (check) {
        case RemotePassword::Check::Match: return EndCode::Ok;
        case RemotePassword::Check::Mismatch: return EndCode::RemotePasswordMismatch;
        case RemotePassword::Check::LockedOut: return EndCode::RemotePasswordLockedOut;
    }
    return EndCode::RemotePasswordMismatch;
}

// Reads the length and the password; the lock belongs to the station the
// client is connected to (§6: "connected station only"), CPU No.1 of the set.
struct PasswordRequest {
    std::span<const std::uint8_t> text;
    devicemodel::Cpu* station = nullptr;
};

EndCode read_request(CommandContext& ctx, PasswordRequest& request) {
    auto length = ctx.in.u16("password length");
    request.text = ctx.in.raw(length, "password");
    if (!ctx.in.finish()) return ctx.in.error();
    request.station = ctx.cpus[0] ? ctx.cpus[0] : &ctx.cpu;
    if (request.station->profile().password_max_length == 0) return end_code(ctx.station_port.not_supported_code);
    return EndCode::Ok;
}

}  // namespace

EndCode password_unlock(CommandContext& ctx) {
    PasswordRequest request;
    if (auto code = read_request(ctx, request); code != EndCode::Ok) return code;
    auto& runtime = request.station->runtime();
    if (ctx.session.password_unlocked || !password_guards(*request.station, ctx.session)) return EndCode::Ok;
    auto code = verdict(runtime.password().check(request.text, request_time(ctx.session, *request.station)));
    if (code == EndCode::Ok) ctx.session.password_unlocked = true;
    return code;
}

EndCode password_lock(CommandContext& ctx) {
    PasswordRequest request;
    if (auto code = read_request(ctx, request); code != EndCode::Ok) return code;
    auto& runtime = request.station->runtime();
    // Without a password guarding this port nothing can match (chosen: C810, not a silent 0000).
    if (!password_guards(*request.station, ctx.session)) return EndCode::RemotePasswordMismatch;
    if (!ctx.session.password_unlocked) return EndCode::Ok;
    auto code = verdict(runtime.password().check(request.text, request_time(ctx.session, *request.station)));
    if (code == EndCode::Ok) ctx.session.password_unlocked = false;
    return code;
}

}  // namespace slmp::protocol::commands
