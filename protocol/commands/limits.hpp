// Point and block limits shared by the random, monitor and block commands
// (slmp-frames-and-devices.md §6.3–§6.8; hardware-behaviour.md §3).
#pragma once

#include <cstdint>

#include "protocol/command_table.hpp"

namespace slmp::protocol::commands {

// The limit for the request's subcommand family.
inline std::uint64_t form_max(const CommandContext& ctx, const devicemodel::FormLimit& limit) {
    return ctx.spec.form == DeviceForm::Q ? limit.q : limit.iqr;
}

// With the Q form's extended subcommands (0080/0081) every point or block
// counts twice (the manual's *1 notes).
inline std::uint64_t weight(const CommandContext& ctx) {
    return ctx.spec.extended && ctx.spec.form == DeviceForm::Q ? 2 : 1;
}

// Whether a weighted count is outside 1..limit.
inline bool over(const CommandContext& ctx, const devicemodel::FormLimit& limit, std::uint64_t count) {
    return count == 0 || count * weight(ctx) > form_max(ctx, limit);
}

// The end code for an exceeded limit (QJ71E71-100 answers extended requests with 4080).
inline EndCode over_limit_code(const CommandContext& ctx, const devicemodel::FormLimit& limit) {
    const auto& profile = ctx.cpu.profile();
    if (ctx.spec.extended && profile.extended_over_limit_code != 0) return end_code(profile.extended_over_limit_code);
    return end_code(limit.end_code);
}

}  // namespace slmp::protocol::commands
