// Read Type Name 0101 — SLMP Reference Manual §5.6, real-CPU measurements.
// The model name is 16 characters padded with spaces, sent as raw characters in
// both codecs; the model code is a word.
// 1E PC type read 15 answers one byte, the profile's frame_1e.pc_type (docs/frames.md).
#include <string>

#include "protocol/commands/handlers.hpp"

namespace slmp::protocol::commands {

EndCode read_type_name(CommandContext& ctx) {
    if (!ctx.in.finish()) return ctx.in.error();
    const auto& profile = ctx.cpu.profile();
    std::string name = profile.type_name;
    name.resize(16, ' ');
    ctx.out.raw(std::span(reinterpret_cast<const std::uint8_t*>(name.data()), name.size()));
    ctx.out.u16(profile.model_code);
    return EndCode::Ok;
}

EndCode read_pc_type_1e(CommandContext& ctx) {
    if (!ctx.in.finish()) return ctx.in.error();
    ctx.out.u8(ctx.port.pc_type_1e);
    return EndCode::Ok;
}

}  // namespace slmp::protocol::commands
