// Device Read 0401 / Device Write 1401 — subcommands 0000 0001 (Q form),
// 0002 0003 (iQ-R form) and 0080–0083 (the same with the extended device
// specification, Appendix 1). Spec: SLMP Reference Manual §5.2, Appendix 1;
// limits and end codes: real-CPU measurements.
//
// Check order (one place, both commands):
//   1. fields (start device, points) decode — C050/C061 from the reader;
//   2. the device resolves (device_access.cpp): known code (C05B), extension
//      target present (4043), not a device this command may not name (4030);
//   3. bit units need a bit device → C05C;
//   4. the point count is 1..limit → the profile's limit code (C051/C052);
//      long devices come in whole units (LTN/LSTN ×4 words, LCN/LZ ×2) → C051;
//   5. the span fits the configured size → 4031 (iQ-R) / C056 (Q/L);
//   6. write data decodes and nothing is left over (C061);
// and only then is memory read or written.
#include <algorithm>
#include <array>
#include <vector>

#include "protocol/commands/handlers.hpp"
#include "protocol/commands/limits.hpp"
#include "protocol/device_access.hpp"

namespace slmp::protocol::commands {
namespace {

using devicemodel::Unit;

// Steps 2–5 of the check order above.
EndCode check(CommandContext& ctx, const DeviceOperand& device, bool write, Target& target) {
    const auto& profile = ctx.port;
    if (auto code = resolve(ctx, device.field, write ? Use::BatchWrite : Use::BatchRead, target); code != EndCode::Ok)
        return code;
    const auto& spec = *target.spec;
    const bool bit_units = ctx.spec.access == Access::Bits;
    if (bit_units && spec.unit != Unit::Bit) return end_code(profile.bad_unit_code);

    const auto& limit = !bit_units ? profile.batch_words
                        : ctx.header.codec == Codec::Binary ? profile.batch_bits_binary
                                                            : profile.batch_bits_ascii;
    const auto points = device.points;
    if (points == 0 || points > limit.max) return end_code(limit.end_code);
    if (!bit_units && points % devicemodel::words_per_device(spec) != 0) return end_code(profile.batch_words.end_code);

    auto devices = bit_units ? std::uint64_t{points} : devices_in_words(spec, points);
    if (!fits(target, devices)) return end_code(profile.out_of_range_code);
    return EndCode::Ok;
}

// Steps 1–5 for both commands: the target of the one operand, or the end code.
EndCode checked_target(CommandContext& ctx, bool write, Target& target) {
    const auto& ops = ctx.operands;
    if (ops.failed_before_checks()) return ops.error;
    if (auto code = check(ctx, ops.devices.front(), write, target); code != EndCode::Ok) return code;
    return ops.error;   // step 6: the write data and what is left over
}

}  // namespace

// Step 1, and the data of step 6 (after the checks).
void decode_batch(DecodeContext& d) {
    DeviceOperand device;
    device.field = read_device(d, "start device");
    device.points = d.in.u16("device points");
    if (!d.in.ok()) return fail_field(d);
    const bool bit_units = d.spec.access == Access::Bits;
    device.unit = bit_units ? DeviceOperand::Unit::Bit : DeviceOperand::Unit::Word;
    if (d.spec.writes()) {
        if (bit_units) device.bits = d.in.bits(device.points, "write data");
        else device.words = d.in.words(device.points, "write data");
    }
    d.out.devices.push_back(std::move(device));
    if (!d.in.finish()) fail_field(d, true);
}

EndCode batch_read(CommandContext& ctx) {
    Target target;
    if (auto code = checked_target(ctx, false, target); code != EndCode::Ok) return code;
    const auto points = ctx.operands.devices.front().points;
    const auto& memory = *target.memory;
    if (ctx.spec.access == Access::Bits) {
        std::vector<std::uint8_t> bits(points);
        for (std::uint32_t i = 0; i < points; ++i) bits[i] = memory.bit(*target.spec, target.number + i);
        ctx.out.bits(bits);
    } else {
        // A read of up to 960 words (every frame's limit) needs no heap.
        std::array<std::uint16_t, 960> on_stack;
        std::vector<std::uint16_t> on_heap;
        std::span<std::uint16_t> words = std::span(on_stack).first(std::min<std::size_t>(points, on_stack.size()));
        if (points > on_stack.size()) words = on_heap = std::vector<std::uint16_t>(points);
        memory.read_words(*target.spec, target.number, words);
        ctx.out.words(words);
    }
    return EndCode::Ok;
}

EndCode batch_write(CommandContext& ctx) {
    Target target;
    if (auto code = checked_target(ctx, true, target); code != EndCode::Ok) return code;
    const auto& device = ctx.operands.devices.front();
    auto& memory = *target.memory;
    if (ctx.spec.access == Access::Bits) {
        for (std::uint32_t i = 0; i < device.points; ++i)
            memory.set_bit(*target.spec, target.number + i, device.bits[i] != 0);
    } else {
        memory.write_words(*target.spec, target.number, device.words);
    }
    return EndCode::Ok;
}

}  // namespace slmp::protocol::commands
