// Device Read 0401 / Device Write 1401 — subcommands 0000 0001 (Q form) and
// 0002 0003 (iQ-R form). Spec: slmp-frames-and-devices.md §6.1–§6.2;
// limits and end codes: hardware-behaviour.md §2, §3, §6, §7.
//
// Check order (one place, both commands):
//   1. fields (start device, points) decode — C050/C061 from the reader;
//   2. the device is known (profile.unknown_device_code, C05B);
//   3. the device may be used by this command: direct LTS/LTC/LSTS/LSTC, and for
//      writes LTN/LSTN and read-only areas (S) → 4030;
//   4. bit units need a bit device → C05C;
//   5. the point count is 1..limit → the profile's limit code (C051/C052);
//      long devices come in whole units (LTN/LSTN ×4 words, LCN/LZ ×2) → C051;
//   6. the span fits the configured size → 4031 (iQ-R) / C056 (Q/L);
//   7. write data decodes and nothing is left over (C061);
// and only then is memory read or written.
#include <vector>

#include "protocol/commands/handlers.hpp"

namespace slmp::protocol::commands {
namespace {

using devicemodel::Area;
using devicemodel::DeviceSpec;
using devicemodel::Part;
using devicemodel::Unit;

bool is_long_timer(const DeviceSpec& spec) { return spec.area == Area::LT || spec.area == Area::LST; }

// LTS/LTC/LSTS/LSTC are read with their LTN/LSTN (4 words); writes to long
// timers and to read-only areas are refused.
bool accessible(const devicemodel::CpuProfile& profile, const DeviceSpec& spec, bool write) {
    if (is_long_timer(spec) && (spec.part != Part::Value || write)) return false;
    if (!write) return true;
    for (auto area : profile.read_only)
        if (area == spec.area) return false;
    return true;
}

// Steps 2–6 of the check order above.
EndCode check(CommandContext& ctx, const DeviceField& device, std::uint16_t points, bool write) {
    const auto& profile = ctx.cpu.profile();
    if (!device.spec) return end_code(profile.unknown_device_code);
    const auto& spec = *device.spec;
    if (!accessible(profile, spec, write)) return end_code(profile.not_accessible_code);
    const bool bit_units = ctx.spec.access == Access::Bits;
    if (bit_units && spec.unit != Unit::Bit) return end_code(profile.bad_unit_code);

    const auto& limit = !bit_units ? profile.batch_words
                        : ctx.in.codec() == Codec::Binary ? profile.batch_bits_binary
                                                          : profile.batch_bits_ascii;
    if (points == 0 || points > limit.max) return end_code(limit.end_code);
    const auto per_device = devicemodel::words_per_device(spec);
    if (points % per_device != 0) return end_code(profile.batch_words.end_code);

    std::uint64_t devices = bit_units ? points
                            : spec.unit == Unit::Bit ? std::uint64_t{points} * 16
                                                     : points / per_device;
    if (!ctx.cpu.in_range(spec.area, device.number, devices)) return end_code(profile.out_of_range_code);
    return EndCode::Ok;
}

}  // namespace

EndCode batch_read(CommandContext& ctx) {
    auto device = ctx.in.device(ctx.spec.form, "start device");
    auto points = ctx.in.u16("device points");
    if (!ctx.in.ok()) return ctx.in.error();
    if (auto code = check(ctx, device, points, false); code != EndCode::Ok) return code;
    if (!ctx.in.finish()) return ctx.in.error();

    const auto& memory = ctx.cpu.memory();
    if (ctx.spec.access == Access::Bits) {
        std::vector<std::uint8_t> bits(points);
        for (std::uint32_t i = 0; i < points; ++i) bits[i] = memory.bit(*device.spec, device.number + i);
        ctx.out.bits(bits);
    } else {
        std::vector<std::uint16_t> words(points);
        memory.read_words(*device.spec, device.number, words);
        ctx.out.words(words);
    }
    return EndCode::Ok;
}

EndCode batch_write(CommandContext& ctx) {
    auto device = ctx.in.device(ctx.spec.form, "start device");
    auto points = ctx.in.u16("device points");
    if (!ctx.in.ok()) return ctx.in.error();
    if (auto code = check(ctx, device, points, true); code != EndCode::Ok) return code;

    auto& memory = ctx.cpu.memory();
    if (ctx.spec.access == Access::Bits) {
        auto bits = ctx.in.bits(points, "write data");
        if (!ctx.in.finish()) return ctx.in.error();
        for (std::uint32_t i = 0; i < points; ++i) memory.set_bit(*device.spec, device.number + i, bits[i] != 0);
    } else {
        auto words = ctx.in.words(points, "write data");
        if (!ctx.in.finish()) return ctx.in.error();
        memory.write_words(*device.spec, device.number, words);
    }
    return EndCode::Ok;
}

}  // namespace slmp::protocol::commands
