// Remote Control — SLMP Reference Manual §5.6, real-CPU measurements.
//   1001 Remote RUN    mode (word: 0001 normal, 0003 forced), clear mode (byte: 00/01/02), fixed byte 00
//   1002 Remote STOP   fixed word 0001
//   1003 Remote PAUSE  mode (word: 0001 / 0003)
//   1005 Remote Latch Clear  fixed word 0001
//   1006 Remote RESET  fixed word 0001; on success no response at all
//   1E 13 Remote RUN / 14 Remote STOP: no data (docs/frames.md); RUN is a
//   normal (not forced) RUN that clears nothing
// Check order: field layout and length (C061) first, then field values (C05C),
// then the operating-state rules of devicemodel::OperatingState. The state
// rules' end codes where the manuals are silent are chosen (docs/cpu-runtime.md):
// held by another client 4015, not in STOP 4013 (real, for latch clear),
// reset disabled 4014, a stop error pending C05F.
#include "devicemodel/drives.hpp"
#include "protocol/commands/handlers.hpp"

namespace slmp::protocol::commands {
namespace {

using devicemodel::ClearMode;
using devicemodel::RemoteRefusal;

EndCode end_code_for(RemoteRefusal refusal) {
    switch (refusal) {
        case RemoteRefusal::None: return EndCode::Ok;
        case RemoteRefusal::HeldByOther: return EndCode::RemoteHeldByOther;
        case RemoteRefusal::NotInStop: return EndCode::LatchClearNotInStop;
        case RemoteRefusal::ResetDisabled: return EndCode::RemoteResetDisabled;
        case RemoteRefusal::StopError: return EndCode::NotExecutableOnCpu;
    }
    return EndCode::NotExecutableOnCpu;
}

constexpr std::uint16_t kNormal = 0x0001;
constexpr std::uint16_t kForced = 0x0003;

// The trailing "fixed value 0001" of 1002/1005/1006 ([ext] iQ-R MC manual).
bool fixed_word_only(FieldReader& in) {
    auto fixed = in.u16("fixed value 0001");
    return in.finish() && fixed == 0x0001;
}

}  // namespace

EndCode remote_run(CommandContext& ctx) {
    auto mode = ctx.in.u16("mode");
    auto clear = ctx.in.u8("clear mode");
    auto fixed = ctx.in.u8("fixed value 00");
    if (!ctx.in.finish()) return ctx.in.error();
    if ((mode != kNormal && mode != kForced) || clear > 2 || fixed != 0) return EndCode::BadRequestContent;
    auto& cpu = ctx.cpu;
    return end_code_for(
        cpu.runtime().remote_run(cpu.memory(), ctx.session.id, mode == kForced, static_cast<ClearMode>(clear)));
}

EndCode remote_stop(CommandContext& ctx) {
    if (!fixed_word_only(ctx.in)) return ctx.in.ok() ? EndCode::BadRequestContent : ctx.in.error();
    return end_code_for(ctx.cpu.runtime().remote_stop(ctx.cpu.memory(), ctx.session.id));
}

EndCode remote_pause(CommandContext& ctx) {
    auto mode = ctx.in.u16("mode");
    if (!ctx.in.finish()) return ctx.in.error();
    if (mode != kNormal && mode != kForced) return EndCode::BadRequestContent;
    return end_code_for(ctx.cpu.runtime().remote_pause(ctx.cpu.memory(), ctx.session.id, mode == kForced));
}

EndCode remote_latch_clear(CommandContext& ctx) {
    if (!fixed_word_only(ctx.in)) return ctx.in.ok() ? EndCode::BadRequestContent : ctx.in.error();
    return end_code_for(ctx.cpu.runtime().latch_clear(ctx.cpu.memory(), ctx.session.id));
}

EndCode remote_reset(CommandContext& ctx) {
    if (!fixed_word_only(ctx.in)) return ctx.in.ok() ? EndCode::BadRequestContent : ctx.in.error();
    auto code = end_code_for(ctx.cpu.runtime().reset(ctx.cpu.memory()));
    ctx.restarted = code == EndCode::Ok;
    if (ctx.restarted) ctx.cpu.drives().clear_locks();   // SLMP Reference Manual §5.8: a CPU reset releases every lock
    return code;
}

// Clear Error 1617 — §8: initialises the error code of the device the client
// is connected to. A CPU's built-in port refuses it (kConnectedDevice). On the
// iQ-F port the device is the CPU: SD0 and SM0/SM1 are cleared, and a stop
// error, which needs a Remote RESET, answers C05F (chosen). Through a module
// port it is the module's error and COM.ERR LED, which slmp-sim does not
// model: the CPU's error stays (docs/cpu-runtime.md).
EndCode clear_error(CommandContext& ctx) {
    if (!ctx.in.finish()) return ctx.in.error();
    if (ctx.station_port.relays) return EndCode::Ok;
    return end_code_for(ctx.cpu.runtime().clear_error(ctx.cpu.memory()));
}

EndCode remote_run_1e(CommandContext& ctx) {
    if (!ctx.in.finish()) return ctx.in.error();
    auto& cpu = ctx.cpu;
    return end_code_for(cpu.runtime().remote_run(cpu.memory(), ctx.session.id, false, ClearMode::None));
}

EndCode remote_stop_1e(CommandContext& ctx) {
    if (!ctx.in.finish()) return ctx.in.error();
    return end_code_for(ctx.cpu.runtime().remote_stop(ctx.cpu.memory(), ctx.session.id));
}

}  // namespace slmp::protocol::commands
