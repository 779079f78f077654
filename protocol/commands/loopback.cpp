// Self Test 0619 — SLMP Reference Manual §5.9. The loopback data count is a
// word; the data are raw characters (the same bytes in binary and ASCII), 1 to
// the profile's maximum (960). Data outside 0-9/A-F is echoed as it came (the
// manual does not say it is refused). A count of 0 or over the maximum answers
// C05C (chosen; the manuals name no code) — see docs/end-codes.md.
// 1E loopback 16: a one-byte count (1-254, inferred: docs/frames.md), the data
// as characters; the answer echoes count and data.
#include "protocol/commands/handlers.hpp"

namespace slmp::protocol::commands {

EndCode self_test(CommandContext& ctx) {
    auto count = ctx.in.u16("loopback data count");
    if (!ctx.in.ok()) return ctx.in.error();
    if (count == 0 || count > ctx.port.loopback_max_bytes) return EndCode::BadRequestContent;
    auto data = ctx.in.raw(count, "loopback data");
    if (!ctx.in.finish()) return ctx.in.error();
    ctx.out.u16(count);
    ctx.out.raw(data);
    return EndCode::Ok;
}

EndCode self_test_1e(CommandContext& ctx) {
    auto count = ctx.in.u8("loopback data count");
    if (!ctx.in.ok()) return ctx.in.error();
    if (count == 0 || count > 254) return EndCode::BadRequestContent;
    auto data = ctx.in.raw(count, "loopback data");
    if (!ctx.in.finish()) return ctx.in.error();
    ctx.out.u8(count);
    ctx.out.raw(data);
    return EndCode::Ok;
}

}  // namespace slmp::protocol::commands
